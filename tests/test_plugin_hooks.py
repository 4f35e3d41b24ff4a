"""The plugin-hook lane (``postproc.fast.plugin_hooks``) against pluggy's manager (``postproc.plugin_manager``): on
random plugin modules, where the lane takes the plugins it calls each hook's implementations as pluggy does (the same
functions, in the same order, with the same arguments, the same results), and where it does not pluggy decides; on
the installed plugins it takes them and the registry it makes is pluggy's. The markers (``postproc.hookspecs``) set
what pluggy's set."""

from __future__ import annotations

import itertools
import types
from typing import Any

import pluggy
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc import hookspecs
from postproc.fast.plugin_hooks import plain_hooks
from postproc.hookspecs import PROJECT, HookimplMarker, HookspecMarker
from postproc.plugin_manager import manager_of
from postproc.plugins import Registry, installed_plugins
from postproc.xmlio import XFactory

SPECS = {name: value.__code__.co_varnames[:value.__code__.co_argcount] for name, value in vars(hookspecs).items()
         if hasattr(value, f"{PROJECT}_spec")}
NAMES = sorted(SPECS) + ["postproc_register_dialect"]  # (a misspelt hook)
OPTIONS = ({}, {}, {}, {"tryfirst": True}, {"trylast": True}, {"optionalhook": True}, {"specname": NAMES[0]})


def test_the_markers_set_what_pluggys_set() -> None:
    ours, theirs = HookimplMarker(PROJECT), pluggy.HookimplMarker(PROJECT)
    for flags in itertools.product((False, True), repeat=5):
        for specname in (None, "postproc_register_xml"):
            options = dict(zip(("hookwrapper", "optionalhook", "tryfirst", "trylast", "wrapper"), flags),
                           specname=specname)

            def one() -> None: ...
            def two() -> None: ...
            ours(**options)(one)
            theirs(**options)(two)
            assert getattr(one, f"{PROJECT}_impl") == getattr(two, f"{PROJECT}_impl")
    bare_ours, bare_theirs = ours(lambda: None), theirs(lambda: None)
    assert getattr(bare_ours, f"{PROJECT}_impl") == getattr(bare_theirs, f"{PROJECT}_impl")
    for firstresult, historic in ((False, False), (True, False), (False, True)):
        def three() -> None: ...
        def four() -> None: ...
        HookspecMarker(PROJECT)(three, firstresult=firstresult, historic=historic)
        pluggy.HookspecMarker(PROJECT)(four, firstresult=firstresult, historic=historic)
        assert getattr(three, f"{PROJECT}_spec") == getattr(four, f"{PROJECT}_spec")


def _implementation(log: list[tuple[Any, ...]], plugin: int, hook: str, arguments: tuple[str, ...],
                    result: object) -> types.FunctionType:
    """A module-level function of ``arguments`` that logs its call and returns ``result``."""
    logged = "".join(a + ", " for a in arguments)
    source = f"def {hook}({', '.join(arguments)}):\n    log.append(({plugin}, {hook!r}, ({logged})))\n    return result\n"
    space: dict[str, Any] = {"log": log, "result": result}
    exec(source, space)
    function: types.FunctionType = space[hook]
    return function


PLUGIN = st.lists(st.tuples(st.sampled_from(NAMES), st.integers(0, 3), st.sampled_from(OPTIONS),
                            st.sampled_from((None, None, 1, "x")), st.booleans()),
                  max_size=5, unique_by=lambda t: t[0])
"""A plugin: its hook implementations, each (hook, which arguments: none, the hook's, an extra one, the hook's and
an extra one, options, what it returns, marked or not)."""


def _plugins(drawn: list[list[tuple[Any, ...]]], log: list[tuple[Any, ...]]) -> list[tuple[str, object]]:
    made: list[tuple[str, object]] = []
    for index, implementations in enumerate(drawn):
        module = types.ModuleType(f"plugin_{index}")
        for hook, which, options, result, marked in implementations:
            given = SPECS.get(hook, ("register",))
            arguments = ((), given, ("extra",), (*given, "extra"))[which]
            function = _implementation(log, index, hook, arguments, result)
            if marked:
                HookimplMarker(PROJECT)(function, **options)
            setattr(module, hook, function)
        made.append((f"plugin_{index}", module))
    return made


@settings(max_examples=300, deadline=None)
@given(st.lists(PLUGIN, min_size=1, max_size=5))
def test_the_lane_calls_the_hooks_as_pluggy_does(drawn: list[list[tuple[Any, ...]]]) -> None:
    ours_log: list[tuple[Any, ...]] = []
    theirs_log: list[tuple[Any, ...]] = []
    lane = plain_hooks(_plugins(drawn, ours_log))
    if lane is None:
        return  # pluggy's to decide
    pm = manager_of(_plugins(drawn, theirs_log))  # a plugin set the lane takes, pluggy takes
    for hook, arguments in SPECS.items():
        given = {name: f"{hook}:{name}" for name in arguments}
        assert getattr(lane.hook, hook)(**given) == getattr(pm.hook, hook)(**given)
    assert ours_log == theirs_log


@settings(max_examples=100, deadline=None)
@given(st.lists(st.lists(st.tuples(st.sampled_from(sorted(SPECS)), st.sampled_from((0, 1))), max_size=4,
                         unique_by=lambda t: t[0]), min_size=1, max_size=5))
def test_the_lane_takes_plain_plugins(drawn: list[list[tuple[str, int]]]) -> None:
    """The other side: plugins of plain, marked implementations of the hooks are the lane's (the test above is not
    blind)."""
    log: list[tuple[Any, ...]] = []
    plugins = _plugins([[(hook, which, {}, None, True) for hook, which in each] for each in drawn], log)
    assert plain_hooks(plugins) is not None


def test_the_installed_plugins_are_the_lanes_and_make_pluggys_registry() -> None:
    plugins = installed_plugins()
    lane = plain_hooks(plugins)
    assert lane is not None and len(plugins) > 5
    ours, theirs = Registry(lane, XFactory()), Registry(manager_of(plugins), XFactory())
    assert ours.dialects == theirs.dialects and list(ours.dialects) == list(theirs.dialects)
    assert ours.lowerings == theirs.lowerings
    assert ours.setup_groups == theirs.setup_groups and list(ours.setup_groups) == list(theirs.setup_groups)
    assert ours.factory._classes == theirs.factory._classes and ours.factory._lazy == theirs.factory._lazy


def test_a_plugin_that_is_no_module_or_comes_twice_is_pluggys() -> None:
    plugins = installed_plugins()

    class Object:
        pass

    assert plain_hooks([*plugins, ("object", Object())]) is None
    assert plain_hooks([*plugins, ("again", plugins[-1][1])]) is None
