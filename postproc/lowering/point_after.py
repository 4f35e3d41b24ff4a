"""Where a block that is no plain move leaves the programmed point: one answer for the lowering steps that
follow the point (the cutter compensation resolver, ``cutter_point``; the tool length timing, ``length_timing``).

A plain move (G0-G3) is each step's own business, on its fast path. The other blocks that move the tool:

* a hole cycle the target keeps native (a ``CannedCycle`` whose ``CompoundMotion`` ``expand_canned_cycles``
  dropped: the call ``G81 X10. Y2. ...`` and each repeat ``X20.`` after it): it ends over its last hole at the
  level the cycle alone sets, ``CycleExpansion.end`` of the family expansion, which is what the reader moved
  its own point by (``CannedCycleResolveSyntax.install``). Issue 26: the resolver did not follow it, and a
  grblHAL start-up after a native ``G81 ... Y2.`` was computed from Y0 (2 mm wrong, exit 0);
* an expanded cycle (``CompoundMotion``): its moves, absolute in program units (each step walks them);
* a reference return (G28/G30) or a move in machine coordinates (G53): each axis it names ends at a machine
  position, not known here in work coordinates (``unknown_axes``); the axes it does not name stay;
* a lathe cycle kept native, and anything after which the program's text order is not its run order (a call,
  a jump, a loop: ``postproc.interp.control``): not known (``loses_after``); a jump's label: not known before
  its block.

Not known means a located error where a later step needs the point (a compensated start-up, a length change's
Z), never a guess.
"""

from __future__ import annotations

from typing import Callable, Final

from ..interp.control import CONTROL, LABEL, IfThen
from ..ir import CompoundMotion, Motion, Section
from ..ir.expr import Expr

MOVES: Final = frozenset(("rapid", "linear", "cw", "ccw"))
RETURNS: Final = frozenset(("home", "home2"))
"""Reference returns (G28, G30): through an intermediate point to a machine position."""
FOLLOWED: Final = frozenset(("CannedCycle", "LatheCycle", "MachineCoordinates", "CompoundMotion", CONTROL, LABEL))
"""Sections of a block that moves the tool other than as a plain move, or before or after which the point is
lost (``loses_after``, a ``LABEL``): a step that keeps a fast path for plain moves sends these blocks the
general way."""

HoleCycleEnd = Callable[[Section], dict[str, float] | None]
"""Where a hole cycle block (its ``CannedCycle`` section) leaves the tool; None where not known."""

_HOLE_CYCLE_ENDS: list[HoleCycleEnd] = []
"""Filled by the cycle engine when its package loads (``postproc.cycles.hole_ends``): the cycle engine's own
steps are lowering steps, so it stands above this package, which asks it through this hook instead of importing
it (an import would run back up the house)."""


def follow_hole_cycles(end: HoleCycleEnd) -> None:
    """The cycle engine tells where its hole cycles end (``postproc.cycles.hole_ends``, once)."""
    if end not in _HOLE_CYCLE_ENDS:
        _HOLE_CYCLE_ENDS.append(end)


def cycle_end(cycle: Section) -> dict[str, float] | None:
    """Where a hole cycle block leaves the tool, absolute, program units (``postproc.cycles.hole_ends``): the
    plane's axes and the drilling axis; None where not known (no cycle engine loaded: no such block was read)."""
    for end in _HOLE_CYCLE_ENDS:
        return end(cycle)
    return None


def compound_end(compound: CompoundMotion) -> dict[str, float | None] | None:
    """Where an expanded construct's moves (a cycle's: absolute, program units) leave the axes they move: each
    at its last move's number (None: computed); an axis they do not move stays where it was. None where the
    point is not known at all after them (a move other than G0-G3 among them). Found once a construct and
    kept on it (``CompoundMotion.end``): every step that follows the point asks it of every expanded hole
    (the cutter resolver, the tool length timing). The answer is shared: read it, never change it."""
    if compound.ended:
        return compound.end
    moved = _moves_end(compound.items)
    compound.end, compound.ended = moved, True
    return moved


def _moves_end(items: list[Section]) -> dict[str, float | None] | None:
    """``compound_end``'s walk over the items, from the last: an axis ends at the first number found for it
    (an expanded hole's moves name every axis each: a look-up, not a store, for all but the last move's). (A
    float word is tested as a float first: compiled, that is a type check, where ``isinstance(value, Expr)``
    of a float is a generic look-up of ``__class__``.)"""
    moved: dict[str, float | None] = {}
    for at in range(len(items) - 1, -1, -1):
        item = items[at]
        if not isinstance(item, Motion):
            continue
        if item.mode not in MOVES:
            return None
        for axis, value in item.axes.items():
            if axis in moved:
                continue
            if isinstance(value, float):
                moved[axis] = value
            else:
                moved[axis] = None if isinstance(value, Expr) else value
    return moved


def unknown_axes(motion: Motion) -> tuple[str, ...]:
    """The axes a reference return or a move in machine coordinates leaves at a point not known in work
    coordinates: those it names (a G28 without axis words moves none [K: the simulation makes no move of it])."""
    return tuple(motion.axes)


def loses_after(sections: dict[str, Section]) -> bool:
    """After this block the programmed point is not known here: a control statement (a call, a jump, a loop:
    what runs next is not the next block of the text), or a lathe cycle the target keeps native (no
    ``CompoundMotion``: where it ends is its controller's rules, not followed here). (A jump's label, ``LABEL``,
    loses the point *before* its block: the block's own move is followed.)"""
    control = sections.get(CONTROL)
    if control is not None and not isinstance(control, IfThen):  # (Fanuc's IF [..] THEN #1=..: an assignment)
        return True
    return "LatheCycle" in sections and "CompoundMotion" not in sections
