"""Cutter radius compensation resolved for a target without it (grbl): the compensated path, written
as plain moves. The lowering steps are here; the resolver they run is one state machine in three modules,
each with one job: ``cutter_point`` (its state and where the program stands), ``cutter_moves`` (the moves
into the compensation, the compensated blocks out) and ``cutter_resolver`` (the blocks, their settings,
the tried stretches and a copy's check).

The path is the simulation's (``cutter_radius.CutterRadius`` under the source dialect's rules,
``Dialect.CUTTER_RULES``), so it is the source controller's path move for move: each move of the
compensated stretch is rewritten to its compensated end (an arc to its compensated centre, in I/J
from the compensated start), an outside corner adds its arc (a rapid's: a straight traverse) in a
block of its own, and a block without motion keeps its place behind the move the compensation holds
back. The compensated stretch is written in absolute positions: a block the program wrote in G91 gets
a G90 and a G91 after it. A program that moves only by increments from where the tool stands (its
start point unknown: an incremental thread milling program) is compensated in a frame of its own, its
start point at zero, and its stretch written by increments (compensation moves with the path, so the
increments are the same wherever it starts); an absolute word on such an axis within the stretch is a
located error. A source whose rules are not modelled leaves its G41/G42 to the writer,
which refuses them.

What the simulation refuses under compensation (a canned cycle, a move in machine coordinates, a
reference return, a plane the rules do not compensate in, a start point not known, a tool change) is a located
error here too. The exit move in machine coordinates (``G40`` then ``G53 G0 Z0``) takes the plane's axes back
to the programmed point: they are written as its machine position from the set-up's ``<WorkOffsets>``
(``_exit_in_machine``). A copy within one dialect keeps its compensation, but its path is computed all the same
(``Resolver.check``), so the copy refuses what the simulation refuses. In the ZX plane (G18) the plane's points are (Z, X), as the simulation has them.

On a lathe (the ZX plane) the path is the imaginary tool tip's, as the simulation writes it: the nose
centre one nose radius beside the programmed path, moved by the radius in the tip's direction
(``<Tool tip>``, ``postproc.compensation.nose``). The lathe lowering has written X as a radius for a
target that is no lathe control (``postproc.cycles.lathe_lowering``), so the geometry is true. A lathe
target programmed in diameters (a Fanuc T stretch towards LinuxCNC in G7, whose rules differ) keeps X a
diameter in its blocks: the resolver halves it where it reads it and doubles it where it writes it; an
arc's I stays a radius [V: rs274 2.9, G7 G18 ``G2 X20 Z-5 I5 K0`` from X10 Z0 turns about X radius 10;
V: grblHAL core ``gcode.c`` (f80fc34), diameter mode halves the X word only, an arc's IJK untouched;
K: Fanuc T, I is a radius in either mode].

Inverse time (G93) under compensation: the controller runs each compensated move at F times the
length of the *programmed* move per minute, an outside corner's arc at the rate of the move after it
[V: rs274 2.9, LinuxCNC's tests/interp/inverse-time-with-comp]. Written as moves, G93 would time the
compensated length instead, so the resolved stretch is written per minute (G94 with those rates) and
G93 comes back with the first block after it.

Towards a target whose own modelled rules differ (Fanuc's and LinuxCNC's), each stretch from G41/G42 to
the move after G40 is held back and run under both rules (``rule_trial``): it keeps its G41/G42 where both
cut the same path, else it is written as the source's moves.

Compensation by a diameter in the program (LinuxCNC's G41.1/G42.1, ``DynamicCutterCompensation``) is
resolved the same way for every target but its source's own (``resolve_dynamic_cutter_compensation``):
no other dialect spells it, and a target with G41/G42 would need a register holding that radius, which
the set-up does not promise. The G41/G42 such a target writes itself pass untouched. A computed diameter
(``G41.1 D#100`` in a subprogram) keeps its block verbatim, which the target refuses: the program is
then flattened, each run's diameter a number.

A target whose own step resolves some of its G41/G42 (``resolution_unless``: an ISG-family target, whose D
brings a length, decides on the length in force after the tool length timing) has one resolver, that step's:
it resolves G41.1/G42.1 as well, and the generic step's run hands over to it (``TARGET_RESOLVES``).
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import RULES_UNKNOWN_KEY, Dialect
from ..errors import UnsupportedError
from ..ir import Block, CutterCompensation
from ..compensation.rules import CutterRules
from .cutter_resolver import Keeps, Resolution, Resolver, keep_native
from .lower import BlockStep, LoweringStep

RESOLVED = "cutter_compensation_resolved"
"""``Context.run_data`` key: the target for which ``resolve_dynamic_cutter_compensation`` resolves every G41/G42
as well (it keeps none and tries none), so the target's own ``resolve_cutter_compensation`` (grbl's, after
steps that leave compensation alone) finds nothing left and passes the blocks untouched: a second resolver
was ~1.5k instructions a block (``fanuc grbl 0``, compiled). After an error the first resolves nothing more, and
neither does the second now: a later G41/G42 is the target writer's refusal."""
TARGET_RESOLVES = "cutter_compensation_target_resolves"
"""``Context.run_data`` key: the target whose own lowering step resolves the compensation it cannot write, G41.1/G42.1
included (``resolution_unless``), set when that step starts, after the generic step started and before any block
runs: the generic step's run then passes every block from the first (``HandingOver``), one resolver following the
program instead of two (the second cost ~450 instructions a block, ``fanuc isg 0`` and ``fanuc fagor 0`` compiled)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ResolveCutterCompensation(LoweringStep):
    """Lowering step: G41/G42 become the compensated path for a target without cutter compensation,
    where the source dialect's rules are modelled (see the module docstring)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME or target.CUTTER_COMPENSATION:
            return None
        rules: CutterRules | None = ctx.cutter_rules  # none for a program written from the neutral IR
        if rules is None:
            why = ctx.run_data.get(RULES_UNKNOWN_KEY)
            return None if why is None else RefuseUnmodelled(ctx, target, str(why))
        if ctx.run_data.get(RESOLVED) is target:
            return None  # (the generic step already resolved every G41/G42 for this target)
        return Resolver(ctx, rules, diameters=_takes_diameters(ctx, target)).resolution()


resolve_cutter_compensation = ResolveCutterCompensation()


@mypyc_attr(allow_interpreted_subclasses=True)
class RefuseUnmodelled(BlockStep):
    """A G41/G42 from a source whose rules are not modelled, towards a target without compensation: a located
    error naming what is unknown (not that the target cannot express it: it is written as moves where the rules
    are known); the section goes, so the writer does not refuse it a second time."""

    def __init__(self, ctx: Context, target: type[Dialect], why: str) -> None:
        super().__init__()
        self.moves = False  # a block that is only a move has no CutterCompensation section
        self.ctx = ctx
        self.target = target
        self.why = why

    def take(self, block: Block) -> list[Block] | None:
        cc = block.sections.get("CutterCompensation")
        if isinstance(cc, CutterCompensation) and cc.mode != "off":
            self.ctx.diagnostics.error(UnsupportedError(
                f"cutter radius compensation ({cc.mode}) cannot be resolved into moves for {self.target.NAME}, "
                f"which has none: {self.why}", self.ctx.at(block)))
            del block.sections["CutterCompensation"]
            block.changed()
        return None


def _takes_diameters(ctx: Context, target: type[Dialect]) -> bool:
    """The blocks still hold X as a diameter (a lathe target programmed in diameters)."""
    return ctx.diameter and "lathe" in target.MACHINE_TYPES and target.DIAMETER_PROGRAMMING


@mypyc_attr(allow_interpreted_subclasses=True)
class ResolveDynamicCutterCompensation(LoweringStep):
    """Lowering step: G41.1/G42.1 (compensation by a diameter) become the compensated path for every
    target but the source's own dialect (see the module docstring); a G41/G42 by register is left to the
    target where it has cutter compensation, unless its modelled rules differ from the source's."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        rules: CutterRules | None = ctx.cutter_rules
        if rules is None:
            return None
        if ctx.dialect == target.NAME:
            return None if ctx.lathe else Resolver(ctx, rules, checking=True).checker()
        differ = _rules_differ(rules, target, ctx)
        keeps = keep_native if target.CUTTER_COMPENSATION and not differ else None
        trial = target.cutter_rules(ctx.setup) if target.CUTTER_COMPENSATION and differ else None
        if keeps is None and trial is None:
            ctx.run_data[RESOLVED] = target
        resolver = Resolver(ctx, rules, keeps, _takes_diameters(ctx, target), trial)
        return resolver.resolution() if keeps is None else HandingOver(resolver, target)


resolve_dynamic_cutter_compensation = ResolveDynamicCutterCompensation()


def _rules_differ(rules: CutterRules, target: type[Dialect], ctx: Context) -> bool:
    """The target compensates by rules of its own that are modelled and not the source's (NIST version 3's
    entry move and inside corners against LinuxCNC's, Fanuc's straight outer corners against LinuxCNC's
    arcs): its G41/G42 may cut another path, so each stretch is tried under both (``rule_trial``) and
    written as the source's compensated moves where the paths differ. Rules that differ only in their name
    (a Haas lathe's and Fanuc T's) are the same."""
    theirs: CutterRules | None = target.cutter_rules(ctx.setup)
    return theirs is not None and not theirs.cuts_like(rules)


@mypyc_attr(allow_interpreted_subclasses=True)
class HandingOver(Resolution):
    """The generic step's run towards a target that writes G41/G42 (``keep_native``): it resolves G41.1/G42.1, unless
    the target's own step resolves them with the rest (``TARGET_RESOLVES``, set before any block runs): then every
    block from the first passes it (``passes``), the other resolver's job."""

    def __init__(self, resolver: Resolver, target: type[Dialect]) -> None:
        super().__init__(resolver)
        self.target = target
        self.asked = False
        """``TARGET_RESOLVES`` was looked at (at the first block taken)."""

    def _handed_over(self) -> bool:
        self.asked = True
        if self.resolver.ctx.run_data.get(TARGET_RESOLVES) is not self.target:
            return False
        self.passes = True
        return True

    def take(self, block: Block) -> list[Block] | None:
        if not self.asked and self._handed_over():
            return None
        return self._take(block, False)

    def take_move(self, block: Block) -> list[Block] | None:
        if not self.asked and self._handed_over():
            return None
        return Resolution.take_move(self, block)


def resolution_unless(ctx: Context, target: type[Dialect], keeps: Keeps) -> BlockStep | None:
    """G41/G42 become the compensated path where ``keeps`` says the target cannot write them as they are (and the
    source's rules are modelled: else the target's own step decides), G41.1/G42.1 always; a lowering step's run
    (None: nothing to resolve), the one resolver of this translation, the generic step's handing over to it
    (``TARGET_RESOLVES``)."""
    rules: CutterRules | None = ctx.cutter_rules
    if rules is None:
        return None
    ctx.run_data[TARGET_RESOLVES] = target
    return Resolver(ctx, rules, keeps).resolution()
