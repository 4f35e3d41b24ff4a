"""The reading state's own following of the set-up's homes and work offsets (``ModalState.places``, made by
``postproc.setup.work_offsets.set_up_places``), block by block: where a reference return, a move in machine
coordinates or a change of work system leaves the tool, and where the following stops.

It was a hook the modal step called at every block that changes a mode; it is data the state reads now, and
these cases pin what the hook did where the order of a block's sections or its modes could make the two differ
(units changed in the block that changes the work system, a length offset in force, incremental distance, a
frame the program sets). The expected positions are derived by hand from the set-up below: X home -100, G54
X-150, G55 X-95, an external offset of X10 (machine coordinates, mm): work = machine - (system's + external).
"""

from __future__ import annotations

import copy
import io

import pytest

from postproc.errors import Diagnostics, ErrorLevel
from postproc.ir.state import ModalState
from postproc.plugins import default_registry
from postproc.reading import read_blocks
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.setup.work_offsets import set_up_places
from postproc.context import Context
from tests.test_arc_set_up_start import SETUP as ARC_SET_UP

SETUP = ARC_SET_UP.replace("<WorkOffsets>\n", '<WorkOffsets>\n    <Offset number="0" x="10."/>\n')
"""``tests.test_arc_set_up_start``'s set-up (X home -100, Y and Z home 0; G54 X-150 Y0 Z0, G55 X-95 Y0 Z0) with an
external offset X10."""


@pytest.fixture(scope="module")
def setup(tmp_path_factory: pytest.TempPathFactory) -> MachineSetup:
    path = tmp_path_factory.mktemp("setup") / "m.xml"
    path.write_text(SETUP)
    return load_setup(path)


def position_after(program: str, setup: MachineSetup) -> dict[str, float | None]:
    """The reading's position after the whole program, read (fanuc) with the set-up's places followed, as a
    translation to another dialect reads it."""
    def prepare(ctx: Context) -> None:
        ctx.state.places = set_up_places(setup)

    ctx, blocks = read_blocks(io.StringIO(program), "in.nc", default_registry().dialect("fanuc"), setup,
                              Diagnostics(ErrorLevel.IMMEDIATE), prepare=prepare)
    for _ in blocks:
        pass
    return dict(ctx.state.position)


def test_the_places_are_the_declared_values_summed_with_the_external_offset(setup: MachineSetup) -> None:
    places = set_up_places(setup)
    assert places is not None
    assert places.homes == {"X": -100.0, "Y": 0.0, "Z": 0.0}
    # system 1: X -150 + 10 (external), Y 0 + 0, Z 0 + 0; system 2: X -95 + 10
    assert places.offsets[1] == {"X": -140.0, "Y": 0.0, "Z": 0.0}
    assert places.offsets[2] == {"X": -85.0, "Y": 0.0, "Z": 0.0}


def test_a_set_up_without_work_offsets_places_nothing() -> None:
    assert set_up_places(MachineSetup()) is None


@pytest.mark.parametrize(("program", "expected"), [
    # a first reference return: X home -100 - (-140) = 40; Y 0; Z not returned, never programmed
    ("G21 G90 G17\nG28 X0. Y0.\n", {"X": 40.0, "Y": 0.0, "Z": None}),
    # a machine move under absolute distance: the words are machine positions
    ("G21 G90 G17\nG53 G0 X-100. Y5.\n", {"X": 40.0, "Y": 5.0, "Z": None}),
    # ... in inches: -3.937 in = -99.9998 mm, 40.0002 mm = 1.574811023622 in (12 places)
    ("G20 G90 G17\nG53 G0 X-3.937\n", {"X": 1.574811023622, "Y": None, "Z": None}),
    # under incremental distance a machine word is no position: unknown
    ("G21 G91 G17\nG53 G0 X-100. Y5.\n", {"X": None, "Y": None, "Z": None}),
    # a length offset in force: Z's programmed point is the controlled point less a length: unknown
    ("G21 G90 G17\nG43 H1 Z10.\nG28 X0. Z0.\n", {"X": 40.0, "Y": None, "Z": None}),
    # cancelled: Z is placed (home 0 - 0)
    ("G21 G90 G17\nG43 H1 Z10.\nG49\nG28 X0. Z0.\n", {"X": 40.0, "Y": None, "Z": 0.0}),
    # a second reference return: no element gives it
    ("G21 G90 G17\nG30 X0. Y0.\n", {"X": None, "Y": None, "Z": None}),
    # a change of work system: X0 under G54 is machine -140, X-55 under G55 (-85)
    ("G21 G90 G17 G54\nG0 X0. Y0.\nG55\n", {"X": -55.0, "Y": 0.0, "Z": None}),
    # ... with inches chosen in the same block: the machine point taken in mm before it, placed in inches after it
    # (-55 / 25.4 = -2.165354330709, 12 places), whatever the order of the two words
    ("G21 G90 G17 G54\nG0 X0. Y0.\nG55 G20\n", {"X": -2.165354330709, "Y": 0.0, "Z": None}),
    ("G21 G90 G17 G54\nG0 X0. Y0.\nG20 G55\n", {"X": -2.165354330709, "Y": 0.0, "Z": None}),
    # ... and back: X1 in under G54 is machine 25.4 - 140 = -114.6 mm, under G55 mm
    ("G20 G90 G17 G54\nG0 X1. Y0.\nG55 G21\n", {"X": -29.6, "Y": 0.0, "Z": None}),
    # a system the set-up does not give: unknown
    ("G21 G90 G17 G54\nG0 X0. Y0.\nG56\n", {"X": None, "Y": None, "Z": None}),
    # the active system selected again moves nothing
    ("G21 G90 G17 G54\nG0 X3. Y4.\nG54\n", {"X": 3.0, "Y": 4.0, "Z": None}),
])
def test_the_state_places_the_tool_where_the_set_up_puts_it(setup: MachineSetup, program: str,
                                                           expected: dict[str, float | None]) -> None:
    found = position_after(program, setup)
    assert found == pytest.approx(expected, abs=1e-12), found


@pytest.mark.parametrize("program", [
    "G21 G90 G17\nG92 X0.\nG28 X0. Y0.\n",  # the program sets its frame (G92): the run holds the values
    "G21 G90 G17\nG10 L2 P1 X5.\nG28 X0. Y0.\n",  # the program writes a work offset
    "G21 G90 G17 G54\nG0 X0. Y0.\nG55 G92 X1.\nG28 Y0.\n",  # in the block that changes the system: not placed
])
def test_after_a_frame_the_program_sets_nothing_is_placed_any_more(setup: MachineSetup, program: str) -> None:
    found = position_after(program, setup)
    assert found["Y"] is None, found


def test_a_reading_without_the_places_leaves_every_such_position_unknown(setup: MachineSetup) -> None:
    ctx, blocks = read_blocks(io.StringIO("G21 G90 G17 G54\nG0 X0. Y0.\nG55\nG28 X0.\n"), "in.nc",
                              default_registry().dialect("fanuc"), setup, Diagnostics(ErrorLevel.IMMEDIATE))
    for _ in blocks:
        pass
    assert ctx.state.places is None
    assert ctx.state.position == {"X": None, "Y": None, "Z": None}



def test_a_copy_of_the_state_follows_the_same_places(setup: MachineSetup) -> None:
    """A dry run reads from a copy of the reading's state (``postproc.api``: ``copy.deepcopy``): the copy has the
    places (compiled too: a native class copies only where it allows interpreted subclasses), and ending the
    following in it leaves the original's."""
    state = ModalState()
    state.places = set_up_places(setup)
    twin = copy.deepcopy(state)
    assert twin.places is not None and state.places is not None
    assert (twin.places.homes, twin.places.offsets) == (state.places.homes, state.places.offsets)
    twin.places = None
    assert state.places is not None
