"""End a Fagor fixed cycle with ``G80`` before any move outside it, never with a motion code.

Whether a ``G00``/``G01``/``G02``/``G03`` ends an active fixed cycle on the 8070, as a group-01 code does on
Fanuc (DIALECTS.md 2.1), is not confirmed [?: the 8070 programming manual's fixed-cycle pages were not
reached; the 8055 family's manual, found but its cycle chapter not read, lists the cycle as modal until
``G80`` or another cycle]. If it does not, every later block that moves runs the cycle again at its end
point: the machine drills where the source only moved. So the written program never relies on it:

* ``end_cycles_before_moves`` (a Fagor ``LOWERING`` step) puts a block of its own with a ``CycleCancel``
  (``G80``) before the first block after a native cycle (``Fagor.NATIVE_CYCLES``, still a ``CannedCycle``
  after the generic lowering) that moves outside it: a motion code with or without axes, a move in machine
  coordinates (``G53``), a reference return that moves, an expanded cycle (a ``CompoundMotion``). A block
  that cancels the cycle itself, calls a native cycle again or repeats it (a hole, a multiple machining
  pattern) needs none.
* A reference return leaves the source's cycle in force (Fanuc: group 00); after the ``G80`` written before
  it the written program has none, so a later hole of that cycle without its code would be a plain move
  there: it is refused by name (call the cycle again), where a re-call would also move the cycle's initial
  level to where the return left the tool.
* Reading Fagor (``FagorBlockSyntax``), a motion code while a cycle is active and without ``G80`` in its
  block is refused by name for the same reason.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Mapping

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir import Block, CycleCancel, Motion
from postproc.lowering.lower import BlockStep, LoweringStep

GROUP_01 = frozenset(("rapid", "linear", "cw", "ccw"))
"""Motion modes of the motion codes, which end a cycle on Fanuc and maybe not on the 8070 [?]."""
REFERENCE = frozenset(("home", "home2"))
"""Motion modes of a reference return (group 00: the source's cycle stays in force)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class EndCyclesBeforeMoves(LoweringStep):
    """The blocks, with a ``G80`` block before each move that follows a native cycle (the module docstring)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _CycleEnds(ctx)


end_cycles_before_moves = EndCyclesBeforeMoves()


@mypyc_attr(allow_interpreted_subclasses=True)
class _CycleEnds(BlockStep):
    """One run: a move is its business while a written cycle is in force or a ``G80`` was written before a
    reference return."""

    def __init__(self, ctx: Context) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.active = False
        """The written program has a native cycle in force."""
        self.kept_by_source = False
        """A ``G80`` was written before a reference return while the source's cycle stays in force."""

    def take(self, block: Block) -> list[Block] | None:
        made = self._take(block)
        self.moves = self.active or self.kept_by_source
        return made

    def _take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if "CycleCancel" in sections:
            self.active = self.kept_by_source = False
        elif "CannedCycle" in sections:
            cycle = sections["CannedCycle"]
            if self.kept_by_source and not getattr(cycle, "call", False):
                ctx = self.ctx
                ctx.diagnostics.error(UnsupportedError(
                    "a hole of a fixed cycle after a reference return: Fagor ends the cycle with G80 before the "
                    "return (whether a motion ends it on the 8070 is not confirmed), so the hole needs the "
                    "cycle called again", ctx.at(block)))
            self.active, self.kept_by_source = True, False
        elif self.active and _moves(sections):
            self.active = False
            motion = sections.get("Motion")
            self.kept_by_source = isinstance(motion, Motion) and motion.mode in REFERENCE \
                and "MachineCoordinates" not in sections
            return [_cancel(block), block]
        elif self.kept_by_source and _moves(sections):
            motion = sections.get("Motion")
            if not (isinstance(motion, Motion) and motion.mode in REFERENCE):
                self.kept_by_source = False  # (a motion code: the source's cycle ends here too)
        return None


def _moves(sections: Mapping[str, object]) -> bool:
    """Whether a block moves outside a cycle: its own hole (``CannedCycle``) and pattern (``HolePattern``)
    are the cycle's, a reference return of no axis moves nothing."""
    if "HolePattern" in sections or "CannedCycle" in sections:
        return False
    if "CompoundMotion" in sections or "MachineCoordinates" in sections:
        return True
    motion = sections.get("Motion")
    if not isinstance(motion, Motion):
        return False
    if motion.mode in REFERENCE:
        return bool(motion.axes)
    return motion.mode is not None or bool(motion.axes)


def _cancel(block: Block) -> Block:
    """A block of its own that ends the cycle, at the line of the move it comes before."""
    cancel = Block(block.line, None, "\n")
    cancel.add(CycleCancel())
    return cancel
