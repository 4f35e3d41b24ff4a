"""``LazyStep``: a lowering step imported where a translation first runs it.

Every installed dialect is registered at start-up, and its ``LOWERING`` names its steps: a step named by a
``LazyStep`` costs a run that does not lower for that target nothing (``tests/test_startup_imports.py``),
where an object imported at registration would load its module, and one wrapper class per step repeated the
same four lines in every dialect.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

from .lower import BlockStep, LoweringStep

if TYPE_CHECKING:
    from ..context import Context
    from ..dialect import Dialect


class LazyStep(LoweringStep):
    """``LazyStep("postproc_grblhal.cancels:cancel_cycles_alone")``: the ``LoweringStep`` at ``module:name`` (an
    absolute module, as an entry point spells it; a plugin writes ``f"{__name__}.cancels:..."``), imported at
    the first ``start`` and run as itself from then on. ``lathe_only``: the step does nothing on a mill (its own
    ``start`` gives None there), so a mill's translation does not import it at all."""

    __slots__ = ("target", "lathe_only", "_step")

    def __init__(self, target: str, lathe_only: bool = False) -> None:
        module, colon, name = target.partition(":")
        if not (module and colon and name) or module.startswith("."):
            raise ValueError(f"a lazy lowering step is 'package.module:name', not {target!r}")
        self.target = target
        self.lathe_only = lathe_only
        self._step: LoweringStep | None = None

    def step(self) -> LoweringStep:
        """The step itself (imported on the first call)."""
        step = self._step
        if step is None:
            module, _, name = self.target.partition(":")
            found = getattr(importlib.import_module(module), name)
            if not isinstance(found, LoweringStep):
                raise TypeError(f"{self.target} is not a lowering step (a LoweringStep object)")
            self._step = step = found
        return step

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if self.lathe_only and not ctx.lathe:
            return None
        return self.step().start(ctx, target)

    def __repr__(self) -> str:
        return f"LazyStep({self.target!r}{', lathe_only=True' if self.lathe_only else ''})"
