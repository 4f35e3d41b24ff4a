"""Hook specifications. Every hook is prefixed ``postproc_``; plugins implement them with ``hookimpl``.

Built-in dialects register through these same hooks, from the same entry-point group (``postproc``),
as any third-party plugin.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

import pluggy

from .xmlio import XFactory

if TYPE_CHECKING:
    from .lower import Lowering

hookspec = pluggy.HookspecMarker("postproc")
hookimpl = pluggy.HookimplMarker("postproc")


@hookspec
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    """Register dialect classes by calling ``register(DialectClass)`` once per dialect."""


@hookspec
def postproc_register_xml(factory: XFactory) -> None:
    """Register the plugin's XML node classes (syntax objects, sections) with ``factory``
    by calling each class's idempotent ``reg(factory)``."""


@hookspec
def postproc_register_lowerings(register: Callable[["Lowering"], None]) -> None:
    """Register generic lowering steps by calling ``register(step)`` once per step, in the order they
    should run. A step is a pure block-stream transform ``step(blocks, ctx, target) -> blocks`` (see
    ``postproc.lower``) that applies to every translation and decides from the target dialect's
    capabilities whether it changes anything. A rewrite only one target needs belongs in that dialect's
    ``LOWERING`` instead."""
