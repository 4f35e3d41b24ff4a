"""The next-hole lane: a block that only moves an active hole cycle to its next hole (``X.. Y..``),
resolved as the same cycle record at another spot when nothing else it depends on changed.

A speed-only copy of what ``CannedCycleResolveSyntax`` makes of such a block, kept apart from the classes
dialects extend (STYLE.md 11). ``postproc.fast.reading`` installs it for a run only where the resolver
class resolves with the base's own methods, and ``tests/test_cycle_repeat.py`` holds it to resolving
from the block's words on random programs. It remembers the last next-hole block the resolver resolved
from its words, with everything of the state the resolver read to do it (``signature``); a later one in
the same state is that record with its hole position and start moved.
"""

from __future__ import annotations

from typing import Any, Final, cast

from mypy_extensions import mypyc_attr

from ..context import Context, HoleLane
from ..errors import PostprocError
from ..ir.expr import Expr
from ..ir import Block, CompoundMotion
from ..ir.state import PLANE_AXES, ModalState
from ..cycles.expansion import CycleExpansion
from ..cycles.resolve import (ACTIVE_KEY, DWELL_KEY, STATE_KEY, WORD_RANK, CannedCycleResolveSyntax, Failer,
                              LazyExpansion, cycle_words, drop_cycle_sections)
from ..cycles.rigid_tap import RIGID_KEY
from ..cycles.section import CannedCycle

_NEXT_HOLE_SECTIONS: Final = frozenset(("Motion", "Sequence", "Comments"))


@mypyc_attr(allow_interpreted_subclasses=True)
class Remembered:
    """A next-hole block the resolver resolved from its words: its cycle record, and what the resolver
    read from the state to make it (``signature``)."""

    __slots__ = ("signature", "cycle", "expansion", "code", "peck", "limit", "axes", "order", "over", "deep",
                 "compound")

    def __init__(self, signature: tuple[Any, ...], cycle: CannedCycle, expansion: CycleExpansion, code: str,
                 peck: str, limit: int) -> None:
        self.signature, self.cycle, self.expansion, self.code, self.peck = signature, cycle, expansion, code, peck
        self.limit = limit
        self.axes: tuple[str, str, str] = PLANE_AXES[cycle.plane]
        first, second, _ = self.axes
        self.order = (first, second) if WORD_RANK[first] < WORD_RANK[second] else (second, first)
        """The plane's two axes in ``WORD_ORDER``, the order the resolver keeps a block's words in."""
        self.over = expansion.ENDS_OVER_THE_SPOT
        """Every hole ends over its spot at the return level: the lane gives where the block leaves the tool
        (``install``'s ``end``), its levels having passed ``end``'s checks for the remembered block."""
        self.deep = self.over and cycle.r is not None and cycle.bottom is not None and cycle.r - cycle.bottom > DEEP
        """Every hole's moves end where the hole before's do, but over its own spot (``moves_end``)."""
        self.compound: CompoundMotion | None = None
        """The motion of the last block resolved from this record: where its moves end, once a step has asked
        (``point_after.compound_end``), gives the next hole's (``moves_end``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class NextHoleLane(HoleLane):
    """Resolves a next-hole block from the one before it (``repeat``), remembering each the resolver
    resolved from its words (``resolved``)."""

    __slots__ = ("resolver", "memo", "offered")

    def __init__(self, resolver: CannedCycleResolveSyntax) -> None:
        self.resolver = resolver
        self.memo: Remembered | None = None
        self.offered = False
        """The block ``repeat`` last declined is a next-hole block, so ``resolved`` remembers it."""

    def repeat(self, block: Block, ctx: Context) -> bool:
        state = ctx.state
        values = block.values
        self.offered = state.distance == "absolute" and _next_hole_only(block, state.plane)
        if not self.offered:
            return False
        memo = self.memo
        if memo is None or memo.signature != signature(state):
            return False
        pattern = memo.cycle
        first, second, normal = memo.axes
        tool = state.position
        a, b, n = tool.get(first), tool.get(second), tool.get(normal)
        if a is None or b is None or n is None:
            return False  # the resolver says what is unknown
        words: dict[str, float | int] = {}
        for letter in memo.order:
            value = values.get(letter)
            if value is not None:
                if type(value) is not float and isinstance(value, Expr):  # (a float first: cheaper)
                    return False  # the resolver keeps a computed word verbatim first
                words[letter] = value
        va, vb = words.get(first), words.get(second)
        at_a = a if va is None else float(va)
        at_b = b if vb is None else float(vb)
        spot = {first: at_a, second: at_b}
        # the tool's X, Y and Z, each known (the plane's three axes are): with no other axis, the whole of it
        here = cast("dict[str, float]", dict(tool)) if len(tool) == 3 else {
            k: v for k, v in tool.items() if k in "XYZ" and v is not None}
        cycle = CannedCycle(
            pattern.kind, call=False, semantics=pattern.semantics, return_level=pattern.return_level,
            plane=pattern.plane, initial=pattern.initial, r=pattern.r, bottom=pattern.bottom, top=pattern.top,
            q=pattern.q, clearance=pattern.clearance, dwell=pattern.dwell, orient=pattern.orient, feed=pattern.feed,
            repeat=1, spindle=pattern.spindle, motion=pattern.motion, start=here, position=spot, step={},
            shift=pattern.shift, words=words, pitch=pattern.pitch,  # a rigid tap stays rigid at every hole
        )
        fail = Failer(ctx, block, memo.code, False)
        fail.words = words
        expansion = memo.expansion
        lazy = LazyExpansion(expansion, cycle, memo.limit, fail, memo.code, memo.peck, None, ctx)
        self.offered = False
        if not memo.over:
            try:  # the expansion finds where the tool ends (and refuses what it refuses)
                self.resolver.install(block, ctx, cycle, lazy, None)
            except PostprocError:
                drop_cycle_sections(block)
                raise
            return True
        # ``install`` given where the block leaves the tool, which it then does without failing: its record
        # and motion added, the block's Motion(None) gone, the tool moved over the spot (as ``holes``
        # makes it: X-0. ends at 0.0) to the return level (a next-hole block has no CycleCall)
        over_a, over_b = at_a + 0.0, at_b + 0.0  # (the spot's, kept in locals: no look-up back)
        level = expansion.return_level(cycle)
        sections = block.sections
        compound = CompoundMotion.lazy(cycle.kind, lazy)
        sections["CannedCycle"] = cycle  # (``block.add``: each section at its KEY)
        sections["CompoundMotion"] = compound
        state.extra[ACTIVE_KEY] = (cycle, expansion)
        motion = sections.get("Motion")
        if motion is not None and motion.mode is None:  # type: ignore[attr-defined]
            del sections["Motion"]
        tool[first], tool[second], tool[normal] = over_a, over_b, level
        before = memo.compound
        if memo.deep and before is not None and before.ended:
            moved = moves_end(before.end, memo.axes, over_a, over_b)
            if moved is not None:
                compound.end, compound.ended = moved, True
        memo.compound = compound
        return True

    def resolved(self, block: Block, ctx: Context) -> None:
        if not self.offered:
            return
        self.offered = False
        cycle = block.sections.get("CannedCycle")
        if isinstance(cycle, CannedCycle) and cycle.repeat == 1 and not cycle.step:
            cw = cycle_words(ctx)
            self.memo = memo = Remembered(signature(ctx.state), cycle, self.resolver.expansion(cycle.kind),
                                          cw.name(cycle.kind), cw.peck, ctx.setup.limits.moves_per_block)
            compound = block.sections.get("CompoundMotion")
            if isinstance(compound, CompoundMotion):
                memo.compound = compound


DEEP: Final = 1e-6
"""A hole whose bottom lies this far below its R level (1,000 times ``expansion.EPS``): its cut to the bottom is
a move at every hole, wherever the tool stood before it."""


def moves_end(before: dict[str, float | None] | None, axes: tuple[str, str, str], a: float,
              b: float) -> dict[str, float | None] | None:
    """Where the moves of a next-hole block of one hole end (``point_after.compound_end``), from where those of
    the block before it, resolved from the same record, end (``before``), or None (unsure: the general walk
    finds it). For a record whose family ``ENDS_OVER_THE_SPOT`` and whose bottom lies ``DEEP`` below R
    (``Remembered.deep``): such a family moves only X, Y and Z, and every hole's moves from its cut to the
    bottom on are the same whatever the tool's level before the hole: its last move, which names the three
    axes (``axes``: the plane's two, then the normal), is over the hole's spot (``a``, ``b``: as the
    expansion's loop makes them, ``holes``) at the same level as the hole before.
    ``tests/test_cycle_repeat.py`` holds the answer to the walk over the moves."""
    first, second, normal = axes
    if before is None or len(before) != 3 or first not in before or second not in before \
            or before.get(normal) is None:
        return None
    moved = dict(before)
    moved[first] = a
    moved[second] = b
    return moved


def signature(state: ModalState) -> tuple[Any, ...]:
    """Everything of the state the resolver reads to resolve a next-hole block, but where the tool is: the
    active cycle (its record of modal words is replaced, never changed in place, so the same object means
    the same words), units, plane, distance mode, feed, spindle, return level, group-01 mode, the plane the
    cycle was commanded in and RS274's remembered tapping dwell; and what a rigid tap's pitch is worked out
    from (the rigid tapping mode, the spindle speed, the feed mode: ``postproc.cycles.rigid_tap``)."""
    active = state.cycle
    extra = state.extra
    return (active, None if active is None else active.kind, None if active is None else active.words,
            None if active is None else active.initial, state.units, state.plane, state.distance, state.feed,
            state.spindle, state.return_level, state.motion, extra.get(STATE_KEY), extra.get(DWELL_KEY),
            extra.get(RIGID_KEY), state.spindle_rpm, state.feed_mode)


def _next_hole_only(block: Block, plane: str) -> bool:
    """A block that only moves an active cycle to its next hole: position words on the plane's two axes
    (``X.. Y..`` in G17), at least one, maybe a block number and a comment."""
    values = block.values
    first, second, _ = PLANE_AXES[plane]
    size = len(values)
    if size == 1:
        if first not in values and second not in values:
            return False
    elif size != 2 or first not in values or second not in values:
        return False  # none (not cycle data: the resolver leaves it), or another letter
    sections = block.sections
    if len(sections) == 1 and "Motion" in sections:
        return True  # the commonest: the block syntax's Motion(None), a repeat of the active cycle
    for key in sections:
        if key not in _NEXT_HOLE_SECTIONS:
            return False
    return True
