"""The settle pass (``postproc.lowering.arcs``, grbl's and grblHAL's ``settle_arc_ends``) follows most blocks without
its general way (``_Arcs.rewrite``, ``_Rewriter.block``):

* a block whose other sections are inert to it (``INERT``: a feed, comments, the spindle, the coolant) beside a
  straight move, a kept-centre arc or an R arc the bound keeps (``_Arcs.take`` -> ``follow_move``);
* an expanded cycle's moves without an arc, by where they end (``point_after.compound_end``), and a block that is such
  an expansion beside ``INERT`` sections (an expanded hole: ``_Arcs.take`` -> ``_Rewriter.moved_to_end``).

Held on random blocks to the general way (the same blocks out, the same moves, the same position after each, R arcs
near half a turn among them: rewritten either way; expansions among them, with arcs, spindle actions and computed
words), and on random expansions to the position each of their moves gives in turn.
"""

from __future__ import annotations

import math

from hypothesis import example, given, settings, strategies as st

from postproc.context import Context
from postproc.errors import Diagnostics, ErrorLevel
from postproc.ir import Block, Comments, CompoundMotion, Coolant, DistanceMode, Dwell, Feed, Motion, ProgramControl
from postproc.ir import Section, Sequence, SpindleControl, SpindleSpeed
from postproc.ir.expr import Expr, Var
from postproc.lowering.arcs import SETTLE, ArcOption, _Arcs
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup


def _step(target: str = "grbl") -> _Arcs:
    ctx = Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE), "fanuc")
    return _Arcs(ctx, ArcOption(SETTLE), default_registry().dialect(target))


numbers = st.floats(-200.0, 200.0, allow_nan=False).map(lambda v: round(v, 3))
plain_axes = st.dictionaries(st.sampled_from(["X", "Y", "Z"]), numbers, min_size=1, max_size=3)


@st.composite
def moves(draw: st.DrawFn) -> Motion:
    """A straight move, an I/J arc, or an R arc (a third of them a half turn from the origin, within rounding)."""
    kind = draw(st.sampled_from(["linear", "rapid", "ij", "r", "half"]))
    if kind in ("linear", "rapid"):
        return Motion(kind, draw(plain_axes))
    mode = draw(st.sampled_from(["cw", "ccw"]))
    if kind == "ij":
        return Motion(mode, draw(plain_axes), {"X": draw(numbers), "Y": draw(numbers)})
    if kind == "r":
        return Motion(mode, draw(plain_axes), None, draw(st.floats(0.5, 300.0).map(lambda v: round(v, 3))))
    radius = draw(st.floats(1.0, 100.0).map(lambda v: round(v, 3)))
    angle = draw(st.floats(0.0, 2 * math.pi))
    return Motion(mode, {"X": round(2 * radius * math.cos(angle), 3), "Y": round(2 * radius * math.sin(angle), 3)},
                  None, radius + draw(st.sampled_from([0.0, 0.0005, -0.0005, 0.001])))


inert = st.lists(st.sampled_from(["Feed", "Comments", "Coolant", "SpindleSpeed", "Sequence"]), unique=True, max_size=3)
"""Besides the move: sections ``INERT`` names."""


def _section(key: str) -> Section:
    return {"Feed": Feed(1500.0), "Comments": Comments(["A NOTE"]), "Coolant": Coolant("flood"),
            "SpindleSpeed": SpindleSpeed(8000.0), "Sequence": Sequence(10), "DistanceMode": DistanceMode("absolute"),
            "Dwell": Dwell(0.5)}[key]


def _copy(motion: Motion) -> Motion:
    return Motion(motion.mode, dict(motion.axes), dict(motion.center) if motion.center else None, motion.radius)


def _block(n: int, motion: Motion | None, keys: list[str], expansion: list[Section] | None = None) -> Block:
    block = Block(n, "", "\n")
    if motion is not None:
        block.sections["Motion"] = _copy(motion)
    if expansion is not None:  # (its own moves: the general way rewrites an arc among them in place)
        block.sections["CompoundMotion"] = CompoundMotion("cycle", [_copy(one) if isinstance(one, Motion) else one
                                                                    for one in expansion])
    for key in keys:
        block.sections[key] = _section(key)
    return block


expansion_item = st.one_of(
    moves(), moves(), moves(),
    st.builds(Motion, st.sampled_from(["rapid", "linear"]), st.dictionaries(st.sampled_from(["X", "Y", "Z"]),
                                                                             st.just(Var(name="depth")), min_size=1)),
    st.builds(Motion, st.just("linear"), st.dictionaries(st.sampled_from(["X", "A"]), numbers, min_size=1)),
    st.builds(Dwell, st.just(0.5)), st.builds(SpindleControl, st.sampled_from(["cw", "ccw", "stop"])),
    st.builds(ProgramControl, st.just("stop")),
)
"""An expansion's items: moves (arcs and R arcs near a half turn among them), a computed word, another axis, a dwell,
the spindle."""


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.one_of(st.none(), moves()), inert, st.sampled_from([[], [], [], ["DistanceMode"],
                                                                                  ["Dwell"]]),
                          st.one_of(st.none(), st.none(), st.lists(expansion_item, max_size=8))),
                max_size=14),
       st.sampled_from(["grbl", "grblhal"]))
@example([(Motion("linear", {"X": 0.0, "Y": 0.0}), ["Feed"], [], None),
          (Motion("cw", {"X": 50.0, "Y": 0.0}, None, 25.0), ["Feed", "Sequence"], [], None)], "grbl")
@example([(Motion("linear", {"X": 0.0, "Y": 0.0}), [], [], None),
          (None, ["Sequence"], [], [Motion("rapid", {"X": 3.0, "Y": 4.0, "Z": 2.0}), Motion("linear", {"Z": -5.0})]),
          (None, [], [], [Motion("cw", {"X": 53.0, "Y": 4.0}, None, 25.0)])], "grbl")
def test_a_block_followed_is_one_the_general_way_gives_as_it_was(
        program: list[tuple[Motion | None, list[str], list[str], list[Section] | None]], target: str) -> None:
    fast, slow = _step(target), _step(target)
    assert fast.kept_centres and fast.settles
    for n, (motion, keys, other, expansion) in enumerate(program):
        if motion is None and not keys and not other and expansion is None:
            continue
        mine, theirs = _block(n + 1, motion, keys + other, expansion), _block(n + 1, motion, keys + other, expansion)
        got, expected = fast.take(mine), slow.rewrite(theirs)
        assert (got is None) == (expected is None)
        assert mine.sections == theirs.sections
        fast.rewriter.settle()
        slow.rewriter.settle()
        assert fast.rewriter.position == slow.rewriter.position
        assert (fast.point is None) == (slow.point is None)


def test_an_expanded_hole_beside_its_number_is_followed_by_where_it_ends() -> None:
    """Not vacuous: an expanded hole (its moves straight) beside a block number goes the fast way (``moved_to_end``,
    not ``rewrite``), and one with a half turn by R among its moves has the arc rewritten by I/J/K through ``take``."""
    calls: list[Block] = []

    class Counting(_Arcs):
        def rewrite(self, block: Block) -> list[Block] | None:
            calls.append(block)
            return super().rewrite(block)

    ctx = Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE), "fanuc")
    step = Counting(ctx, ArcOption(SETTLE), default_registry().dialect("grbl"))
    step.take(_block(1, Motion("linear", {"X": 0.0, "Y": 0.0}), []))
    calls.clear()
    hole = [Motion("rapid", {"X": 3.0, "Y": 4.0, "Z": 2.0}), Motion("linear", {"X": 3.0, "Y": 4.0, "Z": -5.0})]
    assert step.take(_block(2, None, ["Sequence"], hole)) is None
    assert calls == []
    step.rewriter.settle()
    assert step.rewriter.position == {"X": 3.0, "Y": 4.0, "Z": -5.0}
    block = _block(3, None, [], [Motion("cw", {"X": 53.0, "Y": 4.0}, None, 25.0)])
    assert step.take(block) is None
    assert calls == [block]
    arc = block.sections["CompoundMotion"].items[0]  # type: ignore[attr-defined]
    assert isinstance(arc, Motion) and arc.radius is None and arc.center is not None


def test_a_half_turn_by_r_beside_a_feed_is_still_written_by_its_centre() -> None:
    """Not vacuous: the example's half turn by R is rewritten by I/J/K through ``take`` too."""
    step = _step()
    step.take(_block(1, Motion("linear", {"X": 0.0, "Y": 0.0}), []))
    block = _block(2, Motion("cw", {"X": 50.0, "Y": 0.0}, None, 25.0), ["Feed"])
    assert step.take(block) is None
    motion = block.sections["Motion"]
    assert isinstance(motion, Motion) and motion.radius is None and motion.center is not None


words = st.one_of(numbers, numbers, numbers, st.just(Var(name="depth")))
item = st.one_of(
    st.builds(Motion, st.sampled_from(["rapid", "linear"]), st.dictionaries(st.sampled_from(["X", "Y", "Z"]), words,
                                                                            min_size=1, max_size=3)),
    st.builds(lambda mode, axes: Motion(mode, axes, {"X": 1.0, "Y": 0.0}), st.sampled_from(["cw", "ccw"]), plain_axes),
    st.builds(Dwell, st.just(0.5)),
)


@settings(max_examples=300, deadline=None)
@given(st.lists(item, max_size=12), st.dictionaries(st.sampled_from(["X", "Y", "Z"]), numbers))
def test_an_expansion_leaves_the_position_where_its_moves_take_it_in_turn(
        items: list[Section], start: dict[str, float]) -> None:
    """With an arc among the moves (a kept I/J arc: only followed) the moves are walked, without one where they end
    is taken: either way the position after them is each move's words in turn (a computed word: not known)."""
    step = _step()
    step.ctx.state.symbolic = True
    rewriter = step.rewriter
    rewriter.position.update(start)
    expected: dict[str, float | None] = dict(rewriter.position)
    for one in items:
        if isinstance(one, Motion):
            expected.update({a: None if isinstance(v, Expr) else v for a, v in one.axes.items()})
    block = Block(1, "", "\n")
    block.sections["CompoundMotion"] = CompoundMotion("cycle", list(items))
    assert step.take(block) is None
    rewriter.settle()
    assert rewriter.position == expected
