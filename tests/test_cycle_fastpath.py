"""The fast cycle expansion makes exactly the moves the reference tool path made.

``ToolPath`` keeps the tool's three coordinates in fields and ``_move`` works on them instead of copying
a position dictionary for every move. ``ReferencePath`` below is the tool path as it was before that change (a dictionary per move,
every axis compared), kept here as the oracle: over random cycles of every kind, semantics, return
level, plane, distance mode (G91 rows) and peck depth, both give the same items, in the same order,
with the same numbers (compared exactly, float for float), and leave the tool in the same place.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.cycles.expansion import EPS, CycleExpansion, ToolPath
from postproc.cycles.resolve import EXPANSIONS
from postproc.cycles.section import CannedCycle
from postproc.errors import ProgramError
from postproc.ir import Motion, Section
from postproc.ir.state import PLANE_AXES

KINDS = sorted({(kind, cls) for cls in EXPANSIONS for kind in cls.KINDS}, key=lambda pair: pair[0])
coordinate = st.floats(-50.0, 50.0, allow_nan=False).map(lambda v: round(v, 3))


class ReferencePath(ToolPath):
    """The tool path's moves as first written: the position a dictionary, the target a copy of it, every
    axis checked (but for an unknown level, which is now the same located error as an unknown axis, and a move in
    the plane alone from an unknown level, which leaves the level unknown: Fanuc's positioning after a reference
    return in cycle mode)."""

    __slots__ = ("pos",)

    def __init__(self, cycle: CannedCycle) -> None:
        super().__init__(cycle)
        self.pos = dict(cycle.start)

    def level(self) -> float:
        if self.axes[2] not in self.pos:
            raise ProgramError(f"the tool's {self.axes[2]} position is unknown before the cycle")
        return self.pos[self.axes[2]]

    def set_level(self, level: float) -> None:
        self.pos[self.axes[2]] = level

    def end(self) -> dict[str, float]:
        return dict(self.pos)

    def _move(self, mode: str, a: float | None, b: float | None, level: float | None) -> None:
        first, second, normal = self.axes
        target = dict(self.pos)
        for axis, value in ((first, a), (second, b), (normal, level)):
            if value is not None:
                target[axis] = value
        missing = [k for k in "XYZ" if k not in target]
        if missing == [normal] and level is None:  # positioning where the level is unknown: in the plane alone
            self.add(Motion(mode, {k: target[k] for k in "XYZ" if k != normal}))
            self.pos = target
            return
        if not missing and all(k in self.pos and abs(target[k] - self.pos[k]) < EPS for k in "XYZ"):
            return
        if missing:
            raise ProgramError(f"the tool's {missing[0]} position is unknown before the cycle")
        self.add(Motion(mode, {k: target[k] for k in "XYZ"}))
        self.pos = target


def holes(cycle: CannedCycle) -> list[tuple[float, float]]:
    """The plane positions of the block's holes, as the expansion first listed them: a G91 row, or the same spot
    K times."""
    first, second, _ = PLANE_AXES[cycle.plane]
    a, b = cycle.position[first], cycle.position[second]
    da, db = cycle.step.get(first, 0.0), cycle.step.get(second, 0.0)
    return [(a + i * da, b + i * db) for i in range(cycle.repeat)]


def reference_expand(expansion: CycleExpansion, cycle: CannedCycle) -> tuple[list[Section], dict[str, float]]:
    path = ReferencePath(cycle)
    if cycle.repeat <= 0:
        return [], path.end()
    expansion._enter(path, cycle, 1 << 62)
    for a, b in holes(cycle):
        expansion.hole(path, cycle, a, b)
    return path.items, path.end()


def exact(items: list[Section]) -> list[tuple[object, ...]]:
    """Items as comparable tuples: class, key and every attribute, floats by their bits (repr)."""
    out: list[tuple[object, ...]] = []
    for item in items:
        if isinstance(item, Motion):
            out.append(("Motion", item.mode, [(k, repr(v)) for k, v in item.axes.items()], item.center, item.radius))
        else:
            out.append((type(item).__name__, repr(item._key())))
    return out


@st.composite
def cycles(draw: st.DrawFn) -> tuple[type[CycleExpansion], CannedCycle]:
    """Random cycles, with the coincidences that make moves vanish drawn often: the tool already on the
    hole, at R, at the initial level; R on the bottom; a G91 row with a zero step."""
    kind, cls = draw(st.sampled_from(KINDS))
    plane = draw(st.sampled_from(["XY", "ZX", "YZ"]))
    first, second, normal = PLANE_AXES[plane]
    level = st.floats(-30.0, 40.0).map(lambda v: round(v, 3))
    r = draw(level)
    bottom = draw(st.one_of(st.just(r), st.floats(-30.0, r).map(lambda v: round(v, 3))))
    initial = draw(st.one_of(st.just(r), st.just(bottom), level))
    here = (draw(coordinate), draw(coordinate))
    position = draw(st.one_of(st.just(here), st.tuples(coordinate, coordinate)))
    start = {first: here[0], second: here[1], normal: draw(st.one_of(st.just(initial), st.just(r), level))}
    step = draw(st.sampled_from([{}, {first: 0.0, second: 0.0},
                                 {first: draw(coordinate), second: draw(coordinate)}]))
    return cls, CannedCycle(
        kind, semantics=draw(st.sampled_from(["fanuc", "rs274"])),
        return_level=draw(st.sampled_from(["initial", "r"])), plane=plane, initial=initial, r=r,
        bottom=bottom, top=draw(st.floats(bottom, bottom + 20.0).map(lambda v: round(v, 3))),
        q=draw(st.floats(0.3, 12.0)), clearance=draw(st.sampled_from([None, 0.0, 0.254, 0.5])),
        dwell=draw(st.sampled_from([None, 0.0, 0.5])), orient=draw(st.sampled_from([None, 0.0, 90.0])),
        feed=draw(st.sampled_from([None, 100.0, 250.5])), repeat=draw(st.integers(0, 4)),
        spindle=draw(st.sampled_from(["cw", "ccw", "stop"])), motion="linear", start=start,
        position={first: position[0], second: position[1]}, step=step,
        shift=draw(st.sampled_from([None, {first: 0.5, second: 0.0}, {first: 0.0, second: -0.25}])))


def outcome(run: object) -> tuple[str, object]:
    try:
        items, end = run()  # type: ignore[operator]
    except ProgramError as err:
        return type(err).__name__, str(err)
    return "ok", (exact(items), [(k, repr(v)) for k, v in end.items()])


@settings(max_examples=400, deadline=None)
@given(cycles())
def test_the_expansion_makes_exactly_the_reference_moves(case: tuple[type[CycleExpansion], CannedCycle]) -> None:
    cls, cycle = case
    expansion = cls()
    assert outcome(lambda: expansion.expand(cycle)) == outcome(lambda: reference_expand(expansion, cycle))


@settings(max_examples=100, deadline=None)
@given(cycles(), st.sampled_from(["X", "Y", "Z"]))
def test_an_unknown_axis_is_the_same_error(case: tuple[type[CycleExpansion], CannedCycle], axis: str) -> None:
    cls, cycle = case
    cycle.start.pop(axis)
    expansion = cls()
    assert outcome(lambda: expansion.expand(cycle)) == outcome(lambda: reference_expand(expansion, cycle))
