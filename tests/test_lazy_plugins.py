"""Dialects registered without importing their modules: a ``Lazy`` reader and writer, syntax objects
registered by name (``XFactory.register_lazy``), pipelines built in Python. What a run does not use it
does not import (``tests/test_startup_imports.py``), yet every dialect and element name is known, and
each is imported the moment something reads it."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from postproc.dialect import Dialect, Lazy, Reader
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup

ROOT = Path(__file__).resolve().parents[1]
SHIPPED = ("fanuc", "gsk", "isg", "fagor", "grbl", "linuxcnc", "mach3")

PACKAGE = {
    "__init__.py": '''
from postproc.dialect import Dialect, Lazy, Reader
from postproc.output.writer_base import Writer

class Toy(Dialect):
    NAME = "lazytoy"
    READER = Lazy[type[Reader]](".reader:ToyReader")
    WRITER = Lazy[type[Writer]]("postproc.rs274.writer:WordWriter")
    TAPE_MARKS = True
''',
    "reader.py": '''
from postproc.dialect import Reader

IMPORTED = True

class ToyReader(Reader):
    def read(self, lines):
        return iter(())
''',
    "other.py": '''
from . import Toy

class Sub(Toy):
    NAME = "lazysub"
''',
}


@pytest.fixture
def toy_package(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> str:
    name = f"lazytoy_{tmp_path.name.replace('-', '_')}"
    (tmp_path / name).mkdir()
    for file, text in PACKAGE.items():
        (tmp_path / name / file).write_text(text)
    monkeypatch.syspath_prepend(str(tmp_path))
    yield name
    for module in [m for m in sys.modules if m == name or m.startswith(name + ".")]:
        del sys.modules[module]


def test_a_lazy_attribute_is_imported_when_first_read(toy_package: str) -> None:
    import importlib
    toy = importlib.import_module(toy_package).Toy
    assert f"{toy_package}.reader" not in sys.modules
    assert toy.capabilities()["TAPE_MARKS"] is True and f"{toy_package}.reader" not in sys.modules
    reader = toy.READER
    assert reader is sys.modules[f"{toy_package}.reader"].ToyReader and issubclass(reader, Reader)
    assert toy.READER is reader  # imported once
    from postproc.rs274.writer import WordWriter
    assert toy.WRITER is WordWriter


def test_a_relative_target_is_relative_to_the_class_that_set_it(toy_package: str) -> None:
    """A subclass in another module (here a submodule) reads the same reader."""
    import importlib
    sub = importlib.import_module(f"{toy_package}.other").Sub
    assert sub.READER is importlib.import_module(f"{toy_package}.reader").ToyReader


def test_a_lazy_attribute_that_cannot_be_imported_says_so(toy_package: str) -> None:
    class Broken(Dialect):
        NAME = "broken"
        READER = Lazy[type[Reader]]("no_such_package_anywhere.reader:Nope")

    with pytest.raises(ModuleNotFoundError, match="no_such_package_anywhere"):
        Broken.READER
    assert repr(vars(Broken)["READER"]) == "Lazy('no_such_package_anywhere.reader:Nope')"


@pytest.mark.parametrize("name", SHIPPED)
def test_every_shipped_dialect_reads_and_writes_through_its_lazy_classes(name: str) -> None:
    from postproc.output.writer_base import Writer
    dialect = default_registry().dialect(name)
    assert dialect.READER is not None and issubclass(dialect.READER, Reader)
    assert dialect.WRITER is not None and issubclass(dialect.WRITER, Writer)
    assert dialect.pipeline(MachineSetup()).steps


REGISTRY_PROBE = """
import json, sys
from postproc.plugins import default_registry
from postproc.syntaxes.syntax import load_pipeline
registry = default_registry()
before = sorted(m for m in sys.modules if m.startswith(("dialects.", "postproc_")))
names = registry.factory.names()
pipeline = load_pipeline(sys.argv[1])
print(json.dumps({"dialects": sorted(registry.dialects), "names": names, "before": before,
                  "steps": [type(s).__module__ + ":" + type(s).__name__ for s in pipeline.steps],
                  "after": sorted(m for m in sys.modules if m.startswith(("dialects.", "postproc_")))}))
"""


def test_every_name_is_registered_and_imported_when_a_file_uses_it(tmp_path: Path) -> None:
    """In a fresh interpreter: the registry knows every dialect and every syntax object's element name
    without importing their modules; a pipeline file naming Fagor's steps imports exactly those."""
    pipeline = tmp_path / "fagor.xml"
    pipeline.write_bytes((ROOT / "dialects/fagor/fagor.xml").read_bytes())
    done = subprocess.run([sys.executable, "-c", REGISTRY_PROBE, str(pipeline)], capture_output=True, text=True,
                          timeout=120, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    seen = json.loads(done.stdout)
    assert set(SHIPPED) <= set(seen["dialects"])
    assert {"FanucBlockSyntax", "FanucLatheBlockSyntax", "FanucProgramSyntax", "GskBlockSyntax", "IsgBlockSyntax",
            "IsgProgramSyntax", "FagorBlockSyntax", "FagorProgramSyntax", "GrblBlockSyntax", "NgcBlockSyntax",
            "LinuxcncProgramSyntax", "Mach3BlockSyntax"} <= set(seen["names"])
    heavy = ("reader", "writer", "block_syntax", "program", "lathe_block_syntax")
    assert [m for m in seen["before"] if m.rpartition(".")[2] in heavy] == []
    assert seen["steps"][:2] == ["dialects.fagor.program:FagorProgramSyntax",
                                 "dialects.fagor.block_syntax:FagorBlockSyntax"]
    assert {"dialects.fagor.program", "dialects.fagor.block_syntax"} <= set(seen["after"])
    assert "dialects.isg.block_syntax" not in seen["after"]


def test_an_unknown_element_is_still_a_located_error(tmp_path: Path) -> None:
    from postproc.errors import ConfigError
    from postproc.syntaxes.syntax import load_pipeline
    path = tmp_path / "p.xml"
    path.write_text('<Pipeline dialect="fagor">\n  <FagorBlockSyntax/>\n  <FagorBlockSyntaks/>\n</Pipeline>\n')
    with pytest.raises(ConfigError) as info:
        load_pipeline(path)
    assert str(info.value) == f"{path}:3:1: error: unknown element <FagorBlockSyntaks>"
