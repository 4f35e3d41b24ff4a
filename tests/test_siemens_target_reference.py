"""Fanuc reference returns (``G28``) towards SINUMERIK: the intermediate point, then ``G75 FP=1`` with fixed
point 1 the set-up's ``<Axis home>`` (``dialects.siemens.fixed_point``), read back to the same toolpath."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

EXAMPLES = Path(__file__).resolve().parent.parent / "examples" / "fanuc"
TOOLS = "".join(f'<Tool number="{n}" length="{90.0 + 7.5 * n}" radius="{n / 2}"/>' for n in range(1, 8))
HOMES = '<Axis name="X" home="-400.0"/><Axis name="Y" home="-200.0"/><Axis name="Z" home="-10.0"/>'


def _setup(tmp_path: Path, axes: str = HOMES) -> MachineSetup:
    path = tmp_path / "machine.xml"
    path.write_text(f'<MachineSetup name="t"><Axes>{axes}</Axes><Tools>{TOOLS}</Tools></MachineSetup>')
    return load_setup(path)


def _translate(text: str, setup: MachineSetup) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target="siemens", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _moves(text: str, setup: MachineSetup) -> list[tuple[float, float, float]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="out", dialect="siemens", setup=setup)
    return [(e["x"], e["y"], e["z"]) for e in events if "move" in e]


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.nc")), ids=lambda p: p.stem)
def test_each_bundled_fanuc_example_translates_to_siemens_and_verifies(path: Path, tmp_path: Path) -> None:
    setup = _setup(tmp_path)
    text = path.read_text()
    out = _translate(text, setup)
    assert out.count("G75 FP=1 Z1=0") == text.count("G28 Z0.")
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in=path.name,
                          file_out="out.mpf", source="fanuc", target="siemens", setup=setup)
    assert report.ok and report.max_deviation == 0, report.summary()


def test_the_drilling_example_keeps_its_cycle_native(tmp_path: Path) -> None:
    out = _translate((EXAMPLES / "o1001_plate_drill_tap.nc").read_text(), _setup(tmp_path))
    assert "MCALL CYCLE81(" in out


def test_g75_ends_with_the_spindle_at_the_home_whatever_the_tool(tmp_path: Path) -> None:
    """Hand-derived: tool 1 is 97.5 long and Z's home is -10, so the tip stops at -107.5 (machine zero is the
    work zero: no work offset is set); ``G90 G28 Z20.`` passes through Z20 first, ``G91 G28 Z0.`` does not."""
    setup = _setup(tmp_path)
    text = "O1\nG21 G17 G90 G0 X5. Y6.\nT1 M6\nG43 H1 Z50.\nG90 G28 Z20.\nG0 Z30.\nG91 G28 Z0. M5\nG90\nM30\n"
    out = _translate(text, setup)
    assert "G0 Z20.\nG75 FP=1 Z1=0\n" in out
    assert "G91\nG75 FP=1 Z1=0\nM5\n" in out
    assert _moves(out, setup)[-4:] == [(5, 6, 20), (5, 6, -107.5), (5, 6, 30), (5, 6, -107.5)]


def test_a_set_up_without_the_home_is_a_located_error_naming_the_element(tmp_path: Path) -> None:
    setup = _setup(tmp_path, '<Axis name="X" home="0.0"/>')
    with pytest.raises(PostprocError) as caught:
        _translate("O1\nG21 G90 G0 X0 Y0 Z5.\nG91 G28 Z0.\nM30\n", setup)
    text = str(caught.value) + "".join(str(e) for e in getattr(caught.value, "errors", []))
    assert "in.nc:3:1" in text and '<Axis name="Z" home' in text


def test_a_second_reference_return_is_refused(tmp_path: Path) -> None:
    with pytest.raises(PostprocError) as caught:
        _translate("O1\nG21 G90 G0 X0 Y0 Z5.\nG91 G30 Z0.\nM30\n", _setup(tmp_path))
    text = str(caught.value) + "".join(str(e) for e in getattr(caught.value, "errors", []))
    assert "in.nc:3:1" in text and "G30" in text


@pytest.mark.parametrize(("block", "needle"), [("G75 FP=2 Z1=0", "FP=2"), ("G75 FP=1 Y1=0", '<Axis name="Y"')])
def test_reading_a_fixed_point_the_set_up_does_not_give_is_a_located_error(block: str, needle: str,
                                                                           tmp_path: Path) -> None:
    setup = _setup(tmp_path, '<Axis name="Z" home="0.0"/>')
    with pytest.raises((PostprocError, ErrorList)) as caught:
        _moves(f"%_N_T_MPF\nG0 X0 Y0 Z5\n{block}\nM30\n", setup)
    text = str(caught.value) + "".join(str(e) for e in getattr(caught.value, "errors", []))
    assert "out:3:" in text and needle in text


@pytest.mark.parametrize("block", ["G75 FP=1 Z1=0", "G75 Z1=5", "N40 g75 fp=1 z1=0"])
def test_g75_reads_as_a_rapid_to_the_home_with_no_tool(block: str, tmp_path: Path) -> None:
    """No FP is fixed point 1, the value written is ignored [K]; with no D in force the tip is at Z's home."""
    setup = _setup(tmp_path)
    assert _moves(f"%_N_T_MPF\nG0 X5 Y6 Z3\n{block}\nG1 X7 F100\nM30\n", setup) == [
        (5, 6, 3), (5, 6, -10), (7, 6, -10)]
