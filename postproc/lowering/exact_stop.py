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

from mypy_extensions import mypyc_attr
from typing import Final

from ..context import Context
from ..dialect import Dialect
from ..interp.control import CONTROL
from ..errors import UnsupportedError
from ..ir import Block, PathControl
from .lower import BlockStep, LoweringStep

STOP: Final = "exact_stop"


@mypyc_attr(allow_interpreted_subclasses=True)
class ExactStopForOneBlock(LoweringStep):
    """Each one-shot exact stop as exact-stop mode for its block, then the mode before (the module docstring);
    ``refusal``: the message of a one-shot stop whose mode to take back to depends on the way the run takes."""

    def __init__(self, refusal: str) -> None:
        self.refusal = refusal

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _OneShot(ctx, self.refusal)


@mypyc_attr(allow_interpreted_subclasses=True)
class _OneShot(BlockStep):
    """One run: only a block with a control statement or a path mode is its business."""

    def __init__(self, ctx: Context, refusal: str) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.refusal = refusal
        self.before: PathControl | None = None
        """The path mode in force (None: never set, cutting)."""
        self.flow = False
        """A control statement was passed: the program keeps its control flow."""
        self.changed_in_flow = False
        self.stopped_in_flow = False

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if CONTROL in sections:
            self.flow = True
        path = sections.get("PathControl")
        if not isinstance(path, PathControl):
            return None
        if not path.one_shot:
            self.before = path
            self.changed_in_flow = self.changed_in_flow or self.flow
            if self.changed_in_flow and self.stopped_in_flow:
                _refuse(self.ctx, block, self.refusal)
            return None
        self.stopped_in_flow = self.stopped_in_flow or self.flow
        if self.changed_in_flow and self.stopped_in_flow:
            _refuse(self.ctx, block, self.refusal)
        before = self.before
        if before is not None and before.mode == STOP:  # the block stops already
            del sections["PathControl"]
            block.changed()
            return None if sections else []
        sections["PathControl"] = PathControl(STOP)
        block.changed()
        after = Block(block.line, None, block.eol or "\n")
        after.add(PathControl("cutting") if before is None else
                  PathControl(before.mode, False, before.tolerance, before.naive))
        return [block, after]


def _refuse(ctx: Context, block: Block, refusal: str) -> None:
    ctx.diagnostics.error(UnsupportedError(refusal, ctx.at(block)))
