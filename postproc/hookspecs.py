"""Hook specifications. Every hook is prefixed ``postproc_``; plugins implement them with ``hookimpl``.

Built-in dialects register through these same hooks, from the same entry-point group (``postproc``),
as any third-party plugin.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

import pluggy

from .xmlio import XFactory

if TYPE_CHECKING:
    from .lowering.lower import Lowering
    from .setup.machine_setup import SetupGroup

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
    ``postproc.lowering.lower``) that applies to every translation and decides from the target dialect's
    capabilities whether it changes anything. A rewrite only one target needs belongs in that dialect's
    ``LOWERING`` instead."""


@hookspec
def postproc_register_setup_groups(register: Callable[[type["SetupGroup"]], None]) -> None:
    """Register set-up groups by calling ``register(GroupClass)`` once per group: a subclass of
    ``postproc.setup.machine_setup.SetupGroup`` (a dataclass: fields with defaults, bounds by ``postproc.setup.machine_setup.setting``,
    camelCase attributes) whose ``TAG`` names its element. A set-up
    may then hold ``<TAG attr="..."/>``, validated, located in every error, inherited through ``extends``
    and written back by ``config dump``; the plugin reads it with ``setup.group(GroupClass)``. A tag the
    core or another plugin already uses is an error."""
