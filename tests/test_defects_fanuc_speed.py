"""Defects: the Fanuc writer wrote a decimal S (``G96 S656.167979`` after ``--units inch`` on a lathe program
with G96 S200: 200 m/min is 656.168 ft/min). On a Fanuc an S with a decimal point is an illegal statement:
S takes an integer, and a computed S is rounded half away from zero [K: ``Fanuc.WHOLE_SPINDLE_SPEED``]. So
the writer rounds as the controller rounds a computed S, with one located warning; a target whose S takes
decimals (LinuxCNC) keeps them. Expected words by hand: 200 / 0.3048 = 656.17 -> S656; 1234.5 -> S1235."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines

LATHE = load_setup(Path(__file__).resolve().parent.parent / "examples" / "setups" / "fanuc_0i_tf.xml")
CSS = "%\nO1\nG21 G99\nG50 S2000\nG96 S200 M03\nG00 X50. Z2.\nG01 Z-10. F0.2\nG97 S1000\nM30\n%\n"


def written(text: str, source: str, target: str, **kw: object) -> tuple[str, str]:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=warnings), **kw)  # type: ignore[arg-type]
    return out.getvalue(), warnings.getvalue()


def test_a_surface_speed_converted_to_inch_is_a_whole_s_on_fanuc() -> None:
    out, warnings = written(CSS, "fanuc", "fanuc", setup=LATHE, units="inch")
    assert "G96 S656 M03" in out.splitlines() and "G97 S1000" in out.splitlines()
    assert warnings.strip() == (
        "in.nc:5:1: warning: the fanuc dialect takes a whole number in S: 656.168 is written S656 (as the "
        "controller rounds a computed S); this and later S words may differ from the source by up to 0.5")
    assert "S656.167979" in written(CSS, "fanuc", "linuxcnc", setup=LATHE, units="inch")[0]


@pytest.mark.parametrize("speed, word", [("1234.5", "S1235"), ("1234.4", "S1234"), ("1234.6", "S1235"),
                                         ("1200", "S1200")])
def test_a_decimal_speed_from_linuxcnc_is_rounded_half_away(speed: str, word: str) -> None:
    text = f"G21 G90 G17\nS{speed} M3\nG0 X1 Y2 Z3\nG1 X5 F100\nM30\n"
    out, warnings = written(text, "linuxcnc", "fanuc")
    assert f"{word} M03" in out.splitlines()
    assert bool(warnings) == ("." in speed)
    # the motion is the source's
    report = verify_lines(io.StringIO(text).readlines(), io.StringIO(out).readlines(), file_in="in.ngc",
                          file_out="out.nc", source="linuxcnc",
                          target="fanuc", tolerance=0.0)
    assert report.ok


# -- the reader: a written S takes no decimal point on a Fanuc -------------------------------------------------

def read_errors(text: str, **kw: object) -> list[str]:
    with pytest.raises(ErrorList) as info:
        written(text, "fanuc", "linuxcnc", **kw)
    return [str(e) for e in info.value.errors]


@pytest.mark.parametrize("word", ["S1000.5", "S1000.", "S1000.0"])
def test_a_fanuc_mill_refuses_a_decimal_point_in_s(word: str) -> None:
    assert read_errors(f"G21 G90\nM03 {word}\nG00 X1. Y2.\nM30\n") == [
        f"in.nc:2:5: error: address S takes no decimal point ({word})"]


def test_a_fanuc_lathe_refuses_it_too_in_a_plain_block_and_in_a_cycle_block() -> None:
    assert read_errors("%\nO1\nG21 G99\nG97 S1000.5 M03\nM30\n%\n", setup=LATHE) == [
        "in.nc:4:5: error: address S takes no decimal point (S1000.5)"]
    profile = "%\nO1\nG21 G99\nG00 X50. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.2 W0.1 F0.2 S800.5\nN10 G00 X20.\nN20 G01 Z-20.\nM30\n%\n"
    assert read_errors(profile, setup=LATHE)[0] == "in.nc:6:28: error: address S takes no decimal point (S800.5)"


@pytest.mark.parametrize("value, word", [("1000.5", "S1001"), ("1000.4", "S1000"), ("999.5", "S1000")])
def test_a_computed_s_runs_rounded_half_away_from_zero(value: str, word: str) -> None:
    out, _ = written(f"G21 G90\n#1={value}\nM03 S#1\nG00 X1. Y2.\nM30\n", "fanuc", "grbl")
    assert f"{word} M3" in out.splitlines()


def test_linuxcnc_reads_a_decimal_s() -> None:
    out, warnings = written("G21 G90\nS1000.5 M3\nG0 X1 Y2\nM30\n", "linuxcnc", "linuxcnc")
    assert "S1000.5 M3" in out and not warnings
