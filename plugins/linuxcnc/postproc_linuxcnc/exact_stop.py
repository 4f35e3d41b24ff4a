"""A one-shot exact stop (Fanuc ``G09``, ISG/Fagor ``G60``, SINUMERIK ``G9``) for LinuxCNC, which has none: rs274
refuses ``G9`` ("Unknown g code used" [V: /usr/bin/rs274]). The block is written in exact-stop mode (``G61``)
and the path mode in force before it follows on a line of its own (``G64`` with its tolerances, or ``G61``), so
the stop holds for that block only, as the source's does.

Where the program has set no path mode, the one after the block is cutting mode without tolerances (``G64``):
the mode both a Fanuc [K: 0i-F G code list, G64 is group 15's power-on state] and LinuxCNC [K: rs274ngc
``init``, ``CANON_CONTINUOUS``] start in, and the one the simulation takes back to after the source's one-shot
stop (``postproc.simulate.simulator``). Under an exact-stop mode the block already stops: the one-shot is left
out. In a program kept with its control flow (o-words), the mode in force at a block depends on the way the
run took: a one-shot there, with a path mode change anywhere in that flow, is a located error.
"""

from __future__ import annotations

from typing import Iterator

from postproc.context import Context
from postproc.control import CONTROL
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir import Block, PathControl

STOP = "exact_stop"


def exact_stop_for_one_block(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step: each one-shot exact stop as exact-stop mode for its block, then the mode before (the module
    docstring)."""
    before: PathControl | None = None
    """The path mode in force (None: never set, cutting)."""
    flow = False
    """A control statement was passed: the program keeps its control flow."""
    changed_in_flow = stopped_in_flow = False
    for block in blocks:
        sections = block.sections
        if CONTROL in sections:
            flow = True
        path = sections.get("PathControl")
        if not isinstance(path, PathControl):
            yield block
            continue
        if not path.one_shot:
            before = path
            changed_in_flow = changed_in_flow or flow
            if changed_in_flow and stopped_in_flow:
                _refuse(ctx, block)
            yield block
            continue
        stopped_in_flow = stopped_in_flow or flow
        if changed_in_flow and stopped_in_flow:
            _refuse(ctx, block)
        if before is not None and before.mode == STOP:  # the block stops already
            del sections["PathControl"]
            block.changed()
            if sections:
                yield block
            continue
        sections["PathControl"] = PathControl(STOP)
        block.changed()
        yield block
        after = Block(block.line, None, block.eol or "\n")
        after.add(PathControl("cutting") if before is None else
                  PathControl(before.mode, False, before.tolerance, before.naive))
        yield after


def _refuse(ctx: Context, block: Block) -> None:
    ctx.diagnostics.error(UnsupportedError(
        "a one-shot exact stop in a program whose path mode changes inside its control flow: LinuxCNC has no "
        "one-shot stop, and the mode to take back to after the block depends on the way the run takes",
        ctx.at(block)))
