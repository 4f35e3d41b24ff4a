"""Start-up: a run imports only what it uses (issue 13). Counted in a fresh interpreter from the modules in
``sys.modules`` when the command ends, never timed: what a one-line translation or ``postproc dialects``
must not load is pydantic (set-up validation), jinja2 (templates), the batch and cluster machinery, the
toolpath, verify and backplot code; with a set-up file (``--machine``) pydantic is loaded, by design.
Nor the standard modules a plain run has no use for: decimal (an exponent's spelling), threading, json (the
compiled build's manifest is plain lines: ``postproc.native.MANIFEST``), tempfile
and shutil with what they import (the temporary output is made with ``os`` alone: ``postproc.output.outfile``;
argparse's formatter is sized without shutil: ``postproc.commands.command_line._Formatter``); and a command that reads and
writes no XML does not load lxml (``postproc.xmlio.lxml_etree``): neither ``postproc dialects`` nor a
translation without a set-up file, whose dialects declare their reading pipelines in Python
(``Dialect.python_pipeline``). Every installed dialect is registered, but a translation imports the
readers, writers and syntax objects of the dialects it uses only (``Dialect`` attributes ``Lazy``, syntax
objects ``XFactory.register_lazy``)."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PROBE = """
import atexit, os, runpy, sys
atexit.register(lambda: open(os.environ["MODULES_OUT"], "w").write("\\n".join(sorted(sys.modules))))
sys.argv = ["postproc", *os.environ["ARGS"].split("\\n")]
runpy.run_module("postproc", run_name="__main__")
"""
"""Runs a command and writes the names of the modules loaded when it ends, one a line (it imports no
module of its own that a run might not: json is one the runs must not load)."""
NEVER_BY_DEFAULT = ("pydantic", "pydantic_core", "annotated_types", "jinja2", "dask", "distributed", "PIL",
                    "postproc.setup.validate", "postproc.setup.load", "postproc.output.templates", "postproc.commands.batch.command",
                    "postproc.commands.batch.local", "postproc.commands.batch.cluster", "postproc.simulate.toolpath", "postproc.simulate.verify",
                    "postproc.drawing.backplot", "postproc.drawing.canvas", "postproc.commands.export", "pluggy",
                    "postproc.plugin_manager")
NOT_AT_START = ("decimal", "threading", "tempfile", "shutil", "random", "bz2", "lzma", "json", "signal", "zlib",
                "ast", "dis", "tokenize")
"""Standard modules imported where they are used (a top-level import of one of them fails here); ``signal`` and
``zlib`` are never: the command line sets its handlers through ``signal``'s C core (``postproc.commands.cli``),
and the entry-point cache names its file without a CRC (``postproc.entry_points``); nor ``inspect``, seen here by
what it imports (``ast``, ``dis``, ``tokenize``: the name ``inspect`` stands in ``sys.modules`` from the start,
``postproc.commands.launch``): ``dataclasses`` imports it when it first reads a name of it, which it does for a
dataclass without a docstring (every one of ours has one), and the registry calls the plugins' hooks without
pluggy, which imports it (``postproc.fast.plugin_hooks``)."""
ONLY_FOR_XML = ("lxml",)
OTHER_DIALECTS = ("dialects.fagor", "dialects.gsk", "dialects.isg", "postproc_grbl", "postproc_grblhal",
                  "postproc_linuxcnc", "postproc_mach3")
"""Every installed dialect but Fanuc (the built-ins and the plugins in plugins/)."""
KEEP_CHECK = ("postproc.interp.jump_targets", "postproc.frames.parameters", "postproc.interp.numbers",
              "postproc.interp.returns")
"""What judges whether a program that computes can be kept symbolic for its target (``postproc.api._keep_check``)."""
EXPRESSIONS_ONLY = ("postproc.interp.evaluation", "postproc.interp.long_double", "postproc.rs274.oword")
"""What only a program with an expression or a statement uses: the structure check's evaluator (``certain_failure``,
``postproc.interp.structure``) and the RS274/NGC statements' spelling (LinuxCNC's and grblHAL's writers)."""
ARC_PASS = ("postproc.lowering.arcs", "postproc.lowering.arc_words", "postproc.lowering.arc_geometry")
"""The arc pass: ``--arcs``, or the settle pass of a translation that has arcs to settle (``ArcEndRule.settles_for``:
to grbl or grblHAL, or from a controller that moves the centre)."""
NOT_FOR_A_PLAIN_TRANSLATION = ("postproc.transforms.carry", "postproc.transforms.units", "postproc.transforms.spec",
                               "postproc.rs274.lathe_cycles",
                               "postproc.cycles.turning", "postproc_linuxcnc.block_syntax", "postproc_linuxcnc.program",
                               "postproc.rs274.macro_jumps", "postproc.rs274.lean_controller",
                               "postproc.cycles.lathe_lowering", "postproc.cycles.lathe_offsets",
                               "postproc.rs274.lathe_tool_index", "postproc_linuxcnc.lathe_writer",
                               "postproc.rs274.ngc_lathe_writer", "postproc.rs274.ngc_lathe", "postproc.geometry.thread_lead",
                               "postproc.setup.machine", *KEEP_CHECK, *EXPRESSIONS_ONLY, *ARC_PASS)
"""What a plain mill translation to LinuxCNC has no use for: the program transforms' reading and work (``--transform``,
``--units``: ``postproc.transforms.apply``), a lathe's cycle reader and turning cycles (``LatheCycleSyntax`` is
registered lazily), a lathe's lowering (its cycles' expansion and the turret's index:
``postproc.core_plugin``) and writing (LinuxCNC's thread feed step imports it for a lathe only),
the target's reading side and what judges a program that computes (its block syntax and program step: the keep check and
``TARGET_OMITS_VACANT`` build the target's pipeline when a program that computes first asks, ``postproc.api``),
the lowering steps of other targets that registering their dialects named (Fanuc's ``number_jumps``, grbl's
and grblHAL's lean-controller steps: each imported when a translation first lowers for that target), and the
machine's geometry of a set-up (``postproc.setup.machine``: a set-up file's axes, work offsets and tools)."""
REGISTERED_ONLY = ("active_comments",)
"""What registering a dialect imports besides its package: LinuxCNC's generic lowering step. (Not its code table
nor its cycle words: ``Dialect.CYCLE_WORDS`` is ``Lazy``, imported where a run reads that dialect's.)"""


def modules_after(tmp_path: Path, *args: str) -> set[str]:
    out = tmp_path / "modules.txt"
    cwd = tmp_path / "cwd"  # on sys.path (python -c): kept unchanged and old, so the entry-point cache settles
    if not cwd.exists():
        cwd.mkdir()
        past = time.time() - 60
        os.utime(cwd, (past, past))
    env = dict(os.environ, HOME=str(tmp_path), MODULES_OUT=str(out), ARGS="\n".join(args))
    env.pop("POSTPROC_NO_ENTRY_POINT_CACHE", None)
    env.pop("XDG_CACHE_HOME", None)
    done = subprocess.run([sys.executable, "-c", PROBE], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    return set(out.read_text().splitlines())


def loaded(modules: set[str], name: str) -> bool:
    return name in modules or any(m.startswith(name + ".") for m in modules)


@pytest.fixture
def one_line(tmp_path: Path) -> Path:
    path = tmp_path / "one.nc"
    path.write_text("G0 X1. Y2.\n")
    return path


def test_a_one_line_translation_loads_nothing_it_does_not_use(tmp_path: Path, one_line: Path) -> None:
    modules = modules_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", "linuxcnc")
    assert "postproc.api" in modules and "postproc_linuxcnc.writer" in modules  # the probe saw the run
    assert [name for name in NEVER_BY_DEFAULT if loaded(modules, name)] == []


def test_a_program_number_loads_the_structure_check_but_not_decimal(tmp_path: Path) -> None:
    """A program with a program number is shown to the structure check (``postproc.interp.structure``), whose
    expression module imports ``decimal`` only where it rounds to an increment (~1 ms of start-up)."""
    path = tmp_path / "numbered.nc"
    path.write_text("%\nO1234\nN10 G0 X1. Y2.\nN20 M30\n%\n")
    modules = modules_after(tmp_path, "translate", str(path), "--from", "fanuc", "--to", "linuxcnc")
    assert "postproc.interp.structure" in modules  # the check ran
    assert not loaded(modules, "decimal")


DRAWING = ("postproc.drawing", "lxml", "tempfile", "shutil", "random", "bz2", "lzma")
"""What drawing a backplot imports (``postproc.commands.export.write_backplot``): the default toolpath, JSON lines,
draws none."""


def test_a_toolpath_as_json_lines_loads_no_drawing(tmp_path: Path, one_line: Path) -> None:
    out = tmp_path / "one.jsonl"
    modules = warm_modules_after(tmp_path, "toolpath", str(one_line), "--dialect", "fanuc", "-o", str(out))
    assert "postproc.simulate.toolpath" in modules and out.read_text()  # the probe saw the run
    assert [name for name in DRAWING + NOT_AT_START if loaded(modules, name) and name != "json"] == []


TRANSLATION_ONLY = ("postproc.api", "postproc.transforms", "postproc.lowering.sequences", "postproc.rs274.writer",
                    "postproc.fast.lane", "postproc.fast.straight", *ARC_PASS, *EXPRESSIONS_ONLY)
"""What a toolpath has no use for: the translation's API and its transforms (``postproc.commands.handlers`` imports
``translate`` in the translate command), the templates' texts (``Generated`` is registered lazily), the writer's
lane and the word writer (the reading lanes choose without them: ``postproc.fast.reading.own_in``), the arc pass and
the expressions' modules."""


def test_a_toolpath_loads_no_translation_writer_or_arc_pass(tmp_path: Path, one_line: Path) -> None:
    out = tmp_path / "one.jsonl"
    modules = modules_after(tmp_path, "toolpath", str(one_line), "--dialect", "fanuc", "-o", str(out))
    assert "postproc.simulate.toolpath" in modules and out.read_text()  # the probe saw the run
    assert [name for name in TRANSLATION_ONLY if loaded(modules, name)] == []


def test_a_backplot_loads_the_drawing(tmp_path: Path, one_line: Path) -> None:
    """The other side of the lazy import: ``--format svg`` does load the drawing (the probe is not blind)."""
    out = tmp_path / "one.svg"
    modules = modules_after(tmp_path, "toolpath", str(one_line), "--dialect", "fanuc", "--format", "svg",
                            "-o", str(out))
    assert "postproc.drawing.backplot" in modules and out.read_text().lstrip().startswith("<")


def test_a_plain_translation_loads_no_transform_lathe_or_target_reader(tmp_path: Path, one_line: Path) -> None:
    modules = modules_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", "linuxcnc")
    assert "postproc.api" in modules and "postproc_linuxcnc.writer" in modules  # the probe saw the run
    assert [name for name in NOT_FOR_A_PLAIN_TRANSLATION if loaded(modules, name)] == []


@pytest.mark.parametrize("program, target, options, wanted", [
    ("#1=2.\nG0 X#1 Y[#1+1]\nM30\n", "linuxcnc", (), ("postproc_linuxcnc.block_syntax", "postproc_linuxcnc.program",
                                                      *KEEP_CHECK, *EXPRESSIONS_ONLY)),
    ("G0 X1. Y2.\nG2 X3. Y2. R1. F100.\nM30\n", "linuxcnc", ("--arcs", "ijk"), ARC_PASS),
    ("G0 X1. Y2.\nM30\n", "grbl", (), ARC_PASS),
    ("G0 X1. Y2.\nM30\n", "linuxcnc", ("--units", "inch"), ("postproc.transforms.units",)),
    ("G0 X1. Y2.\nM30\n", "linuxcnc", ("--transform", "translate 1,2"), ("postproc.transforms.carry",
                                                                   "postproc.transforms.spec")),
    ("G0 X20. Z2. S500 M3\nG1 Z-10. F0.2\nM30\n", "linuxcnc",
     ("--machine", str(ROOT / "examples/setups/fanuc_0i_tf.xml")),
     ("postproc.rs274.lathe_cycles", "postproc.cycles.lathe_lowering", "postproc_linuxcnc.lathe_writer")),
    ("G0 X1. Y2.\nM30\n", "fanuc", (), ("postproc.rs274.macro_jumps",)),
    ("G0 X1. Y2.\nM30\n", "grbl", (), ("postproc.rs274.lean_controller",)),
    ("G0 X1. Y2.\nM30\n", "grblhal", (), ("postproc.rs274.lean_controller",)),
])
def test_what_a_plain_translation_leaves_out_is_loaded_where_used(tmp_path: Path, program: str, target: str,
                                                                   options: tuple[str, ...],
                                                                   wanted: tuple[str, ...]) -> None:
    """The other side of ``NOT_FOR_A_PLAIN_TRANSLATION``: a program that computes (kept symbolic for LinuxCNC,
    so the keep check reads the target's rules), ``--units``, ``--transform``, a lathe set-up and a translation
    to the target whose lowering step it is load them."""
    path = tmp_path / "program.nc"
    path.write_text(program)
    modules = modules_after(tmp_path, "translate", str(path), "--from", "fanuc", "--to", target, *options)
    assert [name for name in wanted if name not in modules] == []


def test_a_second_run_finds_the_plugins_without_importlib_metadata(tmp_path: Path, one_line: Path) -> None:
    """The first run discovers the entry points (importlib.metadata) and remembers them in its HOME's
    cache; the next run reads them from there. (A distribution installed into this interpreter's
    environment less than two seconds before the first run rightly keeps it from caching: the first
    run is then repeated until the installation has settled, as ``warm_modules_after`` does.)"""
    args = ("translate", str(one_line), "--from", "fanuc", "--to", "linuxcnc")
    assert loaded(modules_after(tmp_path, *args), "importlib.metadata")
    for _ in range(10):
        if any((tmp_path / ".cache" / "postproc").glob("entry-points-*")):
            break
        time.sleep(1)
        assert loaded(modules_after(tmp_path, *args), "importlib.metadata")  # no cache yet: discovered again
    assert any((tmp_path / ".cache" / "postproc").glob("entry-points-*"))
    second = modules_after(tmp_path, *args)
    assert [name for name in ("importlib.metadata", "email") if loaded(second, name)] == []
    assert "postproc_linuxcnc.writer" in second


def test_listing_the_dialects_loads_nothing_it_does_not_use(tmp_path: Path) -> None:
    modules = modules_after(tmp_path, "dialects")
    assert "postproc.plugins" in modules
    assert [name for name in NEVER_BY_DEFAULT if loaded(modules, name)] == []


def warm_modules_after(tmp_path: Path, *args: str) -> set[str]:
    """``modules_after`` of a run that finds the entry-point cache an earlier run wrote (discovering the
    entry points imports importlib.metadata, and with it zipfile, threading, tempfile). A run writes the
    cache once the installation has settled (``postproc.entry_points.SETTLE`` seconds after its last
    change: not yet just after ``make install``), so the first run is repeated until it has."""
    for _ in range(10):
        modules_after(tmp_path, *args)
        if any((tmp_path / ".cache" / "postproc").glob("entry-points-*")):
            break
        time.sleep(1)
    return modules_after(tmp_path, *args)


@pytest.mark.parametrize("target, writer", [("fanuc", "dialects.fanuc.writer"),
                                            ("linuxcnc", "postproc_linuxcnc.writer")])
def test_a_plain_translation_loads_no_standard_module_it_does_not_use(tmp_path: Path, one_line: Path,
                                                                       target: str, writer: str) -> None:
    modules = warm_modules_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", target,
                                 "--normalize")
    assert "postproc.api" in modules and writer in modules  # the probe saw the run
    assert [name for name in NOT_AT_START + ONLY_FOR_XML if loaded(modules, name)] == []


def test_a_translation_imports_only_its_own_dialects_modules(tmp_path: Path, one_line: Path) -> None:
    modules = warm_modules_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", "fanuc",
                                 "--normalize")
    assert "dialects.fanuc.reader" in modules and "dialects.fanuc.writer" in modules  # the probe saw the run
    assert [name for name in OTHER_DIALECTS if name not in modules] == []  # each registered
    extra = sorted(name for name in modules if name.startswith(tuple(p + "." for p in OTHER_DIALECTS))
                   and name.rpartition(".")[2] not in REGISTERED_ONLY)
    assert extra == []
    assert [name for name in ("postproc.isg_family", "postproc.rs274.ngc_lexer") if loaded(modules, name)] == []


def test_listing_the_dialects_loads_no_xml_parser(tmp_path: Path) -> None:
    """Every module that reads or writes XML imports lxml on first use."""
    modules = warm_modules_after(tmp_path, "dialects")
    assert "postproc.xmlio" in modules and "postproc.commands.dialect_table" in modules  # the probe saw the run
    # nor the translating commands' modules (``command_line.handler`` imports the one command's)
    assert [name for name in ("postproc.commands.handlers", "postproc.api", "postproc.output.outfile")
            if name in modules] == []
    assert [name for name in NOT_AT_START + ONLY_FOR_XML if loaded(modules, name)] == []


def test_a_set_up_file_is_validated_with_pydantic(tmp_path: Path, one_line: Path) -> None:
    """The other side of the lazy import: ``--machine`` does load the validator (the probe is not blind) for a
    value the set-up lane leaves to it (``5e-1``: not a plain spelling, ``postproc.fast.setup_values``), and
    a set-up of plain values (a shipped example) is read without it."""
    plain = ROOT / "examples/setups" / "fanuc_0i_mf_vmc.xml"
    modules = modules_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", "linuxcnc",
                            "--machine", str(plain))
    assert "postproc.setup.load" in modules and not loaded(modules, "pydantic")
    setup = tmp_path / "exponent.xml"
    setup.write_text('<MachineSetup><Cycles peckRetract="5e-1"/></MachineSetup>')
    modules = modules_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", "linuxcnc",
                            "--machine", str(setup))
    assert loaded(modules, "pydantic") and "postproc.setup.validate" in modules


NOT_FOR_A_SET_UP = ("pathlib", "urllib", "ipaddress", "fnmatch", "ast", "dis", "tokenize")
"""What loading a set-up file (``--machine``) does not import: ``pathlib`` with what it imports (the loader's paths are
text, ``postproc.setup.paths``), nor ``inspect``, seen by what it imports, which lxml would (``lxml.etree`` binds
``inspect.getfullargspec`` as it loads: ``postproc.commands.launch._inspect_when_read``)."""


@pytest.mark.parametrize("setup", ["benchmarks/machine.xml", "examples/setups/fanuc_0i_mf_vmc.xml"])
def test_a_set_up_file_loads_no_pathlib_and_no_inspect(tmp_path: Path, one_line: Path, setup: str) -> None:
    """The bench's set-up and a shipped example that extends a base (``fanuc-0i-mf.xml``)."""
    out = tmp_path / "one.jsonl"
    modules = warm_modules_after(tmp_path, "toolpath", str(one_line), "--dialect", "fanuc", "--machine",
                                 str(ROOT / setup), "-o", str(out))
    assert "postproc.setup.load" in modules and "lxml.etree" in modules and out.read_text()  # the probe saw the run
    assert [name for name in NOT_FOR_A_SET_UP if loaded(modules, name)] == []


ALL_MODULES = """
import importlib, pkgutil, sys
from postproc import native
native.install()
for top in sys.argv[1:]:
    package = importlib.import_module(top)
    for info in pkgutil.walk_packages(package.__path__, top + "."):
        importlib.import_module(info.name)
print("\\n".join(sorted(name for name in sys.modules if name.split(".")[0] in ("lxml", *sys.argv[1:]))))
"""


def test_no_dialect_module_imports_an_xml_parser_at_its_top() -> None:
    """Every module of every shipped dialect, imported: lxml is not among what they import."""
    done = subprocess.run([sys.executable, "-c", ALL_MODULES, "dialects", "postproc_grbl", "postproc_grblhal",
                           "postproc_linuxcnc", "postproc_mach3"], capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    modules = done.stdout.splitlines()
    assert "dialects.fagor.multiple_machining" in modules and "postproc_linuxcnc.program" in modules
    assert [name for name in modules if name.split(".")[0] == "lxml"] == []


def test_listing_the_dialects_imports_no_reader_or_writer(tmp_path: Path) -> None:
    """The table says whether each dialect reads and writes from its declarations (``Lazy`` ones
    unloaded): no dialect's reader or writer module is imported to list them."""
    modules = warm_modules_after(tmp_path, "dialects")
    assert "postproc.commands.dialect_table" in modules  # the probe saw the run
    loaded_io = sorted(name for name in modules if name.startswith(("dialects.", "postproc_"))
                       and name.rpartition(".")[2] in ("reader", "writer", "lathe_writer"))
    assert loaded_io == []


def test_the_version_imports_no_command(tmp_path: Path) -> None:
    """``postproc --version`` builds the parser only: no command's handler (``command_line.handler``), so none
    of the translation's modules, the registry or the plugins; and its number is a constant
    (``postproc.version``), not the installed metadata (``importlib.metadata`` and the email package)."""
    modules = modules_after(tmp_path, "--version")
    assert "postproc.commands.command_line" in modules and "postproc.version" in modules  # the probe saw the run
    assert [name for name in ("postproc.commands.handlers", "postproc.commands.dialect_table", "postproc.api",
                              "postproc.plugins", "postproc.lowering", "dialects", "importlib.metadata", "email")
            if loaded(modules, name)] == []


def test_the_version_printed_is_the_installed_distributions() -> None:
    """The constant ``--version`` prints is the version the installation's metadata records (the build reads it
    from ``postproc.version``: a stale installation, or a version written elsewhere, fails here)."""
    from importlib.metadata import version
    done = subprocess.run([sys.executable, "-m", "postproc", "--version"], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(f"postproc {version('postproc')}, hot path "), done.stdout


def test_listing_the_dialects_runs_only_the_dialect_hook(tmp_path: Path) -> None:
    """``postproc dialects`` registers the dialects alone (``postproc.plugins.installed_dialects``): the core
    plugin's syntax objects, cycles, frames and lowering steps are not imported (``postproc.core_plugin``)."""
    modules = warm_modules_after(tmp_path, "dialects")
    assert "postproc.core_plugin" in modules and "postproc.commands.dialect_table" in modules  # the probe saw the run
    assert [name for name in ("postproc.cycles.lowering", "postproc.frames.lowering", "postproc.lowering.sequences",
                              "postproc.patterns", "postproc.frames.measured_entries") if loaded(modules, name)] == []


def test_listing_the_dialects_loads_no_cycle_engine_or_target_step(tmp_path: Path) -> None:
    """Every family base that names its hole-cycle rules imports ``postproc.cycles.semantics``, which runs the cycle
    package's ``__init__``: it imports none of the engine (expansions, the resolve step, where a cycle ends), nor
    does a dialect's registration import the lowering steps its ``LOWERING`` names (``LazyStep``: ISG's and
    LinuxCNC's jump nesting, grblHAL's comment after the end)."""
    modules = warm_modules_after(tmp_path, "dialects")
    assert "postproc.cycles.semantics" in modules and "postproc.commands.dialect_table" in modules  # the probe saw the run
    assert [name for name in ("postproc.cycles.resolve", "postproc.cycles.expansion", "postproc.cycles.drilling",
                              "postproc.cycles.back_boring", "postproc.cycles.section", "postproc.cycles.hole_ends",
                              "postproc.lowering.structured_jumps", "postproc.lowering.program_end")
            if name in modules] == []


def test_the_cycle_package_names_its_xml_classes_as_they_are() -> None:
    """``postproc.cycles.register`` registers the package's XML classes by name (``XML_NAMES``): each name is the
    class's own ``XNAME`` and every class of ``XML_CLASSES`` (the section, the resolve step, every expansion) is
    there."""
    from postproc import cycles
    assert {cls.XNAME: f"{cls.__module__}:{cls.__qualname__}" for cls in cycles.XML_CLASSES} == \
        {name: f"postproc.cycles.{target}" for name, target in cycles.XML_NAMES.items()}


PATTERNS_PROBE = """
import atexit, os, re, runpy, sys
atexit.register(lambda: open(os.environ["MODULES_OUT"], "w").write(
    "\\n".join(str(key[1]) for key in list(re._cache) if isinstance(key[1], str))))
sys.argv = ["postproc", *os.environ["ARGS"].split("\\n")]
runpy.run_module("postproc", run_name="__main__")
"""
"""Runs a command and writes the text of every regular expression compiled by then (``re``'s cache: ``re.compile``
and ``re.match`` with a text both go through it), one a line."""


def patterns_after(tmp_path: Path, *args: str, ok: bool = True) -> set[str]:
    out = tmp_path / "patterns.txt"
    env = dict(os.environ, HOME=str(tmp_path), MODULES_OUT=str(out), ARGS="\n".join(args))
    done = subprocess.run([sys.executable, "-c", PATTERNS_PROBE], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=120)
    assert (done.returncode == 0) == ok, done.stderr
    return set(out.read_text().splitlines())


def test_a_plain_translation_compiles_no_pattern_of_an_error_report(tmp_path: Path, one_line: Path) -> None:
    """The patterns only an error report, ``--arg``, ``--define`` or ``--transform`` reads are compiled where
    first used (each ``re.compile`` at import cost every start ~0.3-1M instructions); the other side: a
    ``--define`` with a bad name compiles its pattern, so the probe sees what a run compiles."""
    from postproc import context, errors, xmlio
    from postproc.commands import handlers
    from postproc.cycles import resolve
    from postproc.lowering import sequences
    from postproc.transforms import spec
    # (not ``errors._COMMENT``: the same text as ``postproc.output.line_format._COMMENT``, compiled for the writer)
    cold = {errors._ADDRESS, context._WORD_AT, context._COMMENT_AT, xmlio._LIBXML_POSITION,
            resolve._COMMENT, handlers._ARGUMENT, spec._NUMBER, sequences._NAME}
    assert all(isinstance(text, str) for text in cold)  # texts, not patterns compiled at import
    for target in ("grbl", "linuxcnc", "isg", "fagor", "fanuc"):
        compiled = patterns_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", target)
        assert compiled and sorted(cold & compiled) == [], target
    refused = patterns_after(tmp_path, "translate", str(one_line), "--from", "fanuc", "--to", "grbl",
                             "--define", "1x=2", ok=False)
    assert sequences._NAME in refused


COLLECTIONS_PROBE = """
import atexit, gc, os, runpy, sys
seen = []
gc.callbacks.append(lambda phase, info: seen.append(info["generation"])
                    if phase == "start" and "postproc.commands.cli" in sys.modules else None)
atexit.register(lambda: open(os.environ["MODULES_OUT"], "w").write(
    "\\n".join(str(g) for g in seen) + ("\\n" if seen else "") + "\\n".join(sorted(sys.modules))))
sys.argv = ["postproc", *os.environ["ARGS"].split("\\n")]
runpy.run_module("postproc", run_name="__main__")
"""
"""Runs a command and writes the generation of every collection the cyclic collector started once the command
line was imported (``postproc.commands.launch`` imports it with the collector off), until the exit's own, one a
line, then the modules loaded (the probe sees the run)."""


@pytest.mark.parametrize("args", [("translate", "{program}", "--from", "fanuc", "--to", "grbl"),
                                  ("translate", "{program}", "--from", "fanuc", "--to", "linuxcnc"),
                                  ("translate", "{program}", "--from", "fanuc", "--to", "fanuc"),
                                  ("dialects",)])
def test_a_short_run_makes_the_collector_walk_nothing(tmp_path: Path, one_line: Path, args: tuple[str, ...]) -> None:
    """A one-line translation and ``postproc dialects`` load their command's modules, the plugins and the dialects'
    readers, writers and steps with the cyclic collector paused, and freeze what they made
    (``postproc.commands.command_line.FREEZE_IMPORTS``, ``postproc.plugins``, ``postproc.api.translate``): no
    collection runs before the exit's. With the collector on while they loaded, 33 ran in a one-line
    translation (each walking every object the imports had made so far) and 14 in ``postproc dialects``."""
    out = tmp_path / "collections.txt"
    env = dict(os.environ, HOME=str(tmp_path), MODULES_OUT=str(out),
               ARGS="\n".join(arg.format(program=one_line) for arg in args))
    done = subprocess.run([sys.executable, "-c", COLLECTIONS_PROBE], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    lines = out.read_text().splitlines()
    assert "postproc.plugins" in lines  # the probe saw the run
    assert [line for line in lines if line.isdigit()] == []
