"""What makes a block invalid whatever the target: one place for the simulator (``postproc.toolpath``)
and ``translate`` (the ``check_blocks`` lowering step), so ``translate``, ``toolpath`` and ``verify``
never disagree about the same block.

* A feed rate ``F`` or a spindle speed ``S`` cannot be negative.
* A feed move (straight or arc) with axis words or an arc centre needs a feed rate programmed before
  it, or in its block, even when it ends where it starts (a controller alarms on the command). In a program
  that computes (jumps, loops, subprograms) the order of the text is not the order of execution: from
  its first construct on, ``translate`` leaves this check to the run (``toolpath``, ``verify``).

The step is cheap on the hot path: a block with no feed, speed or motion costs one set test. Arc
geometry (an end point off the circle) needs the tool's position, which only the simulator tracks;
``translate`` does not check it yet.
"""

from __future__ import annotations

from typing import Iterator

from .context import Context
from .control import ASSIGN, CONTROL
from .dialect import Dialect
from .errors import ProgramError
from .ir import Block

NO_FEED = "a feed move with no feed rate (program F first)"
FEED_MOVES = frozenset(("linear", "cw", "ccw"))
"""Motion modes that move at the feed rate."""
_KEYS = frozenset(("Feed", "SpindleSpeed", "Motion", "CompoundMotion", CONTROL, ASSIGN))


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


def needs_feed(motion: object) -> bool:
    """True for a motion that commands a feed move: a feed mode with axis words or an arc centre."""
    return (getattr(motion, "mode", None) in FEED_MOVES
            and bool(getattr(motion, "axes", None) or getattr(motion, "center", None)))


def check_blocks(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step: report invalid blocks (see the module docstring) as located errors; every block
    passes on (the run fails at its end, as for any error)."""
    fed = False
    report = ctx.diagnostics.error
    for block in blocks:
        sections = block.sections
        if sections.keys().isdisjoint(_KEYS):
            yield block
            continue
        if CONTROL in sections or ASSIGN in sections:
            fed = True  # execution order is no longer the text's
        feed = sections.get("Feed")
        if feed is not None:
            problem = feed_problem(feed.value)  # type: ignore[attr-defined]
            if problem is not None:
                report(ProgramError(problem, ctx.at(block, ctx.column_of(block, "F"))))
            fed = True
        speed = sections.get("SpindleSpeed")
        if speed is not None:
            problem = speed_problem(speed.rpm)  # type: ignore[attr-defined]
            if problem is not None:
                report(ProgramError(problem, ctx.at(block, ctx.column_of(block, "S"))))
        motion = sections.get("Motion")
        if not fed and motion is not None and needs_feed(motion):
            report(ProgramError(NO_FEED, ctx.at(block)))
        compound = sections.get("CompoundMotion")
        if compound is not None:
            for item in compound.items:  # type: ignore[attr-defined]
                key = item.KEY
                if key == "Feed":
                    fed = True
                elif not fed and key == "Motion" and needs_feed(item):
                    report(ProgramError(NO_FEED, ctx.at(block)))
                    break
        yield block
