"""The plugin-hook lane (``install``): the installed plugins' hooks called as pluggy calls them, without pluggy.

Every run calls each registry hook of every installed plugin once (``postproc.plugins.Registry``); pluggy's manager
does that, and importing it (with ``inspect``, ``ast`` and ``dis``, which it imports) and registering the plugins
through it cost a one-line translation about a tenth of its start-up instructions (callgrind). Where every plugin
is a module whose hook implementations are plain functions with pluggy's default options, named as the hooks
they implement, taking some of the hook's arguments (nothing for pluggy to order, wrap, rename or refuse), pluggy
calls each hook's implementations one after the other, the last registered first, each with the arguments it
names, and keeps what they return that is not None: ``PlainHooks`` does that. Anything else (a plugin object that
is not a module, a module with its own ``__dir__``, an option, a hook wrapper, a misspelt hook, an argument the
hook does not give, a function wrapped by a decorator, a hook specification with an option) gives None, and the
registry makes pluggy's manager (``postproc.plugins.HOOKS_LANE``). ``tests/test_plugin_hooks.py`` holds the lane's
calls to pluggy's on random plugins.
"""

from __future__ import annotations

import types
from typing import Any, Callable

from .. import hookspecs, plugins
from ..hookspecs import PROJECT

_SPEC = PROJECT + "_spec"
_IMPL = PROJECT + "_impl"
_PLAIN_SPEC = {"firstresult": False, "historic": False, "warn_on_impl": None, "warn_on_impl_args": None}
"""A hook specification's options where pluggy calls its implementations plainly."""
_PLAIN_IMPL = {"wrapper": False, "hookwrapper": False, "optionalhook": False, "tryfirst": False, "trylast": False,
               "specname": None}
"""A hook implementation's options where pluggy calls it plainly, in registration order."""
_HOOKABLE = (types.FunctionType, types.MethodType, staticmethod, classmethod)
"""What pluggy takes a hook implementation from (``postproc.plugin_manager.PluginManager``)."""

Implementation = tuple[Callable[..., Any], tuple[str, ...]]
"""A hook implementation and the names of the arguments it takes, in order."""


class _Relay:
    """``hook.NAME(**arguments)``: each hook a function calling its implementations."""

    def __init__(self, implementations: dict[str, list[Implementation]]) -> None:
        for name, found in implementations.items():
            setattr(self, name, _caller(list(reversed(found))))


def _caller(order: list[Implementation]) -> Callable[..., list[Any]]:
    def call(**arguments: Any) -> list[Any]:
        results = []
        for function, names in order:
            result = function(*[arguments[name] for name in names])
            if result is not None:
                results.append(result)
        return results

    return call


class PlainHooks:
    """The hooks of plugins pluggy would call plainly (see the module), as the registry calls them."""

    def __init__(self, implementations: dict[str, list[Implementation]]) -> None:
        self.hook = _Relay(implementations)


def plain_hooks(found: plugins.Plugins) -> PlainHooks | None:
    """``found``'s hooks (registered by name, in order) called as pluggy would call them, or None where pluggy
    may do anything else (see the module)."""
    specs = _plain_specs()
    if specs is None:
        return None
    implementations: dict[str, list[Implementation]] = {name: [] for name in specs}
    seen: list[object] = []
    for _, plugin in found:
        if not isinstance(plugin, types.ModuleType) or "__dir__" in vars(plugin) or \
                any(plugin is other for other in seen):
            return None
        seen.append(plugin)
        for name, value in vars(plugin).items():
            if not isinstance(value, _HOOKABLE):
                continue
            if not isinstance(value, types.FunctionType):
                return None  # (a method or static method of a module: pluggy's to judge)
            opts = getattr(value, _IMPL, None)
            if opts is None:
                continue
            names = _plain_arguments(value)
            if opts != _PLAIN_IMPL or name not in specs or names is None or not set(names) <= specs[name]:
                return None
            implementations[name].append((value, names))
    return PlainHooks(implementations)


def _plain_specs() -> dict[str, set[str]] | None:
    """The hooks of ``postproc.hookspecs`` by name, with their arguments' names, if every one is plain."""
    specs: dict[str, set[str]] = {}
    for name, value in vars(hookspecs).items():
        opts = getattr(value, _SPEC, None)
        if opts is None:
            continue
        names = _plain_arguments(value) if isinstance(value, types.FunctionType) else None
        if opts != _PLAIN_SPEC or names is None:
            return None
        specs[name] = set(names)
    return specs


def _plain_arguments(function: types.FunctionType) -> tuple[str, ...] | None:
    """The names of a module-level function's arguments, if they are all positional ones without defaults (what
    pluggy's ``varnames`` then gives), else None."""
    code = function.__code__
    if function.__defaults__ or function.__kwdefaults__ or code.co_kwonlyargcount or code.co_posonlyargcount or \
            "." in function.__qualname__ or hasattr(function, "__wrapped__"):
        return None
    return code.co_varnames[:code.co_argcount]


def install() -> None:
    """Let the registry call the installed plugins' hooks through the lane (``postproc.plugins.HOOKS_LANE``)."""
    plugins.HOOKS_LANE = plain_hooks
