"""Every grbl and LinuxCNC program the suite writes is held to its controller's rules.

``install()`` (called by ``conftest.py`` before anything imports ``postproc.cli``) wraps
``postproc.api.translate`` so that each translation that succeeds with grbl or LinuxCNC as its target
between two dialects is checked: grbl's by ``grbl_rules.grbl_problems`` (grbl 1.1's parser, written from its source), LinuxCNC's
by ``linuxcnc_rules.linuxcnc_problems`` (LinuxCNC's own interpreter, when it is installed). What a
translation writes is unchanged; the problems found are collected, and ``conftest.py`` fails the test that
produced them, with the program. Translations whose target is another dialect, and failed ones (their
output is discarded), are not checked; nor is a program written back in its own dialect: it is the input
itself (lossless), often a fragment in the suite, and whether a reader refuses what its controller
refuses is tested where the reader is (``test_output_rules.py``, ``test_linuxcnc.py``).

A test that writes an invalid program on purpose (to show a checker catches it) calls the checker
directly; nothing here can be switched off by a test.
"""

from __future__ import annotations

import functools
from typing import Any, Callable, TextIO

import postproc.api
from postproc.setup import MachineSetup

from .grbl_rules import grbl_problems
from .linuxcnc_rules import available as rs274_available, linuxcnc_problems


def _grbl(text: str, setup: MachineSetup) -> list[str]:
    """Stock grbl 1.1, with M19 where the set-up says the machine has it."""
    return grbl_problems(text, m19=setup.cycles.orientation == "m19")


def _linuxcnc(text: str, setup: MachineSetup) -> list[str]:
    return linuxcnc_problems(text)


CHECKERS: dict[str, Callable[[str, MachineSetup], list[str]]] = {"grbl": _grbl}
if rs274_available():
    CHECKERS["linuxcnc"] = _linuxcnc

violations: list[str] = []
"""Problems found since the last ``take_violations()``."""
checked = {"grbl": 0, "linuxcnc": 0}
"""How many distinct outputs were checked per target (for the report at the end of a run)."""
_seen: dict[tuple[str, str, str], list[str]] = {}
"""Outputs already checked (fuzzing writes the same program many times), with their problems."""


class _Tee:
    """Passes writes through to the real output and keeps a copy."""

    def __init__(self, out: TextIO) -> None:
        self.out = out
        self.parts: list[str] = []

    def write(self, text: str) -> int:
        self.parts.append(text)
        return self.out.write(text)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.out, name)


def problems(target: str, text: str, setup: MachineSetup) -> list[str]:
    """What ``target``'s controller refuses in ``text`` (nothing for a target without a checker)."""
    checker = CHECKERS.get(target)
    if checker is None:
        return []
    key = (target, text, setup.cycles.orientation)
    found = _seen.get(key)
    if found is None:
        found = _seen[key] = checker(text, setup)
        checked[target] += 1
    return found


def _check(target: str, text: str, setup: MachineSetup) -> None:
    found = problems(target, text, setup)
    if found:
        listing = "\n".join(f"{n:4} | {line}" for n, line in enumerate(text.splitlines(), 1))
        violations.append(f"{target} output its controller refuses:\n  " + "\n  ".join(found)
                          + f"\n--- the {target} program ---\n{listing}")


def install() -> None:
    """Wrap ``postproc.api.translate`` (once)."""
    real = postproc.api.translate
    if getattr(real, "checks_output_rules", False):
        return

    @functools.wraps(real)
    def translate(lines: Any, out: TextIO, **kwargs: Any) -> Any:
        target = kwargs.get("target", "")
        if target not in CHECKERS or kwargs.get("source") == target:
            return real(lines, out, **kwargs)
        tee = _Tee(out)
        result = real(lines, tee, **kwargs)  # raises on failure: nothing to check
        _check(target, "".join(tee.parts), kwargs.get("setup") or MachineSetup())
        return result

    translate.checks_output_rules = True  # type: ignore[attr-defined]
    postproc.api.translate = translate  # type: ignore[assignment]


def take_violations() -> list[str]:
    found = violations[:]
    violations.clear()
    return found
