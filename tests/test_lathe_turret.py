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
        "with the spindle stopped, the lathe keeps it turning (stop the spindle before the index)"]


def test_with_warn_only_the_t_word_is_left_out() -> None:
    text, warnings = _translate(TURNING, "linuxcnc", warn=True)
    assert "(UNSUPPORTED T0202)" in text and "M6" not in text and "G1 X40. F0.2" in text, text  # G7: a diameter
    assert len(warnings) == 1 and "l.nc:5:1: warning: a turret index (T0202)" in warnings[0]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_an_index_with_the_spindle_stopped_is_the_tool_change_and_moves_alike() -> None:
    text, _ = _translate(STOPPED, "linuxcnc")
    assert "T2 M6" in text.splitlines() and "T3 M6" in text.splitlines(), text
    moves = [(e["move"], round(e["x"], 4), round(e["z"], 4))
             for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
    assert moves == RADIUS_MOVES
    ours = [(e["move"], e["x"] / 2, e["z"]) for e in toolpath_events(io.StringIO(STOPPED), file="l.nc",
                                                                      dialect="fanuc", setup=LATHE) if "move" in e]
    assert ours == RADIUS_MOVES
    report = verify_lines(io.StringIO(STOPPED), io.StringIO(text), file_in="l.nc", file_out="l.ngc",
                          source="fanuc", target="linuxcnc", setup=LATHE, tolerance=0.0)
    assert report.ok, report.summary()
