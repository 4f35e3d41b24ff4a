"""A lathe's turret index (``T0202``) towards a mill control: a tool change there (``T2 M6``) stops the
spindle [V: rs274 prints STOP_SPINDLE_TURNING before CHANGE_TOOL], the turret does not [K: Fanuc T, the T
code only indexes]. With the spindle stopped the two agree and the index is written as the tool change;
with it turning the block is refused where it stands.

Expected moves are hand-derived (X a diameter on the lathe, a radius in rs274's canonical calls: LinuxCNC's
lathe mode G7 reads the diameter and prints the radius); rs274 runs the LinuxCNC output.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274

LATHE = MachineSetup(input=InputSettings(machine_type="lathe"))
STOPPED = ("O0001\nG21 G18 G99\nG0 X50. Z5.\nT0202\nM03 S1000\nG1 X40. F0.2\nZ-10.\nM05\nT0303\nM03\nG1 X30.\n"
           "M30\n")
TURNING = "O0001\nG21 G18 G99\nG0 X50. Z5.\nM03 S1000\nT0202\nG1 X40. F0.2\nZ-10.\nM30\n"
RADIUS_MOVES = [("rapid", 25.0, 5.0), ("feed", 20.0, 5.0), ("feed", 20.0, -10.0), ("feed", 15.0, -10.0)]


def _translate(text: str, target: str, warn: bool = False) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = translate(io.StringIO(text), out, file="l.nc", source="fanuc", target=target, setup=LATHE,
                            on_unsupported="warn" if warn else "error")
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


@pytest.mark.parametrize("target", ["linuxcnc", "isg"])
def test_an_index_with_the_spindle_turning_is_refused_where_it_stands(target: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(TURNING, target)
    assert [str(e) for e in caught.value.errors] == [
        "l.nc:5:1: error: a turret index (T0202) with the spindle turning: a mill control changes the tool "
        "with the spindle stopped, the lathe keeps it turning (stop the spindle before the index, or give a set-up "
        "whose machine changes tools with the spindle on: <Controller toolChangeWithSpindleOn=\"true\"/>)"]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_machine_that_changes_tools_with_the_spindle_on_takes_the_index_as_its_tool_change() -> None:
    """LinuxCNC's ``[EMCIO] TOOL_CHANGE_WITH_SPINDLE_ON = 1`` (for lathes) leaves the spindle turning through
    ``M6``: rs274 run with it prints no STOP_SPINDLE_TURNING, without it one before CHANGE_TOOL. A set-up that
    says so (``<Controller toolChangeWithSpindleOn="true"/>``) gets the index written as ``T2 M6`` with the
    spindle on, and verify passes; checked under the set-up without it, the same output stops the spindle
    at the change, which verify finds."""
    import dataclasses

    from postproc.setup.groups import ControllerSettings

    keeps = MachineSetup(input=InputSettings(machine_type="lathe"),
                         controller=ControllerSettings(tool_change_with_spindle_on=True))
    out = io.StringIO()
    translate(io.StringIO(TURNING), out, file="l.nc", source="fanuc", target="linuxcnc", setup=keeps)
    text = out.getvalue()
    lines = text.splitlines()
    assert lines.index("S1000 M3") < lines.index("T2 M6") and "M5" not in lines, text
    table = "T2 P2 X0 Z0 D0\n"
    with_it = run_rs274(text, tool_table=table, ini="[EMCIO]\nTOOL_CHANGE_WITH_SPINDLE_ON = 1\n")
    without = run_rs274(text, tool_table=table)
    assert not any("STOP_SPINDLE_TURNING" in c for c in with_it[:[i for i, c in enumerate(with_it) if "CHANGE_TOOL(" in c][0]])
    assert any("STOP_SPINDLE_TURNING" in c for c in without[:[i for i, c in enumerate(without) if "CHANGE_TOOL(" in c][0]])
    args = dict(file_in="l.nc", file_out="l.ngc", source="fanuc", target="linuxcnc", tolerance=0.0)
    assert verify_lines(io.StringIO(TURNING), io.StringIO(text), setup=keeps, **args).ok  # type: ignore[arg-type]
    stops = dataclasses.replace(keeps.controller, tool_change_with_spindle_on=False)
    report = verify_lines(io.StringIO(TURNING), io.StringIO(text), setup=MachineSetup(
        input=InputSettings(machine_type="lathe"), controller=stops), **args)  # type: ignore[arg-type]
    assert not report.ok and "spindle stop" in report.summary()


def test_with_warn_only_the_t_word_is_left_out() -> None:
    text, warnings = _translate(TURNING, "linuxcnc", warn=True)
    assert "(UNSUPPORTED T0202)" in text and "M6" not in text and "G1 X40. F0.2" in text, text  # G7: a diameter
    assert len(warnings) == 1 and "l.nc:5:1: warning: a turret index (T0202)" in warnings[0]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_an_index_with_the_spindle_stopped_is_the_tool_change_and_moves_alike() -> None:
    text, _ = _translate(STOPPED, "linuxcnc")
    # the index's offset number is LinuxCNC's G43 register: its tool table entry's X and Z offsets; Fanuc
    # applies it with the next move (both axes), LinuxCNC where X and Z are programmed: the move gets both
    lines = text.splitlines()
    assert "T2 M6" in lines and "G43 H02 G1 X40. Z5. F0.2" in lines and "G43 H03 G1 X30. Z-10." in lines, text
    moves = [(e["move"], round(e["x"], 4), round(e["z"], 4))
             for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
    assert moves == RADIUS_MOVES
    ours = [(e["move"], e["x"] / 2, e["z"]) for e in toolpath_events(io.StringIO(STOPPED), file="l.nc",
                                                                      dialect="fanuc", setup=LATHE) if "move" in e]
    assert ours == RADIUS_MOVES
    report = verify_lines(io.StringIO(STOPPED), io.StringIO(text), file_in="l.nc", file_out="l.ngc",
                          source="fanuc", target="linuxcnc", setup=LATHE, tolerance=0.0)
    assert report.ok, report.summary()


# -- the offset number ---------------------------------------------------------------------------------

OFFSETS = ("O0001\nG21 G18 G99\nT0102\nM03 S1000\nG0 X50. Z5.\nG1 X40. F0.2\nM05\nT0100\nG0 X60.\n"
           "M30\n")
TABLE = "T1 P1 X0 Z0 D0\nT2 P2 X0.1 Z0.2 D0\n"
"""Entry 2 shifts X by 0.1 in and Z by 0.2 in (a standalone rs274 reads its table in inches)."""


def test_the_offset_number_becomes_the_register_and_offset_zero_the_cancel() -> None:
    text, warnings = _translate(OFFSETS, "linuxcnc")
    lines = text.splitlines()
    # T0102: tool 1, offset 2, applied by the next move (with both axes, as Fanuc T moves both there)
    assert "G43 H02 G0 X50. Z5." in lines and "G49 G0 X60. Z5." in lines, text
    assert warnings == []


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_applies_the_offset_the_turret_index_selected() -> None:
    """[V] rs274: G43 H2 on a lathe applies entry 2's X and Z offsets (USE_TOOL_LENGTH_OFFSET), and G49
    takes them off: what Fanuc's T0102 and T0100 do with offset register 2."""
    text, _ = _translate(OFFSETS, "linuxcnc")
    calls = [c for c in run_rs274(text, tool_table=TABLE) if "TOOL_LENGTH_OFFSET" in c]
    assert len(calls) == 2, calls
    first = [float(v) for v in calls[0].split("(", 1)[1].rstrip(")").replace(",", " ").split()]
    last = [float(v) for v in calls[1].split("(", 1)[1].rstrip(")").replace(",", " ").split()]
    assert first[0] == pytest.approx(0.1 * 25.4) and first[2] == pytest.approx(0.2 * 25.4), calls
    assert all(v == 0 for v in last), calls


def test_verify_compares_the_offset_selected_on_both_sides() -> None:
    """The set-up holds no lathe offsets to apply: the selection is compared, and another register fails."""
    text, _ = _translate(OFFSETS, "linuxcnc")
    same = verify_lines(io.StringIO(OFFSETS), io.StringIO(text), file_in="l.nc", file_out="l.ngc",
                        source="fanuc", target="linuxcnc", setup=LATHE, tolerance=0.0)
    assert same.ok, same.summary()
    other = verify_lines(io.StringIO(OFFSETS), io.StringIO(text.replace("G43 H02", "G43 H03")), file_in="l.nc",
                         file_out="l.ngc", source="fanuc", target="linuxcnc", setup=LATHE, tolerance=0.0)
    assert not other.ok and "lathe tool offset" in other.summary(), other.summary()
    none = verify_lines(io.StringIO(OFFSETS), io.StringIO(text.replace("G43 H02 ", "")), file_in="l.nc",
                        file_out="l.ngc", source="fanuc", target="linuxcnc", setup=LATHE, tolerance=0.0)
    assert not none.ok, none.summary()


def test_a_mill_control_without_lathe_offsets_needs_the_set_up_values() -> None:
    """grbl has no lathe tool offsets: they are written into the coordinates from the set-up, so a
    set-up that gives none is a located error naming the element (it warned, and verify failed, before)."""
    source = OFFSETS.replace("G99", "G98").replace("F0.2", "F200.")  # feed per minute: grbl has no other
    with pytest.raises(ErrorList) as caught:
        _translate(source, "grbl")
    assert [str(e) for e in caught.value.errors] == [
        'l.nc:3:1: error: T0102 selects lathe offset 02, which the target has no way to apply: it is written into '
        'the coordinates from the set-up, which gives offset 2 no X and Z (add <Tool number="2" x=".." z=".."/> '
        'to its <Tools>)']
