"""expand_canned_cycles: keep a hole cycle native where the target runs it, else write its motion.

A cycle is expanded when the target does not run its kind natively, when the set-up asks for it
(``<Cycles expand="drill,back_bore"/>`` or ``"all"``), or when the target's controller moves through
its native cycles by other rules (``CYCLE_SEMANTICS`` on the dialect, judged per block by ``Dialect.moves_like``; one
that names none has every cycle expanded), or, for G73
and G83, with another retract or clearance than the program was read with (``PECK_CLEARANCE_MM``,
else the set-up's ``<Cycles peckRetract peckClearance>``: LinuxCNC's fixed 0.254 mm against a Mach3
machine's 0.5): the expansion is exact, the native cycle there would not be. Once a block of a cycle is expanded, the
rest of that cycle (up to its cancel) is expanded too: the expansion's own G00/G01 have cancelled the
cycle on the target, so a later native repeat would no longer drill there.

An expanded block loses its ``CannedCycle`` and is marked changed, so the writer writes its
``CompoundMotion`` with a comment naming the source line; a native block loses its
``CompoundMotion``, so nothing is written twice.

An expansion is the motion of one run: the reader resolved the cycle from the state where the block
stands in the text. In a program kept symbolically that is exact only in straight code: from the first
control statement or label on (a subprogram body called with ``L`` repeats, a loop, a jump target) a
block runs where the control flow takes it, with the caller's position, and a baked expansion would
drill one call's holes for every call (issue 26: LinuxCNC ``M98 P1 L3`` around ``G91 X1`` + ``G81``
gave Fanuc the first call's hole three times, 2 mm off). Such a cycle is a located error, which makes
the keep check (``postproc.api``) flatten the program (each run's cycle expanded where it runs); an
executed block (flattened) has no control statements and is exact.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Final

from postproc.dialect import Dialect
from postproc.errors import PostprocError, UnsupportedError
from postproc.ir import (
    Block, Comments, CompoundMotion, Motion, ProgramControl, Section, SpindleControl, SpindleOrientation, one_line,
)
from postproc.context import DROPPED_MOVES, Context
from postproc.interp.control import CONTROL, LABEL
from postproc.ir.source_map import ExecutedBlock

from postproc.lowering.synchronised_tap import RigidTap

from .resolve import peck_clearance_mm
from .section import CannedCycle
from ..lowering.lower import BlockStep, LoweringStep
from .semantics import PECK

_CANCELS: Final = frozenset(("rapid", "linear", "cw", "ccw"))


@mypyc_attr(allow_interpreted_subclasses=True)
class ExpandCannedCycles(LoweringStep):
    """Lowering transform (see the module docstring). Back to its own dialect with nothing forced, every
    cycle stays native and blocks are copied or rewritten from their words: the stream passes through."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if target.NAME == ctx.dialect and not ctx.setup.cycles.expanded():
            return None
        return _Expand(ctx, target)


expand_canned_cycles = ExpandCannedCycles()


def expands(cycle: CannedCycle, ctx: Context, target: type[Dialect]) -> bool:
    """True when ``target`` gets this block of ``cycle`` as motion whatever came before it (the module
    docstring's reasons; a later block of an expanded cycle is expanded too, see ``cancels``). A hole
    pattern that repeats the cycle asks the same question (``expand_hole_patterns``)."""
    forced = ctx.setup.cycles.expanded()
    if target.NAME == ctx.dialect and not forced:
        return False
    return "all" in forced or cycle.expand or cycle.kind in forced or cycle.kind not in target.NATIVE_CYCLES \
        or not target.moves_like(cycle) or cycle.kind in _other_clearances(ctx, target)


def cancels(sections: dict[str, Section]) -> bool:
    """True when a block without a cycle ends the active one (G80, or a motion code)."""
    return "CycleCancel" in sections or getattr(sections.get("Motion"), "mode", None) in _CANCELS


@mypyc_attr(allow_interpreted_subclasses=True)
class _Expand(BlockStep):
    """One run: a block that is only a move is its business while a cycle is expanded (it may cancel it)."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.target = target
        self.cycles = ctx.setup.cycles
        self.can_orient = target.SPINDLE_ORIENTATION
        self.expanding = False  # from the first expanded block of a cycle to its cancel
        self.flowing = False  # a control statement or label has passed: the state is the text's, not each run's
        self.repeated: UnsupportedError | None = None  # in a dry run, the first expansion's (a later jump may repeat it)
        self.dry = bool(ctx.run_data.get("dry_run"))

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        ctx = self.ctx
        cycle = sections.get("CannedCycle")
        if cycle is None:
            if self.expanding and cancels(sections):
                self.expanding = self.moves = False
            if not self.flowing and (CONTROL in sections or LABEL in sections) and not isinstance(block, ExecutedBlock):
                self.flowing = True
                if self.repeated is not None:
                    ctx.diagnostics.error(self.repeated)
            return None
        if not isinstance(cycle, CannedCycle):
            return None
        self.expanding = self.moves = self.expanding or expands(cycle, ctx, self.target)
        if not self.expanding:
            sections.pop("CompoundMotion", None)
            return None
        if self.flowing:
            ctx.diagnostics.error(_run_dependent(block, ctx))
            return []
        if self.repeated is None and self.dry:
            self.repeated = _run_dependent(block, ctx)
        del sections["CannedCycle"]
        block.changed()
        compound = sections.get("CompoundMotion")
        if isinstance(compound, CompoundMotion):
            try:
                made = compound.items  # a lazy expansion is made here, and refused here (e.g. too many moves)
            except PostprocError as err:
                ctx.diagnostics.error(err)
                return []
            del made
            _restore_motion_mode(compound, cycle.motion)
            if not self.can_orient and _orients(compound) and not _handle_orientation(
                    block, compound, ctx, self.cycles.orientation, self.target,
                    one_line(block.text or _source(block)).strip()):
                return []
        return None


def _run_dependent(block: Block, ctx: Context) -> UnsupportedError:
    """The error of an expansion in a program kept symbolically whose control flow may run it elsewhere."""
    source = one_line(block.text or _source(block)).strip()
    return UnsupportedError(f"the cycle in '{source}' would be written as the moves of one run, but the "
                            "program's control flow (a subprogram, a loop or a jump) runs it from other "
                            "positions", ctx.at(block))


def _other_clearances(ctx: Context, target: type[Dialect]) -> frozenset[str]:
    """The peck cycles whose retract or clearance on ``target`` differs from the one the program was read
    with (both in mm, from the dialects' fixed values or the set-up), decided once per translation."""
    cycles = ctx.setup.cycles
    return frozenset(kind for kind in PECK
                     if abs(peck_clearance_mm(kind, ctx.peck_clearance_mm, cycles)
                            - peck_clearance_mm(kind, target.PECK_CLEARANCE_MM, cycles)) > 1e-9)


def _restore_motion_mode(compound: CompoundMotion, mode: str | None) -> None:
    """End the expansion in the group-01 mode the program had, so a plain move after G80 keeps it (a rigid
    tap's synchronised move is a motion mode of its own on a target that writes it)."""
    items = compound.items
    last: Motion | RigidTap | None = None
    for at in range(len(items) - 1, -1, -1):  # (from the end; compiled, a generator's ``next`` cost ~250 a hole)
        item = items[at]
        if isinstance(item, (Motion, RigidTap)):
            last = item
            break
    if last is not None and mode in ("rapid", "linear") and (isinstance(last, RigidTap) or last.mode != mode):
        compound.items.append(Motion(mode, {}))


def _orients(compound: CompoundMotion) -> bool:
    """(A loop: compiled, ``any`` over a generator cost ~800 instructions an expanded hole, towards grbl.)"""
    for item in compound.items:
        if isinstance(item, SpindleOrientation):
            return True
    return False


def _handle_orientation(block: Block, compound: CompoundMotion, ctx: Context, mode: str,
                        target: type[Dialect], source: str) -> bool:
    """Apply ``<Cycles orientation=...>`` to an expansion for a target without oriented stops.
    Returns False when the block must not be written (an error was reported)."""
    if mode == "m19":
        return True
    if mode == "stop":
        items: list[Section] = []
        for item in compound.items:
            if isinstance(item, SpindleOrientation):
                items.append(SpindleControl("stop"))  # a program stop alone may leave the spindle turning
                items.append(Comments([f"orient the spindle to {item.angle:g} deg by hand, then cycle start"]))
                items.append(ProgramControl("stop"))
            else:
                items.append(item)
        compound.items = items
        return True
    code = ctx.cycle_words.name(compound.term) if ctx.cycle_words is not None else compound.term
    err = UnsupportedError(f"{code} needs an oriented spindle stop, which the {target.NAME} dialect cannot "
                           f"make (set <Cycles orientation=\"stop\"/> or \"m19\")", ctx.at(block))
    if ctx.on_unsupported == "warn":
        ctx.diagnostics.warn(err.message + "; written as a comment", err.location)
        ctx.run_data.setdefault(DROPPED_MOVES, []).append(block.line)  # its holes' moves: the writer's to judge
        block.sections = {"Comments": Comments([f"UNSUPPORTED LINE {block.line}: {source}"])}
        return True
    ctx.diagnostics.error(err)
    return False


def _source(block: Block) -> str:
    return " ".join(letter + num for letter, num in block.words)
