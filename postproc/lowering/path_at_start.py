"""The exact mode a program starts in, carried to a target that powers on blending (a lowering step).

A program that moves before it programs a path control mode runs in its controller's power-on mode
(``Dialect.PATH_CONTROL_AT_START``: G64 on Fanuc and LinuxCNC [K], G60 on a SINUMERIK as its machine data is
delivered [K], the exact path G61 on grbl and grblHAL [V: ``gcode.h``]). A SINUMERIK or grbl program written for a
controller that starts blending would have its corners blended there: so the source's mode is written before the
first block that moves (the exact path as the target's exact path code, or its exact stop where it has none:
``WordWriter.path_control_words``), unless the program sets a mode itself before it (then that one is in force at
the first move on both). It goes in the block of that move (a block of its own before it where that block has a
one-shot exact stop already).

Towards a lathe whose code table has no modal path code (``Dialect.LATHE_PATH_CONTROL``: Fanuc T, GSK [?]) the
power-on mode is not written, with a warning: the program never asked for it (it is the source controller's only
mode on grbl), the target cannot say it, and refusing it would refuse every such program; ``verify`` still lists
the difference (the source's mode, recorded at its first move, against none).

The other way (a Fanuc program for a SINUMERIK) nothing is written: the target then runs exact stops where the
source blended, which reach every programmed point (blending only lets the path leave them), and ``verify``
accepts it with a note (``postproc.simulate.verify``), as it does grbl's one exact path mode. Nothing changes
between two dialects that start alike, and a same-dialect copy passes untouched.
"""

from __future__ import annotations

from typing import Final, Iterator

from ..context import Context
from ..dialect import Dialect
from ..ir import Block, PathControl

MOVING: Final = frozenset(("Motion", "CompoundMotion", "CycleCall", "CannedCycle", "HolePattern", "RigidTap"))
"""Sections of a block that may move the tool."""
EXACT: Final = frozenset(("exact_stop", "exact_path"))
"""The modes that reach every programmed point (``PathControl``)."""


def carry_path_at_start(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step: see the module docstring."""
    if ctx.dialect == target.NAME or ctx.path_at_start not in EXACT or target.PATH_CONTROL_AT_START in EXACT:
        return blocks
    if not target.LATHE_PATH_CONTROL and target.reads_lathe(ctx.setup):  # (the target writes a lathe program)
        return _unwritten(blocks, ctx, target)
    return _carry(blocks, ctx.path_at_start)


def _carry(blocks: Iterator[Block], mode: str) -> Iterator[Block]:
    for block in blocks:
        sections = block.sections
        path = sections.get("PathControl")
        if isinstance(path, PathControl) and not path.one_shot:
            yield block  # the program sets its mode before it moves: nothing to carry
            yield from blocks
            return
        if not MOVING.isdisjoint(sections):
            if "PathControl" in sections:  # a one-shot exact stop there: the mode goes in a block before
                first = Block(block.line, None, "\n")
                first.add(PathControl(mode))
                yield first
            else:
                block.add(PathControl(mode))  # the mode in the block of the first move (``G61 G00 X..``)
            yield block
            yield from blocks
            return
        yield block


def _unwritten(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """The blocks as they are, and a warning at the first move where the program set no mode before it."""
    for block in blocks:
        sections = block.sections
        path = sections.get("PathControl")
        if isinstance(path, PathControl) and not path.one_shot:
            yield block
            yield from blocks
            return
        if not MOVING.isdisjoint(sections):
            mode = ctx.path_at_start.replace("_", " ")
            ctx.diagnostics.warn(
                f"the {ctx.dialect} controller runs this program in the {mode} mode from power-on; a {target.NAME} "
                "lathe has no path control code here [?]: not written, the lathe runs in its own mode", ctx.at(block))
            yield block
            yield from blocks
            return
        yield block
