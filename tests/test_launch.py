"""The command's process (``postproc.commands.launch``): the collector is off only while the modules load, runs
during the command, and what the imports and the command made is frozen; the exit status is main's."""

from __future__ import annotations

import gc
import subprocess
import sys
from pathlib import Path

import pytest

from postproc.commands import cli, launch


@pytest.fixture
def collector_restored():
    enabled = gc.isenabled()
    yield
    gc.unfreeze()
    (gc.enable if enabled else gc.disable)()


@pytest.mark.parametrize("status", [0, 1, 2])
def test_run_collects_during_the_command_and_exits_with_its_status(monkeypatch, collector_restored, status):
    seen: dict[str, object] = {}

    def main() -> int:
        seen["enabled"] = gc.isenabled()
        seen["frozen"] = gc.get_freeze_count()
        seen["made"] = [status]  # alive at the end: frozen then, so no generation holds it
        return status

    monkeypatch.setattr(cli, "main", main)
    gc.enable()
    gc.unfreeze()
    with pytest.raises(SystemExit) as ended:
        launch.run()
    assert ended.value.code == status
    assert seen["enabled"] is True  # a long interpreted program's cyclic garbage is still collected
    assert isinstance(seen["frozen"], int) and seen["frozen"] > 0  # the imports' objects are frozen
    made = seen["made"]
    assert not any(obj is made for obj in gc.get_objects())  # what the command left is frozen too
    assert gc.isenabled()


def test_run_leaves_a_disabled_collector_disabled(monkeypatch, collector_restored):
    monkeypatch.setattr(cli, "main", lambda: 0)
    gc.disable()
    with pytest.raises(SystemExit):
        launch.run()
    assert not gc.isenabled()


def test_python_m_postproc_is_the_launcher(tmp_path: Path):
    """``python -m postproc`` exits with the command's status (2: a usage error) and writes its output."""
    src = tmp_path / "a.nc"
    src.write_text("G0 X1.\n")
    done = subprocess.run([sys.executable, "-m", "postproc", "translate", str(src), "--from", "fanuc",
                           "--to", "linuxcnc"], check=False, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "X1." in done.stdout
    wrong = subprocess.run([sys.executable, "-m", "postproc", "translate", str(src), "--from", "nosuch",
                            "--to", "linuxcnc"], check=False, capture_output=True, text=True)
    assert wrong.returncode == 2
    assert "nosuch" in wrong.stderr


STAND_IN_PROBE = """
import json, sys
from postproc.commands import launch
launch._inspect_when_read()
from lxml import etree
quiet = sorted(m for m in ("ast", "dis", "tokenize") if m in sys.modules)  # inspect not imported with lxml


class Target:
    def __init__(self):
        self.seen = []

    def start(self, tag, attrib, nsmap):  # lxml passes nsmap where getfullargspec shows a third argument
        self.seen.append([tag, dict(nsmap)])

    def close(self):
        return self.seen


seen = etree.fromstring('<a xmlns:p="urn:p"><b/></a>', etree.XMLParser(target=Target()))
from inspect import getfullargspec  # (the real module's now)
import inspect
samples = [lambda a, *b, c=1, **d: 0, Target.start, len, print]
def spec(f):
    try:
        return repr(getfullargspec(f))
    except TypeError as exc:
        return "TypeError: " + str(exc)
print(json.dumps([quiet, seen, "ast" in sys.modules, sys.modules["inspect"].getfullargspec is inspect.getfullargspec,
                  [spec(f) for f in samples]]))
"""


def test_lxml_imports_without_inspect_and_its_parser_targets_work_as_with_it() -> None:
    """``lxml.etree`` binds ``inspect.getfullargspec`` as it loads: the stand-in's own function, so loading it imports
    no ``inspect``; called (a parser target's ``start``), it gives the real function's answer: here the namespace
    map lxml passes to a ``start`` of three arguments."""
    done = subprocess.run([sys.executable, "-c", STAND_IN_PROBE], capture_output=True, text=True, timeout=120,
                          check=False)
    assert done.returncode == 0, done.stderr
    import inspect
    import json
    quiet, seen, imported, same, specs = json.loads(done.stdout)
    assert quiet == []
    assert seen == [["a", {"p": "urn:p"}], ["b", {}]]  # (the namespaces an element declares)
    assert imported and same  # the call imported the real module, whose names the stand-in then holds

    def spec(f: object) -> str:
        try:
            return repr(inspect.getfullargspec(f))  # type: ignore[arg-type]
        except TypeError as exc:
            return "TypeError: " + str(exc)
    assert specs[0] == spec(lambda a, *b, c=1, **d: 0)
    assert specs[2:] == [spec(len), spec(print)]
