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
