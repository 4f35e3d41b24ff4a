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

from typing import Iterator, Mapping

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir import Block, CycleCancel, Motion

GROUP_01 = frozenset(("rapid", "linear", "cw", "ccw"))
"""Motion modes of the motion codes, which end a cycle on Fanuc and maybe not on the 8070 [?]."""
REFERENCE = frozenset(("home", "home2"))
"""Motion modes of a reference return (group 00: the source's cycle stays in force)."""


def end_cycles_before_moves(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """The blocks, with a ``G80`` block before each move that follows a native cycle (the module docstring)."""
    active = False
    """The written program has a native cycle in force."""
    kept_by_source = False
    """A ``G80`` was written before a reference return while the source's cycle stays in force."""
    for block in blocks:
        sections = block.sections
        if "CycleCancel" in sections:
            active = kept_by_source = False
        elif "CannedCycle" in sections:
            cycle = sections["CannedCycle"]
            if kept_by_source and not getattr(cycle, "call", False):
                ctx.diagnostics.error(UnsupportedError(
                    "a hole of a fixed cycle after a reference return: Fagor ends the cycle with G80 before the "
                    "return (whether a motion ends it on the 8070 is not confirmed), so the hole needs the "
                    "cycle called again", ctx.at(block)))
            active, kept_by_source = True, False
        elif active and _moves(sections):
            yield _cancel(block)
            active = False
            motion = sections.get("Motion")
            kept_by_source = isinstance(motion, Motion) and motion.mode in REFERENCE \
                and "MachineCoordinates" not in sections
        elif kept_by_source and _moves(sections):
            motion = sections.get("Motion")
            if not (isinstance(motion, Motion) and motion.mode in REFERENCE):
                kept_by_source = False  # (a motion code: the source's cycle ends here too)
        yield block


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
