"""Hook specifications. Every hook is prefixed ``postproc_``; plugins implement them with ``hookimpl``.

Built-in dialects register through these same hooks, from the same entry-point group (``postproc``),
as any third-party plugin.
"""

from __future__ import annotations

from typing import Callable

import pluggy

from .xmlio import XFactory

hookspec = pluggy.HookspecMarker("postproc")
hookimpl = pluggy.HookimplMarker("postproc")


@hookspec
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    """Register dialect classes by calling ``register(DialectClass)`` once per dialect."""


@hookspec
def postproc_register_xml(factory: XFactory) -> None:
    """Register the plugin's XML node classes (syntax objects, sections) with ``factory``
    by calling each class's idempotent ``reg(factory)``."""
