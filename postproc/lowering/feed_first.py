"""The ``check_blocks`` lowering step: ``translate`` refuses a feed move before any feed rate, at its line, as
the simulator does. The rule is ``postproc.block_rules``'s; the step lives with the lowering engine it runs in,
so the rules, which every reading imports, stay below that engine."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..block_rules import NO_FEED, needs_feed
from ..context import Context
from ..interp.control import ASSIGN, CONTROL
from ..dialect import Dialect
from ..errors import ProgramError
from ..ir import Block
from .lower import BlockStep, LoweringStep

_KEYS = frozenset(("Feed", "Motion", "CompoundMotion", CONTROL, ASSIGN))


@mypyc_attr(allow_interpreted_subclasses=True)
class CheckBlocks(LoweringStep):
    """Lowering step for ``translate``: a feed move before any feed rate is a located error (the
    simulator makes the same check itself). Once a feed rate is in force nothing is left to check: the
    step then looks at no block (``_UntilFed.done``, ``BlockStep.passes``)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _UntilFed(ctx)


check_blocks = CheckBlocks()


@mypyc_attr(allow_interpreted_subclasses=True)
class _UntilFed(BlockStep):
    """The blocks up to the first feed rate (or the first construct of a program that computes). A block
    that is only a move is looked at until then (a feed move in it needs a rate); after it, none."""

    def __init__(self, ctx: Context) -> None:
        super().__init__()
        self.ctx = ctx
        self.done = False
        """A feed rate (or a construct) went by: every block passes unlooked at."""

    def take(self, block: Block) -> list[Block] | None:
        if self.done:
            return None
        sections = block.sections
        if sections.keys().isdisjoint(_KEYS):
            return None
        if CONTROL in sections or ASSIGN in sections or "Feed" in sections:
            self._fed()  # from a construct on, execution order is no longer the text's
            return None
        ctx = self.ctx
        motion = sections.get("Motion")
        if motion is not None and needs_feed(motion):
            ctx.diagnostics.error(ProgramError(NO_FEED, ctx.at(block), needs="F"))
        compound = sections.get("CompoundMotion")
        if compound is not None:
            for item in compound.items:  # type: ignore[attr-defined]
                if item.KEY == "Feed":
                    self._fed()
                    return None
                if item.KEY == "Motion" and needs_feed(item):
                    ctx.diagnostics.error(ProgramError(NO_FEED, ctx.at(block), needs="F"))
                    break
        return None

    def _fed(self) -> None:
        self.done = True
        self.moves = False
        self.passes = True
