"""Shared fixtures. Keep this file small: helpers that one test module needs live in that module."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import os
import sys

import pytest
from hypothesis import HealthCheck, settings

# pytest rewrites the asserts of every test module as it imports it and keeps the result beside it
# (tests/__pycache__/*-pytest-*.pyc) only where Python may write byte code: under PYTHONDONTWRITEBYTECODE (set on
# this machine and in CI) every xdist worker of every run rewrote all ~330 modules again, about two thirds of the
# collection's CPU (cProfile of `pytest --collect-only`). This conftest is imported before any test module, so
# from here on the rewritten modules are cached (keyed on each source's mtime and size; written atomically, so two
# workers may race). The tree already gets .pyc files for the core from `make bytecode`.
sys.dont_write_bytecode = False

# No per-example deadline nor too-slow health check: the suite shares two cores with other work, and a
# first example that pays for an import or the plugin registry took over hypothesis's default 200 ms on a
# loaded machine (and generating examples got "too slow"), failures that say nothing about the code. Slowness is measured in benchmarks, not asserted in tests.
SLOW = [HealthCheck.too_slow]  # generating examples on a loaded machine is slow: the same cause
settings.register_profile("ci", derandomize=True, print_blob=True, deadline=None, suppress_health_check=SLOW)
settings.register_profile("local", deadline=None, suppress_health_check=SLOW)
# CI runs the same examples every time: a red CI then always means a change, never luck.
# Local runs keep exploring new examples.
settings.load_profile("ci" if os.environ.get("CI") else "local")

from tests.support import output_rules

output_rules.install()  # every grbl and LinuxCNC program the suite writes is checked: see output_rules
from postproc.commands.cli import main  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


@dataclass
class CliResult:
    status: int
    out: bytes
    err: str

    @property
    def err_lines(self) -> list[str]:
        return self.err.splitlines()


@pytest.fixture
def cli(capsysbinary: pytest.CaptureFixture[bytes]) -> Callable[..., CliResult]:
    """Run ``postproc ARGS...`` in this process: exit status, stdout bytes, stderr text."""

    def run(*args: object) -> CliResult:
        capsysbinary.readouterr()
        try:
            status = main([str(a) for a in args])
        except SystemExit as exc:  # argparse reports wrong usage by exiting
            status = exc.code if isinstance(exc.code, int) else 2
        captured = capsysbinary.readouterr()
        return CliResult(status, captured.out, captured.err.decode("utf-8", "replace"))

    return run


@pytest.fixture
def root() -> Path:
    """The repository root (examples/, tests/golden/)."""
    return ROOT


@pytest.fixture(autouse=True)
def _outputs_valid_on_their_controllers() -> object:
    """Fail a test whose grbl or LinuxCNC translations their controller would refuse (``output_rules``)."""
    output_rules.take_violations()
    yield
    found = output_rules.take_violations()
    assert not found, "\n\n".join(found)


ONE_BUILD = "one_build"
"""The marker of a test whose run is the same in both builds: it exercises no compiled module (a scan of the
sources, of the benchmark harness). ``make test`` runs the suite against the compiled build and then the pure
one; the second pass (``POSTPROC_SECOND_BUILD=1``) skips these: the first proved all they prove. The reason
is required, and says why the build cannot matter."""


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", f"{ONE_BUILD}(reason): the same in both builds; make test's second pass skips it")


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    second = os.environ.get("POSTPROC_SECOND_BUILD", "") not in ("", "0")
    for item in items:
        marker = item.get_closest_marker(ONE_BUILD)
        if marker is None:
            continue
        reason = marker.kwargs.get("reason", "")
        if not reason:
            raise pytest.UsageError(f"{item.nodeid}: {ONE_BUILD} needs a reason= saying why the build cannot matter")
        if second:
            item.add_marker(pytest.mark.skip(reason=f"the same in both builds, run in make test's first pass: {reason}"))


def pytest_sessionfinish(session: pytest.Session) -> None:
    """An xdist worker hands its counts to the controller, which prints the sum (``pytest_testnodedown``)."""
    workeroutput = getattr(session.config, "workeroutput", None)
    if workeroutput is not None:
        workeroutput["outputs_checked"] = dict(output_rules.checked)


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node: object, error: object) -> None:
    for target, n in getattr(node, "workeroutput", {}).get("outputs_checked", {}).items():
        output_rules.checked[target] = output_rules.checked.get(target, 0) + n


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    counts = ", ".join(f"{n} {target}" for target, n in output_rules.checked.items())
    terminalreporter.write_line(f"outputs checked against their controller's rules: {counts}")
    # a failure log then says whether its examples can be drawn again (CI) or were new ones
    examples = "derandomized (CI is set)" if settings.default.derandomize else "random (CI is not set)"
    terminalreporter.write_line(f"hypothesis examples: {examples}")
