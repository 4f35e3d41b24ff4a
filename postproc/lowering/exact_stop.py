"""A one-shot exact stop for a target that has none (a lowering step its dialect names, with its words for
the refusal): the block is written in exact-stop mode and the path mode in force before it follows in a block
of its own (cutting with its tolerances, or exact stop), so the stop holds for that block only, as the
source's does.

Where the program has set no path mode, the one after the block is cutting mode without tolerances: the mode
the RS274 family's controls start in, and the one the simulation takes back to after the source's one-shot
stop (``postproc.simulate.simulator``). Under an exact-stop mode the block already stops: the one-shot is
left out. In a program kept with its control flow, the mode in force at a block depends on the way the run
took: a one-shot there, with a path mode change anywhere in that flow, is a located error.

In the core and compiled with the hot path because the step sees every block of a translation to its
dialect (a plugin's step runs interpreted).
"""

from __future__ import annotations

from typing import Final, Iterator

from ..context import Context
from ..control import CONTROL
from ..errors import UnsupportedError
from ..ir import Block, PathControl

STOP: Final = "exact_stop"


def exact_stop_for_one_block(blocks: Iterator[Block], ctx: Context, refusal: str) -> Iterator[Block]:
    """Each one-shot exact stop as exact-stop mode for its block, then the mode before (the module docstring);
    ``refusal``: the message of a one-shot stop whose mode to take back to depends on the way the run takes."""
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
                _refuse(ctx, block, refusal)
            yield block
            continue
        stopped_in_flow = stopped_in_flow or flow
        if changed_in_flow and stopped_in_flow:
            _refuse(ctx, block, refusal)
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


def _refuse(ctx: Context, block: Block, refusal: str) -> None:
    ctx.diagnostics.error(UnsupportedError(refusal, ctx.at(block)))
