"""Generic lowering steps whose work is imported when a translation first runs them: registered at every
start (``core_plugin``) and named by the simulation (``simulate.toolpath.TRANSLATE_ONLY``), they keep
their modules out of a start that never translates."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .lower import BlockStep, LoweringStep

if TYPE_CHECKING:
    from ..context import Context
    from ..dialect import Dialect


class ResolveDynamicCutterCompensation(LoweringStep):
    """``cutter_compensation.resolve_dynamic_cutter_compensation`` (a translation's only: the simulation
    applies G41.1/G42.1 itself, keeping the programmed point beside the controlled one)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from .cutter_compensation import resolve_dynamic_cutter_compensation as step
        return step.start(ctx, target)


resolve_dynamic_cutter_compensation = ResolveDynamicCutterCompensation()
