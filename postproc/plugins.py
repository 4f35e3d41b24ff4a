"""The plugin manager: loads the ``postproc`` entry points lazily and collects dialects.

Nothing here names a concrete dialect; built-ins arrive through their entry points like any plugin.
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, Any, Callable, Iterable, Protocol

from . import native
native.install()  # the compiled hot path, before any of its modules is imported

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
from .hookspecs import PROJECT as PROJECT
from .xmlio import DEFAULT, XFactory

if TYPE_CHECKING:
    import pluggy

RESERVED_SETUP_TAGS = frozenset(("Templates", "Library", "MachineCodes", "CodeCall", "Axes", "WorkOffsets", "Tools"))
"""Set-up elements that are not groups: no plugin group may take their names."""

CORE = "postproc.core"
"""The name the core's own plugin (``postproc.core_plugin``) is registered by, before the entry points'."""


class Hooks(Protocol):
    """What the registry calls the plugins' hooks through, ``hook.NAME(**arguments)``: pluggy's manager
    (``postproc.plugin_manager``), or the fast lane's plain calls (``postproc.fast.plugin_hooks``)."""

    @property
    def hook(self) -> Any: ...


Plugins = list[tuple[str, object]]
"""The plugins by name, in the order they are registered."""

HOOKS_LANE: Callable[[Plugins], Hooks | None] | None = None
"""The fast lane's calls of the installed plugins' hooks (``postproc.fast.plugin_hooks.install``, by the command's
process), or None where it cannot tell that they are pluggy's: the registry then makes pluggy's manager."""


def collect_dialects(pm: Hooks) -> dict[str, type[Dialect]]:
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

    def __init__(self, pm: Hooks, factory: XFactory) -> None:
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


def installed_plugins(entry_points: bool = True) -> Plugins:
    """The core's plugin, then (unless ``entry_points`` is False) each installed entry point's, loaded: pluggy's
    ``load_setuptools_entrypoints``, with the discovery remembered between runs (``postproc.entry_points``); the
    same order, and the first plugin of a name wins as there."""
    from . import core_plugin
    found: Plugins = [(CORE, core_plugin)]
    if entry_points:
        names = {CORE}
        for name, value in installed_entry_points(PROJECT):
            if name not in names:
                names.add(name)
                found.append((name, load_entry_point(value)))
    return found


def make_plugin_manager(extra: Iterable[object] = (), entry_points: bool = True) -> pluggy.PluginManager:
    """pluggy's manager of the installed plugins (``installed_plugins``) and ``extra``."""
    from .plugin_manager import manager_of
    return manager_of(installed_plugins(entry_points), extra)


def _installed_hooks() -> Hooks:
    """The installed plugins' hooks: the fast lane's calls where it takes them (``HOOKS_LANE``), else pluggy's."""
    plugins = installed_plugins()
    lane = HOOKS_LANE(plugins) if HOOKS_LANE is not None else None
    if lane is not None:
        return lane
    from .plugin_manager import manager_of
    return manager_of(plugins)


def installed_dialects() -> dict[str, type[Dialect]]:
    """The installed dialects (``postproc dialects``): the default registry's once it is made, else those of
    the dialect hook alone, which imports the plugins' dialect classes but none of what the registry's
    other hooks register (the core's syntax objects, cycles, frames and lowering steps: ``core_plugin``)."""
    if default_registry.cache_info().currsize:
        return default_registry().dialects
    with gc_paused():
        return collect_dialects(_installed_hooks())


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
        registry = Registry(_installed_hooks(), DEFAULT)
        for step in registry.lowerings:
            register_transform(step)
    return registry
