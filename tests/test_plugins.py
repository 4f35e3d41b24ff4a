"""Plugins: hooks, the plugin manager, entry points, and the example dialect plugin.

A small real plugin is registered into a fresh plugin manager by a fixture and unregistered afterwards;
the default registry (``default_registry()``) is never touched by these tests.
"""

from __future__ import annotations

import inspect
import io
from importlib.metadata import entry_points
from pathlib import Path
from typing import Callable, Iterator

import pluggy
import pytest

from postproc import hookspecs
from postproc.api import translate
from postproc.dialect import Dialect
from postproc.errors import ErrorList
from postproc.hookspecs import hookimpl
from postproc.context import Context
from postproc.cycles.lowering import expand_canned_cycles
from postproc.ir import Block, Coolant, Section
from postproc.lowering.lower import Lowering
from postproc.plugins import PROJECT, Registry, default_registry, make_plugin_manager
from postproc.rs274.codes import CodeTable
from postproc.rs274.writer import WordWriter
from postproc.xmlio import XAttr, XFactory, parse_xml_bytes

ROOT = Path(__file__).resolve().parents[1]


class Beep(Section):
    """A section only the toy plugin knows."""

    XNAME = KEY = "Beep"
    XATTRS = (XAttr("pitch", int),)
    __slots__ = ("pitch",)


class ToyWriter(WordWriter):
    DIALECT = "toy"
    CODES = CodeTable((("G00", "01", "motion", "rapid"), ("G21", "06", "units", "mm"),
                       ("G90", "03", "distance", "absolute"), ("M88", "", "coolant", "flood"),
                       ("M09", "", "coolant", "off")))


class Toy(Dialect):
    NAME = "toy"
    DESCRIPTION = "a toy controller for tests"
    WRITER = ToyWriter
    ARCS_R = False
    """Arcs only with I/J/K."""


class ToyPlugin:
    """Implements both registration hooks, as a third-party plugin module would."""

    @hookimpl
    def postproc_register_dialects(self, register: Callable[[type], None]) -> None:
        register(Toy)

    @hookimpl
    def postproc_register_xml(self, factory: XFactory) -> None:
        Beep.reg(factory)


@pytest.fixture
def toy_pm():
    plugin = ToyPlugin()
    pm = make_plugin_manager(extra=[plugin])
    assert pm.is_registered(plugin)
    yield pm
    pm.unregister(plugin)
    assert not pm.is_registered(plugin)


def test_plugin_dialect_appears(toy_pm):
    registry = Registry(toy_pm, XFactory())
    assert registry.dialect("toy") is Toy
    assert registry.dialect("fanuc").NAME == "fanuc"  # the entry points are loaded as well


def test_plugin_xml_class_registers(toy_pm):
    factory = XFactory()
    Registry(toy_pm, factory)
    assert "Beep" in factory.names()
    assert factory.create(parse_xml_bytes(b'<Beep pitch="440"/>', "b.xml")) == Beep(440)
    assert "Beep" not in default_registry().factory.names()  # a fresh manager leaves the default alone


def test_plugin_dialect_translates(toy_pm):
    registry = Registry(toy_pm, XFactory())
    out = io.StringIO()
    translate(io.StringIO("G21 G90 G00 X1.\nM08\nM09\n"), out, file="t.nc", source="fanuc", target="toy",
              registry=registry)
    assert out.getvalue() == "G21 G90 G00 X1.\nM88\nM09\n"


def mist_to_flood(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """A generic lowering step: mist coolant becomes flood where the target has no mist."""
    has_mist = target.WRITER is None or getattr(target.WRITER, "CODES").spell("coolant", "mist") is not None
    for block in blocks:
        coolant = block.sections.get("Coolant")
        if not has_mist and coolant is not None and coolant.mode == "mist":  # type: ignore[attr-defined]
            block.sections["Coolant"] = Coolant("flood")
            block.changed()
        yield block


class LoweringPlugin:
    @hookimpl
    def postproc_register_lowerings(self, register: Callable[[Lowering], None]) -> None:
        register(mist_to_flood)


def test_a_plugin_contributes_a_lowering_step(toy_pm):
    program = "G21 G90 G00 X1.\nM07\nM09\n"
    with pytest.raises(ErrorList, match="cannot express coolant mist"):
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source="fanuc", target="toy",
                  registry=Registry(toy_pm, XFactory()))
    plugin = LoweringPlugin()
    toy_pm.register(plugin)
    try:
        registry = Registry(toy_pm, XFactory())
        assert mist_to_flood in registry.lowerings and expand_canned_cycles in registry.lowerings
        out = io.StringIO()
        translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="toy", registry=registry)
        assert out.getvalue() == "G21 G90 G00 X1.\nM88\nM09\n"
        out = io.StringIO()  # a target with mist is left alone by the step
        translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="fanuc", registry=registry)
        assert out.getvalue() == program
    finally:
        toy_pm.unregister(plugin)


def test_unregistered_plugin_is_gone(toy_pm):
    [plugin] = [p for p in toy_pm.get_plugins() if isinstance(p, ToyPlugin)]
    toy_pm.unregister(plugin)
    assert "toy" not in Registry(toy_pm, XFactory()).dialects
    toy_pm.register(plugin)  # the fixture unregisters it again


def test_without_entry_points_only_the_core_remains():
    pm = make_plugin_manager(entry_points=False)
    factory = XFactory()
    registry = Registry(pm, factory)
    assert registry.dialects == {}
    assert {"Sequence", "Motion", "Pipeline", "MachineSetup", "ModalStateSyntax"} <= set(factory.names())


class Impostor(Dialect):
    NAME = "fanuc"


class ImpostorPlugin:
    @hookimpl
    def postproc_register_dialects(self, register: Callable[[type], None]) -> None:
        register(Impostor)


def test_duplicate_dialect_names_are_an_error():
    pm = make_plugin_manager(extra=[ImpostorPlugin()])
    with pytest.raises(Exception, match="dialect 'fanuc' registered twice"):
        Registry(pm, XFactory())


def test_registering_the_same_dialect_twice_is_harmless(toy_pm):
    class Again:
        @hookimpl
        def postproc_register_dialects(self, register: Callable[[type], None]) -> None:
            register(Toy)

    toy_pm.register(Again())
    assert Registry(toy_pm, XFactory()).dialect("toy") is Toy


class NotADialectPlugin:
    @hookimpl
    def postproc_register_dialects(self, register: Callable[[type], None]) -> None:
        register(WordWriter)


def test_only_named_dialects_can_be_registered():
    pm = make_plugin_manager(extra=[NotADialectPlugin()], entry_points=False)
    with pytest.raises(TypeError, match="is not a named postproc Dialect"):
        Registry(pm, XFactory())


class MisspeltPlugin:
    @hookimpl
    def postproc_register_dialect(self, register: Callable[[type], None]) -> None:  # no trailing s
        register(Toy)


def test_check_pending_catches_a_misspelt_hook():
    with pytest.raises(pluggy.PluginValidationError, match="postproc_register_dialect"):
        make_plugin_manager(extra=[MisspeltPlugin()], entry_points=False)


class WrongArgumentPlugin:
    @hookimpl
    def postproc_register_xml(self, registry: XFactory) -> None:
        pass


def test_a_hook_with_an_unknown_argument_is_refused():
    with pytest.raises(pluggy.PluginValidationError, match="registry"):
        make_plugin_manager(extra=[WrongArgumentPlugin()], entry_points=False)


def test_unknown_dialect_is_a_usage_error_listing_the_installed_ones(toy_pm):
    from postproc.errors import UsageError

    with pytest.raises(UsageError, match=r"unknown dialect 'nope' \(installed: .*fanuc.*toy"):
        Registry(toy_pm, XFactory()).dialect("nope")


# -- the hook specifications themselves --------------------------------------------------------------

def _hookspecs() -> dict[str, Callable[..., object]]:
    return {name: fn for name, fn in inspect.getmembers(hookspecs, inspect.isfunction)
            if hasattr(fn, f"{PROJECT}_spec")}


def test_hooks_are_prefixed_and_documented():
    specs = _hookspecs()
    assert specs, "postproc.hookspecs declares no hooks"
    for name, fn in specs.items():
        assert name.startswith("postproc_"), name
        assert inspect.getdoc(fn), f"hook {name} has no docstring"
        if getattr(fn, f"{PROJECT}_spec").get("firstresult"):
            assert "first non-None result" in inspect.getdoc(fn), f"firstresult hook {name} must say so"


def test_every_hook_is_mentioned_by_a_test():
    """This test names no hook itself: a new hook passes only once some test uses it."""
    sources = {p.name: p.read_text() for p in (ROOT / "tests").rglob("test_*.py")}
    for name in _hookspecs():
        assert any(name in text for text in sources.values()), (
            f"hook {name} has no test: register a plugin implementing it in a test")


# -- entry points and the built-in dialect -------------------------------------------------------------

def test_builtin_fanuc_comes_through_the_entry_point_group():
    eps = {ep.name: ep.value for ep in entry_points(group=PROJECT)}
    assert eps.get("fanuc") == "dialects.fanuc"


def _matrix_column(text: str, dialect: str) -> dict[str, str]:
    """One dialect's column of the ``dialects`` table: row label -> its cell."""
    import re
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("capability "))
    header = re.split(r"\s{2,}", lines[start].strip())
    column: dict[str, str] = {}
    for line in lines[start + 1:]:
        if not line.strip():
            break
        cells = re.split(r"\s{2,}", line.strip())
        column[cells[0]] = cells[header.index(dialect)]
    return column


def test_dialects_command_lists_fanuc_with_its_capability_table(cli):
    result = cli("dialects")
    assert result.status == 0, result.err
    text = result.out.decode()
    fanuc = default_registry().dialect("fanuc")
    assert f"fanuc: {fanuc.DESCRIPTION}" in text.splitlines()
    assert ("  fanuc NATIVE_CYCLES: back_bore, bore_dwell_feed, bore_feed, bore_manual, bore_stop, drill, "
            "drill_dwell, fine_bore, peck_chip, peck_deep, tap, tap_left") in text.splitlines()
    column = _matrix_column(text, "fanuc")
    assert (column["read"], column["write"]) == ("yes", "yes")
    assert column["NATIVE_CYCLES"] == "12 (below)"
    assert column["SPINDLE_ORIENTATION"] == "yes"


def test_dialects_command_as_json(cli):
    import json

    result = cli("dialects", "--json")
    table = json.loads(result.out)
    assert table["fanuc"]["reads"] is True and table["fanuc"]["writes"] is True
    assert "drill" in table["fanuc"]["capabilities"]["NATIVE_CYCLES"]
    assert table["fanuc"]["capabilities"]["SPINDLE_ORIENTATION"] is True


def test_capabilities_are_documented_upper_case_attributes():
    table = Toy.capabilities()
    assert table["ARCS_R"] is False
    assert "NAME" not in table and "WRITER" not in table and "DESCRIPTION" not in table


# -- the example plugin (plugins/example_dialect: the mach3 dialect) -------------------------------------

def _example_installed() -> None:
    names = {ep.name for ep in entry_points(group=PROJECT)}
    assert "mach3" in names, ("the example dialect plugin is not installed: "
                              ".venv/bin/pip install -e plugins/example_dialect (make install does it)")


def test_example_plugin_is_listed(cli):
    _example_installed()
    text = cli("dialects").out.decode()
    column = _matrix_column(text, "mach3")
    assert (column["read"], column["write"]) == ("yes", "yes")
    assert column["NATIVE_CYCLES"] == "3 (below)"  # G81, and G73/G83 with the set-up's clearances
    assert "  mach3 NATIVE_CYCLES: drill, peck_chip, peck_deep\n" in text
    assert column["SPINDLE_ORIENTATION"] == "no"
    assert column["PECK_CLEARANCE_MM"] == "-"


def test_example_plugin_is_built_like_a_third_party_plugin():
    _example_installed()
    example = default_registry().dialect("mach3")
    assert issubclass(example, Dialect) and issubclass(example.WRITER, WordWriter)
    assert example.READER is not None and example.PIPELINE_FILE == "mach3.xml"
    assert example.__module__.split(".")[0] == "postproc_mach3"
    assert example.WRITER.CODES.spell("motion", "rapid") == "G0"
    assert example.WRITER.CODES.spell("home", "home") == "G28"


def test_example_plugin_writes_g0_and_four_decimals(cli):
    _example_installed()
    result = cli("translate", ROOT / "examples/fanuc/o1003_pocket_and_edge.nc", "--from", "fanuc", "--to", "mach3")
    assert result.status == 0, result.err
    lines = result.out.decode().splitlines()
    # hand-written from the source lines N50, N100, N180, N200, N260 and N340 of O1003: codes without
    # leading zeros, four decimals, and N260's M05 (Fanuc: after the move) in a block of its own after
    # it, since Mach3 (RS274/NGC order) would stop the spindle before the move
    for expected in ("N50 G54 G0 X50.0000 Y50.0000 S8000 M3", "N100 G3 I-7.0000",
                     "N180 G3 X20.0000 Y10.0000 I0.0000 J-6.0000", "N200 G3 X80.0000 Y22.0000 R6.0000",
                     "N340 G3 X103.0000 Z-5.0000 I0.0000 K-8.0000"):
        assert expected in lines
    at = lines.index("N260 G91 G28 Z0.0000")
    assert lines[at + 1] == "M5"


def test_example_plugin_refuses_an_oriented_spindle_stop():
    _example_installed()
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO("G21 G90 G00 X0. Y0.\nM19\n"), io.StringIO(), file="o.nc", source="fanuc",
                  target="mach3")
    [err] = info.value.errors
    assert str(err) == "o.nc:2:1: error: the mach3 dialect cannot express an oriented spindle stop"


def test_example_plugin_reads_its_own_programs(cli):
    _example_installed()
    program = ROOT / "plugins/example_dialect/examples/face_and_drill.tap"
    result = cli("translate", program, "--from", "mach3", "--to", "mach3")
    assert result.status == 0, result.err
    assert result.out == program.read_bytes()


def test_the_managers_scan_finds_what_pluggys_finds():
    """``postproc.plugin_manager.PluginManager`` cuts pluggy's scan of a module short: on every installed plugin module
    (and a toy one with a marked function, a misspelt marked one, a static method and a class), for every name,
    it answers as pluggy's own ``parse_hookimpl_opts``."""
    import types

    from postproc import core_plugin
    from postproc.entry_points import entry_points as installed, load
    from postproc.plugin_manager import PluginManager

    toy = types.ModuleType("toy_plugin")
    exec("from postproc.hookspecs import hookimpl\n"
         "@hookimpl\ndef postproc_register_dialects(register): pass\n"
         "@hookimpl\ndef postproc_register_dialect(register): pass\n"
         "def helper(): pass\n"
         "class Thing:\n    pass\n"
         "marked = staticmethod(postproc_register_dialects)\n", vars(toy))
    ours, theirs = PluginManager(PROJECT), pluggy.PluginManager(PROJECT)
    modules = [core_plugin, toy, *(load(value) for _, value in installed(PROJECT))]
    assert len(modules) > 5
    for module in modules:
        for name in dir(module):
            assert ours.parse_hookimpl_opts(module, name) == theirs.parse_hookimpl_opts(module, name), name
    assert ours.parse_hookimpl_opts(toy, "postproc_register_dialect") is not None  # misspelt: still found, refused


def test_the_installed_dialects_are_the_registrys():
    """``installed_dialects`` (the dialect hook alone, for ``postproc dialects``, while no registry is made) names
    the same classes as the registry, and the registry's once it is made."""
    from postproc.plugins import collect_dialects, installed_dialects
    alone = collect_dialects(make_plugin_manager())
    assert alone == default_registry().dialects and len(alone) >= 9
    assert installed_dialects() is default_registry().dialects
