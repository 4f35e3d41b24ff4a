"""Defect: LinuxCNC's repeated-state check (a loop head reached again with everything the program can read as
the time before is endless, refused at once) was off wherever the run evaluates the frames - ``toolpath``,
``verify`` and a translation that flattens - because the parameters then read the frame (``#5221``...) and
the variables' snapshot gave up. The snapshot now holds what the frame readings can answer too, so the one
check runs everywhere, and a loop that only the frame changes still runs to its end."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.groups import MachineSettings
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

BOUND = 20_000
SMALL = MachineSetup(limits=Limits(repeated_work=BOUND))
ENDLESS = ("G21 G90 G0 X0 Y0 Z5\n#1 = 0\no1 while [#1 LT 10]\n#1 = [#1 + 1]\n#1 = [#1 - 1]\nG1 X1 F100\nG1 X0\n"
           "o1 endwhile\nM2\n")
NEVER = ("t.ngc:8:1: error: loop 'o1 endwhile' never ends: it runs again with every variable as the time before, "
         "so nothing can change (does the program count its variable?)")


def test_toolpath_refuses_an_endless_loop_at_its_second_pass() -> None:
    moves = 0
    with pytest.raises(ErrorList) as info:
        for ev in toolpath_events(io.StringIO(ENDLESS), file="t.ngc", dialect="linuxcnc", setup=SMALL):
            moves += "move" in ev
    assert [str(e) for e in info.value.errors] == [NEVER]
    assert moves <= 5  # the start, and two passes of two moves: far below the bound of 20,000


def test_a_flattening_translation_refuses_it_too() -> None:
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(ENDLESS), io.StringIO(), file="t.ngc", source="linuxcnc", target="grbl", setup=SMALL,
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert [str(e) for e in info.value.errors] == [NEVER]


# Nothing but the frame changes from one pass to the next: G54's X offset, which the test reads, grows by 1 each
# pass, so the loop ends after 3 passes (rs274 runs it so; the bound 2.5, not 3: an offset kept in mm reads back in
# inches within a rounding of 3). In inches on an inch machine: a standalone rs274
# keeps its offset parameters in inches.
FRAME_COUNTED = ("G20 G90 G10 L2 P1 X0\nG54 G0 X0 Y0 Z5\no1 while [#5221 LT 2.5]\nG10 L2 P1 X[#5221 + 1]\n"
                 "G0 X0 Y1\nG0 Y0\no1 endwhile\nM2\n")
INCH = MachineSetup(machine=MachineSettings(units="inch"), limits=Limits(repeated_work=BOUND))


def test_a_loop_that_only_the_frame_changes_runs_to_its_end() -> None:
    events = [e for e in toolpath_events(io.StringIO(FRAME_COUNTED), file="t.ngc", dialect="linuxcnc", setup=INCH)
              if "move" in e]
    # the toolpath's frame holds a program's own offsets: X0 is 1, 2, 3 inches along in the three passes
    assert [(e["x"], e["y"]) for e in events] == [(0, 0), (25.4, 25.4), (25.4, 0), (50.8, 25.4), (50.8, 0),
                                                  (76.2, 25.4), (76.2, 0)]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_frame_counted_loop_three_times() -> None:
    passes = [e for e in canonical_moves(run_rs274(FRAME_COUNTED)) if e.get("move") == "rapid" and e["y"] == 25.4]
    assert len(passes) == 3
