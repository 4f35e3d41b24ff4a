"""Hook specifications. Every hook is prefixed ``postproc_``; plugins implement them with ``hookimpl``.

Built-in dialects register through these same hooks, from the same entry-point group (``postproc``),
as any third-party plugin.

``hookspec`` and ``hookimpl`` are pluggy's markers, written here: each sets on the function the attribute
pluggy's ``HookspecMarker``/``HookimplMarker`` of the project would, with the same options, so a plugin module
imports neither pluggy nor its ``inspect`` (about a tenth of a one-line translation's start-up, callgrind); the
registry's manager is pluggy's all the same (``postproc.plugin_manager``), unless the fast lane calls the hooks
(``postproc.fast.plugin_hooks``). ``tests/test_plugins.py`` holds them to pluggy's markers.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Mapping, TypeVar, overload

from .xmlio import XFactory

if TYPE_CHECKING:
    from .lowering.lower import Lowering
    from .setup.machine_setup import SetupGroup

PROJECT = "postproc"
"""The project name of the markers and of the entry-point group."""

_F = TypeVar("_F", bound=Callable[..., Any])


class HookspecMarker:
    """pluggy's ``HookspecMarker``: ``@hookspec`` or ``@hookspec(firstresult=True, ...)`` sets
    ``<project>_spec`` on the function to the options' dictionary."""

    __slots__ = ("project_name",)

    def __init__(self, project_name: str) -> None:
        self.project_name = project_name

    @overload
    def __call__(self, function: _F, firstresult: bool = False, historic: bool = False,
                 warn_on_impl: Warning | None = None, warn_on_impl_args: Mapping[str, Warning] | None = None) -> _F: ...
    @overload
    def __call__(self, function: None = None, firstresult: bool = False, historic: bool = False,
                 warn_on_impl: Warning | None = None,
                 warn_on_impl_args: Mapping[str, Warning] | None = None) -> Callable[[_F], _F]: ...

    def __call__(self, function: _F | None = None, firstresult: bool = False, historic: bool = False,
                 warn_on_impl: Warning | None = None,
                 warn_on_impl_args: Mapping[str, Warning] | None = None) -> _F | Callable[[_F], _F]:
        def mark(func: _F) -> _F:
            if historic and firstresult:
                raise ValueError("cannot have a historic firstresult hook")
            setattr(func, self.project_name + "_spec", {"firstresult": firstresult, "historic": historic,
                                                        "warn_on_impl": warn_on_impl,
                                                        "warn_on_impl_args": warn_on_impl_args})
            return func

        return mark(function) if function is not None else mark


class HookimplMarker:
    """pluggy's ``HookimplMarker``: ``@hookimpl`` or ``@hookimpl(tryfirst=True, ...)`` sets ``<project>_impl``
    on the function to the options' dictionary."""

    __slots__ = ("project_name",)

    def __init__(self, project_name: str) -> None:
        self.project_name = project_name

    @overload
    def __call__(self, function: _F, hookwrapper: bool = False, optionalhook: bool = False, tryfirst: bool = False,
                 trylast: bool = False, specname: str | None = None, wrapper: bool = False) -> _F: ...
    @overload
    def __call__(self, function: None = None, hookwrapper: bool = False, optionalhook: bool = False,
                 tryfirst: bool = False, trylast: bool = False, specname: str | None = None,
                 wrapper: bool = False) -> Callable[[_F], _F]: ...

    def __call__(self, function: _F | None = None, hookwrapper: bool = False, optionalhook: bool = False,
                 tryfirst: bool = False, trylast: bool = False, specname: str | None = None,
                 wrapper: bool = False) -> _F | Callable[[_F], _F]:
        def mark(func: _F) -> _F:
            setattr(func, self.project_name + "_impl", {"wrapper": wrapper, "hookwrapper": hookwrapper,
                                                        "optionalhook": optionalhook, "tryfirst": tryfirst,
                                                        "trylast": trylast, "specname": specname})
            return func

        return mark(function) if function is not None else mark


hookspec = HookspecMarker(PROJECT)
hookimpl = HookimplMarker(PROJECT)


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
