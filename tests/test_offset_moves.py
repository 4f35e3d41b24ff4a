"""The simulator's direct moves under a tool length (and a lathe's tool offset) alone, held to its general path.

A straight move and an arc made while only a length or tool offset moves the controlled point are written by
``Moves._offset_line`` and ``Moves._offset_arc`` in one pass; the general path (``Moves._compensated``: the
cutter's segment, written by ``_write``) makes every compensated move. On random points, offsets and arcs both
must emit the same events (the same JSON text: an int stays an int) and leave the same state."""

from __future__ import annotations

import json

from hypothesis import given, settings, strategies as st

from postproc.context import Context
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.events import num
from postproc.simulate.simulator import Simulator

COORD = st.one_of(st.integers(-500, 500).map(float), st.floats(-500.0, 500.0, allow_nan=False).map(lambda v: round(v, 4)))
OFFSET = st.one_of(st.just(0.0), st.integers(-200, 200).map(float), st.floats(-200.0, 200.0).map(lambda v: round(v, 3)))
POINT = st.fixed_dictionaries({"X": COORD, "Y": COORD, "Z": COORD})


def _simulator(pos: dict[str, float], length: float, shift: dict[str, float], feed: float | None,
               plane: str) -> tuple[Simulator, list[dict[str, object]]]:
    sim = Simulator(Context("t.nc", MachineSetup(), Diagnostics(), "fanuc"))
    sim.pos = dict(pos)
    sim.rounded = [num(pos[a]) for a in sim.axes]
    sim.length.offset = length
    sim.lathe_shift = dict(shift)
    sim._begin()  # the controlled point of the last move: the programmed one (as after a tool change)
    sim.feed = feed
    sim.modal.plane = plane
    events: list[dict[str, object]] = []
    sim.out = events  # type: ignore[assignment]
    return sim, events


def _state(sim: Simulator) -> tuple[object, ...]:
    return (sim.pos, [json.dumps(v) for v in sim.rounded], [json.dumps(v) for v in sim.crounded],
            sim.compensating, sim.header_mode)


@settings(max_examples=300, deadline=None)
@given(start=POINT, end=POINT, length=OFFSET, shift_x=OFFSET, shift_z=OFFSET, rapid=st.booleans(),
       feed=st.sampled_from([1500.0, 250.5]), same=st.sets(st.sampled_from("XYZ")))
def test_a_straight_move_under_an_offset_is_the_general_paths(start: dict[str, float], end: dict[str, float],
                                                            length: float, shift_x: float, shift_z: float,
                                                            rapid: bool, feed: float, same: set[str]) -> None:
    target = {a: start[a] if a in same else end[a] for a in "XYZ"}
    shift = {"X": shift_x, "Z": shift_z} if shift_x or shift_z else {}
    kind = "rapid" if rapid else "feed"
    direct, direct_events = _simulator(start, length, shift, feed, "XY")
    general, general_events = _simulator(start, length, shift, feed, "XY")
    direct._offset_line(kind, [target[a] for a in direct.axes], 7)  # (a point in the order of the machine's axes)
    general._compensated(kind, [target[a] for a in general.axes], 7, None, None)
    assert [json.dumps(ev) for ev in direct_events] == [json.dumps(ev) for ev in general_events]
    assert _state(direct) == _state(general)


@settings(max_examples=300, deadline=None)
@given(start=POINT, end=POINT, centre=st.tuples(COORD, COORD), length=OFFSET, shift_x=OFFSET, shift_z=OFFSET,
       clockwise=st.booleans(), plane=st.sampled_from(["XY", "ZX", "YZ"]), feed=st.sampled_from([1500.0, 250.5]))
def test_an_arc_under_an_offset_is_the_general_paths(start: dict[str, float], end: dict[str, float],
                                                   centre: tuple[float, float], length: float, shift_x: float,
                                                   shift_z: float, clockwise: bool, plane: str, feed: float) -> None:
    shift = {"X": shift_x, "Z": shift_z} if shift_x or shift_z else {}
    kind = "cw" if clockwise else "ccw"
    direct, direct_events = _simulator(start, length, shift, feed, plane)
    general, general_events = _simulator(start, length, shift, feed, plane)
    direct._offset_arc(kind, [end[a] for a in direct.axes], 9, centre, plane)
    general._compensated(kind, [end[a] for a in general.axes], 9, centre, plane)
    assert [json.dumps(ev) for ev in direct_events] == [json.dumps(ev) for ev in general_events]
    assert _state(direct) == _state(general)
