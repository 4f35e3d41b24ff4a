"""A compiled base class must read a plugin subclass's class attributes, as the pure build does.

mypyc compiles a class attribute declared without ``ClassVar`` (``DIALECT = ""``) into a native instance
slot, set from the base's own class body when an instance is made: an interpreted subclass's
``DIALECT = "linuxcnc"`` is then never read by the compiled base (the LinuxCNC reader compiled this way
read no o-words: 419 failures in the compiled suite, a green pure suite). ``ClassVar`` (or ``Final``)
keeps it a class attribute, read through ``self``. These tests hold every compiled class that allows
interpreted subclasses to that: statically in both builds, and on the compiled types themselves."""

from __future__ import annotations

import ast
import functools
import importlib
import tomllib
from pathlib import Path
from typing import Iterator

import pytest

from postproc import native

ROOT = Path(__file__).resolve().parents[1]
STATIC = pytest.mark.one_build(reason="a scan of the source files (ast): the compiled types are looked at below")
HOT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["postproc"]["compiled"]


@functools.cache
def _all_classes() -> tuple[tuple[ast.ClassDef, str], ...]:
    """Every class of the core, dialects and plugins, with its source, in file order: parsed once for
    the scans below (each parsed every file again, twice for one of them: ~8 s of CPU between them)."""
    return tuple((node, str(path.relative_to(ROOT)))
                 for folder in ("postproc", "dialects", "plugins") for path in sorted((ROOT / folder).rglob("*.py"))
                 for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))) if isinstance(node, ast.ClassDef))


@pytest.fixture(autouse=True, scope="module")
def _parsed_once() -> Iterator[None]:
    """Drops the parsed sources after this file's tests: kept, their million objects made every later
    collection of the cyclic garbage collector in the worker walk them (tests/test_no_cycles_per_block.py's
    ``gc.collect()`` took 4 s instead of 0.1 s)."""
    yield
    _all_classes.cache_clear()


def _classes() -> dict[str, tuple[ast.ClassDef, str]]:
    """Every class of the core, dialects and plugins by name (the first one of a name wins: names used
    as bases here are unique), with its source."""
    found: dict[str, tuple[ast.ClassDef, str]] = {}
    for node, source in _all_classes():
        found.setdefault(node.name, (node, source))
    return found


def _declared(cls: ast.ClassDef, name: str) -> str | None:
    """How ``cls``'s own body declares ``name``: 'class' (ClassVar or Final), 'instance' (annotated
    otherwise), 'bare' (assigned, not annotated), None (not at all)."""
    for st in cls.body:
        if isinstance(st, ast.AnnAssign) and isinstance(st.target, ast.Name) and st.target.id == name:
            text = ast.unparse(st.annotation)
            return "class" if "ClassVar" in text or "Final" in text else "instance"
        if isinstance(st, ast.Assign) and any(isinstance(t, ast.Name) and t.id == name for t in st.targets):
            return "bare"
    return None


def _first_declaration(cls: ast.ClassDef, name: str, classes: dict[str, tuple[ast.ClassDef, str]]) -> str | None:
    """The declaration mypy takes for ``name`` in ``cls``: its own annotation, else its bases'."""
    own = _declared(cls, name)
    if own in ("class", "instance"):
        return own
    for base in cls.bases:
        found = classes.get(ast.unparse(base).rsplit(".", 1)[-1])
        if found is not None:
            inherited = _first_declaration(found[0], name, classes)
            if inherited is not None:
                return inherited
    return own


def _compiled_open_classes() -> list[tuple[ast.ClassDef, str]]:
    """The classes of the compiled modules that allow interpreted subclasses (plugins extend them);
    protocols are no native classes (they only declare)."""
    hot = set(HOT)
    return [(node, source) for node, source in _all_classes() if source in hot and any(
            "allow_interpreted_subclasses=True" in ast.unparse(d) for d in node.decorator_list)
            and not any(ast.unparse(b).endswith("Protocol") for b in node.bases)]


@STATIC
def test_constants_of_open_compiled_classes_are_class_attributes() -> None:
    """An UPPER_CASE attribute of a compiled class that plugins subclass is declared ``ClassVar`` or
    ``Final`` (here or in a base), never a bare or annotated instance default."""
    classes = _classes()
    wrong = []
    for cls, source in _compiled_open_classes():
        for st in cls.body:
            names = [t.id for t in st.targets if isinstance(t, ast.Name)] if isinstance(st, ast.Assign) else \
                [st.target.id] if isinstance(st, ast.AnnAssign) and isinstance(st.target, ast.Name) \
                and st.value is not None else []
            for name in names:
                if name.isupper() and not name.startswith("__"):
                    kind = _first_declaration(cls, name, classes)
                    if kind != "class":
                        wrong.append(f"{source}: {cls.name}.{name} ({kind})")
    assert not wrong, "declare these ClassVar (compiled, a subclass's value is not read):\n" + "\n".join(wrong)


@STATIC
def test_the_scan_finds_a_bare_constant() -> None:
    """The scan above flags the declaration that broke the compiled LinuxCNC reader."""
    tree = ast.parse("class Base:\n    X: ClassVar[int] = 1\nclass R(Base):\n    DIALECT = ''\n    X = 2\n")
    classes = {node.name: (node, "t.py") for node in tree.body if isinstance(node, ast.ClassDef)}
    reader = classes["R"][0]
    assert _first_declaration(reader, "DIALECT", classes) == "bare"
    assert _first_declaration(reader, "X", classes) == "class"


def _inherits(cls: ast.ClassDef, base: str, classes: dict[str, tuple[ast.ClassDef, str]], depth: int = 0) -> bool:
    """``cls`` derives from the class named ``base`` (bases resolved by name in ``classes``)."""
    for b in cls.bases:
        name = ast.unparse(b).rsplit(".", 1)[-1]
        if name == base:
            return True
        found = classes.get(name)
        if found is not None and found[0] is not cls and depth < 20 and _inherits(found[0], base, classes, depth + 1):
            return True
    return False


def _static_names(cls: ast.ClassDef) -> set[str]:
    """The static and class methods ``cls``'s own code calls through ``self`` (``self.helper()``)."""
    statics = {f.name for f in cls.body if isinstance(f, ast.FunctionDef)
               and any(ast.unparse(d) in ("staticmethod", "classmethod") for d in f.decorator_list)}
    called = {node.func.attr for node in ast.walk(cls) if isinstance(node, ast.Call)
              and isinstance(node.func, ast.Attribute) and isinstance(node.func.value, ast.Name)
              and node.func.value.id == "self"}
    return statics & called


@STATIC
def test_no_subclass_overrides_a_static_method_of_an_open_compiled_class() -> None:
    """Compiled, ``self.helper()`` of a static (or class) method calls the base's own function directly: a
    plugin's override is never reached (LinuxCNC's ``_path_tolerance`` read no ``G64 P Q`` so). Such a
    helper a subclass overrides must be a plain method."""
    classes = _classes()
    everything = _all_classes()
    wrong = []
    for cls, source in _compiled_open_classes():
        statics = _static_names(cls)
        if not statics:
            continue
        for sub, where in everything:
            if _inherits(sub, cls.name, classes):
                for f in sub.body:
                    if isinstance(f, ast.FunctionDef) and f.name in statics:
                        wrong.append(f"{where}: {sub.name}.{f.name} overrides {source}: {cls.name}.{f.name}")
    assert not wrong, "\n".join(wrong)


@STATIC
def test_the_scan_finds_an_overridden_static_method() -> None:
    tree = ast.parse("class Base:\n    @staticmethod\n    def helper() -> None: ...\n"
                     "    def run(self) -> None:\n        self.helper()\n"
                     "class Mid(Base): ...\nclass Plugin(Mid):\n    def helper(self) -> None: ...\n")
    classes = {node.name: (node, "t.py") for node in tree.body if isinstance(node, ast.ClassDef)}
    assert _static_names(classes["Base"][0]) == {"helper"}
    assert _inherits(classes["Plugin"][0], "Base", classes) and not _inherits(classes["Base"][0], "Plugin", classes)


@pytest.mark.skipif(not native.compiled_modules(), reason="pure Python: no compiled types to look at")
def test_compiled_types_keep_no_constant_in_an_instance_slot() -> None:
    """On the compiled types: an UPPER_CASE name of an open class is no native attribute (a getset
    descriptor on the type), and the LinuxCNC reader sees its own values."""
    for cls, source in _compiled_open_classes():
        module = importlib.import_module(source.removesuffix(".py").replace("/", "."))
        compiled_type = getattr(module, cls.name)
        for klass in compiled_type.__mro__:
            for name, value in vars(klass).items():
                if name.isupper():
                    assert type(value).__name__ != "getset_descriptor", f"{cls.name}.{name} is an instance slot"
    from postproc_linuxcnc.reader import LinuxcncReader
    from postproc.context import Context
    from postproc.errors import Diagnostics
    from postproc.setup.machine_setup import MachineSetup
    diagnostics = Diagnostics()
    reader = LinuxcncReader(Context("t.ngc", MachineSetup(), diagnostics, "linuxcnc"))
    block = next(iter(reader.read(["o100 sub\n"])))
    assert not diagnostics.errors and "Control" in block.sections, (diagnostics.errors, block.sections)
