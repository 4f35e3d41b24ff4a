"""SINUMERIK's power-on path control mode (issue 26, defects): G60, exact stop, is the standard reset value of
G group 10 (machine data MD20150 ``$MC_GCODE_RESET_VALUES[9]``) [K: the SINUMERIK G-group tables; the page for
group 10 was not reached here]. The reader and the simulation started in Fanuc's G64 (blending), so a SINUMERIK
program that never programs G60/G64 was written for Fanuc or LinuxCNC without an exact stop mode: there it blends
where the SINUMERIK stops exactly, and ``verify`` said nothing (both sides "never set").

Now (``Dialect.PATH_CONTROL_AT_START``): the simulation of a SINUMERIK program records the exact stop at its
first move where the program set no mode before; a translation for a target that powers on blending writes the
mode in the first moving block (``postproc.lowering.path_at_start``); the other way (Fanuc -> SINUMERIK) the
output stops exactly where the source blended until the program sets a mode, which reaches every programmed point,
and ``verify`` accepts it with a note. Expected lines are hand-derived from these rules.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.verify import verify_lines

SIEMENS = "G710 G90 G17\nG0 X0 Y0 Z5\nG1 X10 F100\nY10\nM30\n"


def _translate(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _report(text: str, out: str, source: str, target: str):  # type: ignore[no-untyped-def]
    return verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source=source,
                        target=target, tolerance=0.0)


@pytest.mark.parametrize(("target", "first_move"), [
    ("fanuc", "G61 G00 X0. Y0. Z5."), ("linuxcnc", "G61 G0 X0. Y0. Z5."), ("isg", "G360 G00 X0. Y0. Z5."),
    ("fagor", "G07 G00 X0. Y0. Z5."),
])
def test_a_siemens_program_without_a_mode_keeps_its_exact_stop(target: str, first_move: str) -> None:
    out = _translate(SIEMENS, "siemens", target)
    assert out.splitlines()[1] == first_move
    report = _report(SIEMENS, out, "siemens", target)
    assert report.ok, report.summary()
    assert any("path control" in note and "exact stop (line 2)" in note for note in report.ignored), report.ignored


def test_the_output_that_lost_the_exact_stop_fails_verify() -> None:
    """What the translation wrote before: no mode, the Fanuc machine blends."""
    out = _translate(SIEMENS, "siemens", "fanuc").replace("G61 ", "")
    report = _report(SIEMENS, out, "siemens", "fanuc")
    assert not report.ok and "path control differs" in report.summary(), report.summary()


@pytest.mark.parametrize("mode", ["G64", "G60"])
def test_a_mode_the_program_sets_before_it_moves_is_the_one_written(mode: str) -> None:
    text = SIEMENS.replace("G17\n", f"G17\n{mode}\n")
    out = _translate(text, "siemens", "fanuc").splitlines()
    assert out[1] == {"G64": "G64", "G60": "G61"}[mode] and out[2] == "G00 X0. Y0. Z5.", out
    assert _report(text, "\n".join(out) + "\n", "siemens", "fanuc").ok


def test_a_blending_mode_set_later_follows_the_exact_stop() -> None:
    text = "G710 G90 G17\nG0 X0 Y0 Z5\nG1 X10 F100\nG64\nY10\nM30\n"
    out = _translate(text, "siemens", "linuxcnc")
    assert [line for line in out.splitlines() if line.startswith(("G61", "G64"))] == ["G61 G0 X0. Y0. Z5.", "G64"]
    assert _report(text, out, "siemens", "linuxcnc").ok


@pytest.mark.parametrize("text", [
    "G21 G90 G17\nG0 X0. Y0. Z5.\nG1 X10. F100.\nY10.\nM30\n",
    "G21 G90 G17\nG0 X0. Y0. Z5.\nG1 X10. F100.\nG64\nY10.\nG61\nX0.\nM30\n",
    "G21 G90 G17\nG09 G0 X0. Y0. Z5.\nG1 X10. F100.\nY10.\nM30\n",
    "G21 G90 G17\nG0 X0. Y0. Z5.\nG09 G1 X10. F100.\nY10.\nG61\nX0.\nM30\n",
])
def test_a_fanuc_program_for_siemens_stops_exactly_until_it_blends_and_verifies(text: str) -> None:
    out = _translate(text, "fanuc", "siemens")
    assert "G64" not in out.splitlines()[0]  # nothing written for the start: the SINUMERIK's exact stop is stricter
    report = _report(text, out, "fanuc", "siemens")
    assert report.ok, report.summary()


def test_a_siemens_output_that_blends_where_the_source_stops_exactly_still_fails() -> None:
    """The acceptance is one way: an output blending where the source asked for an exact stop differs."""
    text = "G21 G90 G17\nG61\nG0 X0. Y0. Z5.\nG1 X10. F100.\nY10.\nM30\n"
    out = _translate(text, "fanuc", "siemens").replace("G60\n", "G64\n")
    report = _report(text, out, "fanuc", "siemens")
    assert not report.ok, report.summary()


def test_a_copy_within_siemens_is_unchanged() -> None:
    assert _translate(SIEMENS, "siemens", "siemens") == SIEMENS
