"""What makes a block invalid whatever the target: one place for the simulator (``postproc.simulate.toolpath``)
and ``translate``, so ``translate``, ``toolpath`` and ``verify`` never disagree about the same block.
A negative F or S is refused by the reading pipeline's modal-state step (every reading passes there);
a feed move with no feed rate by the simulator and, for ``translate``, the ``check_blocks`` lowering
step (``postproc.lowering.feed_first``), which looks only at the blocks before the first feed rate.

* A feed rate ``F`` or a spindle speed ``S`` cannot be negative.
* A feed move (straight or arc) with axis words or an arc centre needs a feed rate programmed before
  it, or in its block, even when it ends where it starts (a controller alarms on the command), and one
  above zero (``ZERO_FEED``: the modal-state step and the simulator check that). In a program that
  computes (jumps, loops, subprograms) the order of the text is not the order of execution: from its
  first construct on, ``translate`` leaves both checks to the run (``toolpath``, ``verify``).

* An arc's end point lies on its circle (I/J/K form, within the reading controller's rule,
  ``postproc.geometry.arc_end``, in the program's units), its R reaches the end point, and an R arc is no full circle (``arc_centre``): the simulator checks every arc; the reading
  pipeline's modal-state step checks every arc whose start it knows (``translate`` refuses it too).
"""

from __future__ import annotations

import math
from typing import Final

from mypy_extensions import mypyc_attr

from .context import Context
from .errors import ProgramError
from .geometry.arc_end import NEUTRAL_ARC_END, ArcEndRule
from .geometry.arc_end_math import rule_allows, rule_centre
from .geometry.arcs import PLACES, centre_from_radius
from .ir import Block

NO_FEED = "a feed move with no feed rate (program F first)"
ZERO_FEED = "a feed move at a zero feed rate (F0 is in force: program a feed rate above 0 first)"
"""Fanuc alarms (FEED ZERO), rs274 refuses ("Cannot do g1 with zero feed rate"), grbl too (error 22)."""
FEED_MOVES = frozenset(("linear", "cw", "ccw"))
"""Motion modes that move at the feed rate."""


def feed_problem(value: object) -> str | None:
    """Why a programmed feed rate is invalid (None: it is valid, or only known at run time)."""
    if isinstance(value, (int, float)) and value < 0:
        return f"feed rate F{value:g} cannot be negative"
    return None


def speed_problem(rpm: object) -> str | None:
    """Why a programmed spindle speed is invalid (None: it is valid, or only known at run time)."""
    if isinstance(rpm, (int, float)) and rpm < 0:
        return f"spindle speed S{rpm:g} cannot be negative"
    return None


def per_rev_problem(turning: str, rpm: object) -> str | None:
    """Why a feed move in feed per revolution cannot run with the spindle ``turning`` ('cw', 'ccw',
    'stop') at ``rpm`` (None: unknown, an Expr: known at run time), or None. The axes would wait for
    revolutions that never come: a Fanuc waits forever [K]; rs274 refuses the block ("Cannot feed with zero
    spindle speed in feed per rev mode") [V]."""
    if turning == "stop":
        return ("a feed-per-revolution move with the spindle stopped: the axes would wait for revolutions that "
                "never come (start the spindle first, or feed per minute)")
    if isinstance(rpm, (int, float)) and rpm == 0:
        return ("a feed-per-revolution move at spindle speed S0: the axes would wait for revolutions that never "
                "come (program a speed above 0 first, or feed per minute)")
    return None


def needs_feed(motion: object) -> bool:
    """True for a motion that commands a feed move: a feed mode with axis words or an arc centre."""
    return (getattr(motion, "mode", None) in FEED_MOVES
            and bool(getattr(motion, "axes", None) or getattr(motion, "center", None)))


def check_values(block: Block, ctx: Context) -> None:
    """Raise a located error for a negative F or S in ``block`` (the reading pipeline's modal-state step
    calls it for every block with either)."""
    sections = block.sections
    feed = sections.get("Feed")
    if feed is not None:
        problem = feed_problem(feed.value)  # type: ignore[attr-defined]
        if problem is not None:
            raise ProgramError(problem, ctx.at(block, ctx.column_of(block, "F")))
    speed = sections.get("SpindleSpeed")
    if speed is not None:
        problem = speed_problem(speed.rpm)  # type: ignore[attr-defined]
        if problem is not None:
            raise ProgramError(problem, ctx.at(block, ctx.column_of(block, "S")))


@mypyc_attr(allow_interpreted_subclasses=True)
class ArcError(ProgramError):
    """An arc no controller runs; ``letter`` is the word to point at (``R``, ``I``/``J``/``K`` or ``G``)."""

    def __init__(self, message: str, letter: str) -> None:
        super().__init__(message)
        self.letter = letter


_CENTRE_LETTERS = {"X": "I", "Y": "J", "Z": "K"}
_SMALLEST_RADIUS: Final = 10.0 ** -PLACES
"""A radius below this is none (``arc_centre``): computed once (compiled, the power was a call an arc)."""


def arc_centre(s: tuple[float, float], e: tuple[float, float], axes: tuple[str, str], radius: float | None,
               offsets: dict[str, float], clockwise: bool, rule: ArcEndRule = NEUTRAL_ARC_END,
               inch: bool = False, unit: float = 1.0) -> tuple[float, float] | None:
    """The centre a controller turns an arc from ``s`` to ``e`` about, in mm (plane axes ``axes``), from its R
    or its centre offsets (mm); None for a zero-radius arc that does not move (a controller runs it as nothing).
    An I/J/K arc's end may lie off its circle as far as the controller's ``rule`` allows in the program's
    units (``inch``: an inch program; ``unit``: one program unit in the numbers given, 25.4 where they are
    mm of an inch program), and the centre is then the one the rule says the controller runs. Raises ``ArcError`` for an arc no controller runs."""
    if radius is not None:
        try:
            return centre_from_radius(s, e, radius, clockwise)
        except ProgramError as err:
            raise ArcError(err.message, "R") from None
    a1, a2 = axes
    c = (s[0] + offsets.get(a1, 0.0), s[1] + offsets.get(a2, 0.0))
    r0 = math.hypot(s[0] - c[0], s[1] - c[1])
    r1 = math.hypot(e[0] - c[0], e[1] - c[1])
    chord = math.hypot(e[0] - s[0], e[1] - s[1]) / unit
    if not rule_allows(rule, r0 / unit, r1 / unit, inch, chord):  # (``rule.allows``, ``rule.centre``: called compiled,
        # not through the interpreted record's methods, ~500 instructions each an arc)
        letter = next((_CENTRE_LETTERS[a] for a in offsets if a in _CENTRE_LETTERS), "G")  # (only for the error)
        limit = rule.limit(r0 / unit, r1 / unit, inch, chord)
        accepts = "a move of the centre" if rule.of_centre_shift else "a difference"
        raise ArcError(f"arc end point is not on the circle: radius {r0:.4f} mm at the start, "
                       f"{r1:.4f} mm at the end (the controller accepts {accepts} up to "
                       f"{limit:.6g} {'in' if inch else 'mm'} here)", letter)
    if r0 < _SMALLEST_RADIUS:
        if round(e[0], PLACES) == round(s[0], PLACES) and round(e[1], PLACES) == round(s[1], PLACES):
            return None
        raise ArcError("arc centre coincides with its start point", "G")
    return rule_centre(rule, s, e, c)
