"""The plugin manager: loads the ``postproc`` entry points lazily and collects dialects.

Nothing here names a concrete dialect; built-ins arrive through their entry points like any plugin.
"""

from __future__ import annotations

import functools
import types
from typing import Iterable

import pluggy

from . import native
native.install()  # the compiled hot path, before any of its modules is imported

from . import hookspecs
from .collector import gc_paused
from .interp.control import register_control
from .dialect import Dialect
from .entry_points import entry_points as installed_entry_points
from .entry_points import load as load_entry_point
from .errors import UsageError
from .ir.expr import register_expressions
from .ir import register_sections
from .lowering.lower import Lowering, register_transform
from .setup.machine_setup import SetupGroup, builtin_groups
from .xmlio import DEFAULT, XFactory

RESERVED_SETUP_TAGS = frozenset(("Templates", "Library", "MachineCodes", "CodeCall", "Axes", "WorkOffsets", "Tools"))
"""Set-up elements that are not groups: no plugin group may take their names."""

PROJECT = "postproc"


def collect_dialects(pm: pluggy.PluginManager) -> dict[str, type[Dialect]]:
    """Name -> dialect class, from every plugin's ``postproc_register_dialects``: each a named ``Dialect``,
    no name given to two classes."""
    dialects: dict[str, type[Dialect]] = {}

    def register(cls: type) -> None:
        if not (isinstance(cls, type) and issubclass(cls, Dialect) and cls.NAME):
            raise TypeError(f"{cls!r} is not a named postproc Dialect")
        known = dialects.get(cls.NAME)
        if known is not None and known is not cls:
            raise TypeError(f"dialect {cls.NAME!r} registered twice ({known.__module__}, {cls.__module__})")
        dialects[cls.NAME] = cls

    pm.hook.postproc_register_dialects(register=register)
    return dialects


class Registry:
    """Dialects and XML node classes contributed by the loaded plugins."""

    def __init__(self, pm: pluggy.PluginManager, factory: XFactory) -> None:
        self.pm = pm
        self.factory = factory
        self.lowerings: list[Lowering] = []
        """Generic lowering steps, in registration order (``postproc_register_lowerings``)."""
        self.setup_groups: dict[str, type[SetupGroup]] = builtin_groups()
        """Element name -> set-up group class: the built-in groups, then the plugins' (``postproc_register_setup_groups``)."""
        self.dialects = collect_dialects(pm)
        pm.hook.postproc_register_xml(factory=factory)
        pm.hook.postproc_register_lowerings(register=self._register_lowering)
        pm.hook.postproc_register_setup_groups(register=self._register_setup_group)

    def _register_lowering(self, step: Lowering) -> None:
        if not callable(step):
            raise TypeError(f"{step!r} is not a lowering step")
        if step not in self.lowerings:
            self.lowerings.append(step)

    def _register_setup_group(self, cls: type[SetupGroup]) -> None:
        if not (isinstance(cls, type) and issubclass(cls, SetupGroup) and cls.TAG):
            raise TypeError(f"{cls!r} is not a postproc SetupGroup with a TAG")
        known = self.setup_groups.get(cls.TAG)
        if known is cls:
            return
        if known is not None or cls.TAG in RESERVED_SETUP_TAGS:
            raise TypeError(f"set-up element <{cls.TAG}> registered twice ({cls.__module__}.{cls.__name__})")
        self.setup_groups[cls.TAG] = cls

    def dialect(self, name: str) -> type[Dialect]:
        try:
            return self.dialects[name]
        except KeyError:
            known = ", ".join(sorted(self.dialects)) or "none"
            raise UsageError(f"unknown dialect {name!r} (installed: {known})") from None


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


def make_plugin_manager(extra: Iterable[object] = (), entry_points: bool = True) -> pluggy.PluginManager:
    pm = PluginManager(PROJECT)
    pm.add_hookspecs(hookspecs)
    from . import core_plugin
    pm.register(core_plugin, name="postproc.core")
    if entry_points:
        # pluggy's load_setuptools_entrypoints, with the discovery remembered between runs
        # (postproc.entry_points); the same order, and the first plugin of a name wins as there
        for name, value in installed_entry_points(PROJECT):
            if not (pm.has_plugin(name) or pm.is_blocked(name)):
                pm.register(load_entry_point(value), name=name)
    for plugin in extra:
        pm.register(plugin)
    pm.check_pending()
    return pm


def installed_dialects() -> dict[str, type[Dialect]]:
    """The installed dialects (``postproc dialects``): the default registry's once it is made, else those of
    the dialect hook alone, which imports the plugins' dialect classes but none of what the registry's
    other hooks register (the core's syntax objects, cycles, frames and lowering steps: ``core_plugin``)."""
    if default_registry.cache_info().currsize:
        return default_registry().dialects
    with gc_paused():
        return collect_dialects(make_plugin_manager())


@functools.cache
def default_registry() -> Registry:
    """The registry of every installed plugin, built on first use, with the cyclic collector off while the plugins
    load: they only allocate what lives as long as the registry (modules, classes, tables), and its collections
    while they did walked everything made before them again (``postproc.commands.command_line.handler`` says what
    that cost)."""
    with gc_paused():
        register_sections(DEFAULT)
        register_expressions(DEFAULT)
        register_control(DEFAULT)
        registry = Registry(make_plugin_manager(), DEFAULT)
        for step in registry.lowerings:
            register_transform(step)
    return registry
