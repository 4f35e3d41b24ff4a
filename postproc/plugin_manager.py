"""pluggy's plugin manager for the registry (``postproc.plugins``): the general path of calling the plugins' hooks.

Imported where a manager is made, not with ``postproc.plugins``: pluggy (with ``inspect``, which it imports) is
about a tenth of a one-line translation's start-up, and the command's process calls the installed plugins' hooks
through the fast lane (``postproc.fast.plugin_hooks``) where pluggy would call them plainly.
"""

from __future__ import annotations

import types
from typing import Iterable

import pluggy

from . import hookspecs
from .hookspecs import PROJECT


class PluginManager(pluggy.PluginManager):
    """pluggy's manager, with its scan of a module for hook implementations cut short where pluggy's answer is
    already known: pluggy looks up every name of a plugin module (each name it imports: ~400 over the
    installed plugins) with ``inspect.getattr_static``, ~1.5 ms of every start (pure build, cProfile). A
    module's names are its dictionary's (``dir``); a value that is not a function or method (a class, a
    module, a constant) is no implementation for pluggy, nor a plain function without the project's marker
    (pluggy's ``_get_marker_opts`` reads the same attribute). Everything else goes to pluggy as before
    (``parse_hookimpl_opts`` is pluggy's documented override point)."""

    def parse_hookimpl_opts(self, plugin: object, name: str) -> pluggy.HookimplOpts | None:
        if isinstance(plugin, types.ModuleType):
            value = vars(plugin).get(name)
            if not isinstance(value, _HOOKABLE):
                return None
            if isinstance(value, types.FunctionType) and getattr(value, _MARKER, None) is None:
                return None
        return super().parse_hookimpl_opts(plugin, name)


_HOOKABLE = (types.FunctionType, types.MethodType, staticmethod, classmethod)
"""What pluggy takes a hook implementation from (``pluggy._manager._static_hook_attr``)."""
_MARKER = PROJECT + "_impl"
"""The attribute ``hookimpl`` sets on what it marks (pluggy: the project name + ``_impl``)."""


def manager_of(plugins: Iterable[tuple[str, object]], extra: Iterable[object] = ()) -> pluggy.PluginManager:
    """A manager of the hook specifications with ``plugins`` registered by name, in order, then ``extra`` (by
    their canonical names), its pending hooks checked."""
    pm = PluginManager(PROJECT)
    pm.add_hookspecs(hookspecs)
    for name, plugin in plugins:
        pm.register(plugin, name=name)
    for plugin in extra:
        pm.register(plugin)
    pm.check_pending()
    return pm
