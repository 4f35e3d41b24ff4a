"""Every grbl and LinuxCNC program the suite writes is held to its controller's rules.

``install()`` (called by ``conftest.py`` before any test runs) wraps the ``write`` of the grbl and LinuxCNC
writers, the one place their programs are made, so every program written is checked: translations
(``postproc.api.translate``, the command line run in the suite's process), the conformance suite's
generated programs (``postproc.testing``), a writer used on its own. grbl's by ``grbl_rules.grbl_problems``
(grbl 1.1's parser, written from its source), grblHAL's by ``grblhal_rules.grblhal_problems`` (likewise), LinuxCNC's by ``linuxcnc_rules.linuxcnc_problems`` (LinuxCNC's
own interpreter, when it is installed). What a writer writes is unchanged; the problems found are
collected, and ``conftest.py`` fails the test that produced them, with the program. A run with errors
(its output is discarded) is not checked, nor a translation's dry run (``api._keep_check`` writes the rest
of a program that computes to see whether the target can keep it symbolic); nor is a program written back in its own dialect: it is the
input itself (lossless), often a fragment in the suite, and whether a reader refuses what its controller
refuses is tested where the reader is (``test_output_rules.py``, ``test_linuxcnc.py``). Programs written
by another process (``postproc batch`` workers, the command in a subprocess) are compared in their tests
with the same translation made here, which is checked.

rs274 takes about a tenth of a second a program: its answers are kept on disk (``RS274_CACHE``, keyed by
the program, the tool table and the interpreter's file), so a run of the suite pays only for programs
it has not seen before.

A test that writes an invalid program on purpose (to show a checker catches it) calls the checker
directly; nothing here can be switched off by a test.
"""

from __future__ import annotations

import copy
import dataclasses
import re
from typing import Any, Callable, Iterable, TextIO

from postproc.setup.machine_setup import MachineSetup

from .grbl_rules import grbl_problems
from .grblhal_rules import grblhal_problems
from .linuxcnc_rules import available as rs274_available, linuxcnc_problems


def _grbl(text: str, setup: MachineSetup) -> list[str]:
    """Stock grbl 1.1, with M19 and M7 where the set-up says the machine's build has them."""
    return grbl_problems(text, m19=setup.cycles.orientation == "m19", m7=bool(setup.controller.mist_coolant))


def _grblhal(text: str, setup: MachineSetup) -> list[str]:
    """grblHAL, with the build the set-up describes (tool table, spindle encoder, mist coolant, M19, lathe mode)."""
    controller = setup.controller
    return grblhal_problems(text, tool_table=bool(controller.tool_table), spindle_sync=bool(controller.spindle_sync),
                            mist=bool(controller.mist_coolant), m19=setup.cycles.orientation == "m19",
                            lathe=setup.input.machine_type == "lathe")


def _linuxcnc(text: str, setup: MachineSetup) -> list[str]:
    """rs274 on the program, with the user M codes (M100-M199) the set-up declares taken out first: those run
    the machine's own program files, which the standalone interpreter cannot be given (it registers no user
    M code [V: LinuxCNC src/emc/sai/saicanon.cc, USER_DEFINED_FUNCTION all zero, never added to]), so it
    refuses every one; an undeclared one stays and is refused as before."""
    declared = sorted(c.number for c in setup.machine_codes if c.letter == "M" and 100 <= int(c.number) <= 199)
    if declared:
        text = re.sub(rf"(?i)\bM0*({'|'.join(declared)})(?![\d.])", "", text)
    state = machine_state(setup)
    if state:  # (after an opening '%': rs274 takes one only as the program's first line)
        opening = re.match(r"\s*%[^\n]*\n", text)
        at = opening.end() if opening else 0
        text = text[:at] + state + text[at:]
    return linuxcnc_problems(text)


def machine_state(setup: MachineSetup) -> str:
    """The machine the set-up describes, as lines rs274 runs before the program: the reference position G28 goes
    to (``<Axes><Axis home>``, rs274's #5161-#5163, in its machine unit, inches [V: rs274 reads #5161=-100 as
    -2540 mm]) and the work offsets of G54-G59 (``<WorkOffsets>``, by ``G10 L2``, in mm). Empty without them
    (rs274's own: every one zero). The translation's reading and the simulator take the tool there
    (``postproc.ir.state.SetUpPlaces``), so the program is run where they say it runs."""
    mm = setup.machine.mm()
    lines = [f"#{5161 + 'XYZ'.index(a)}=[{t.home * mm!r}/25.4]" for a, t in sorted(setup.travel.items())
             if a in "XYZ" and t.home is not None]
    for number, offset in sorted(setup.work_offsets.items(), key=lambda item: int(item[0])):
        words = " ".join(f"{a}{v * mm!r}" for a, v in offset.axes().items() if a in "XYZ")
        if 1 <= int(number) <= 6 and words:
            lines.append(f"G21 G10 L2 P{number} {words}")
    return "".join(f"{line}\n" for line in lines)


CHECKERS: dict[str, Callable[[str, MachineSetup], list[str]]] = {"grbl": _grbl, "grblhal": _grblhal}
if rs274_available():
    CHECKERS["linuxcnc"] = _linuxcnc

violations: list[str] = []
"""Problems found since the last ``take_violations()``."""
checked = {"grbl": 0, "grblhal": 0, "linuxcnc": 0}
"""How many distinct outputs were checked per target (for the report at the end of a run)."""
_seen: dict[tuple[object, ...], list[str]] = {}
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


def problems(target: str, text: str, setup: MachineSetup, source: str | None = None) -> list[str]:
    """What ``target``'s controller refuses in ``text`` (nothing for a target without a checker). ``source``:
    the dialect ``text`` was translated from; the target runs on the source's machine, so a program a lathe-only
    dialect read (GSK) is checked in the target's lathe mode whatever type the set-up names, as ``translate``
    writes it and ``verify`` reads it."""
    checker = CHECKERS.get(target)
    if checker is None:
        return []
    if source is not None and setup.input.machine_type != "lathe":
        registry = _registry()  # (a writer's own DIALECT, e.g. the neutral IR's, is no installed dialect)
        if source in registry.dialects and registry.dialect(source).reads_lathe(setup):
            setup = copy.copy(setup)
            setup.input = dataclasses.replace(setup.input, machine_type="lathe")
    controller = setup.controller
    key = (target, text, setup.input.machine_type, setup.cycles.orientation, controller.mist_coolant, controller.tool_table,
           controller.spindle_sync, tuple(setup.machine_codes))
    found = _seen.get(key)
    if found is None:
        found = _seen[key] = checker(text, setup)
        checked[target] += 1
    return found


_REGISTRY: list[Any] = []
"""The default registry, as ``install`` found it: a test that puts the global one out of reach (to show a run
uses its own) does not meet it in the check."""


def _registry() -> Any:
    if not _REGISTRY:
        from postproc.plugins import default_registry
        _REGISTRY.append(default_registry())
    return _REGISTRY[0]


def _check(target: str, text: str, setup: MachineSetup, source: str | None = None) -> None:
    found = problems(target, text, setup, source=source)  # (a GSK program's grblHAL output runs in lathe mode)
    if found:
        listing = "\n".join(f"{n:4} | {line}" for n, line in enumerate(text.splitlines(), 1))
        violations.append(f"{target} output its controller refuses:\n  " + "\n  ".join(found)
                          + f"\n--- the {target} program ---\n{listing}")


def install() -> None:
    """Wrap the ``write`` of the writers whose controllers have a checker (once)."""
    registry = _registry()
    for name in CHECKERS:
        writer = registry.dialects[name].WRITER if name in registry.dialects else None
        if writer is not None:
            _wrap(writer)


def _wrap(cls: type[Any]) -> None:
    real = cls.write
    if getattr(real, "checks_output_rules", False):
        return

    def write(self: Any, blocks: Iterable[Any], out: TextIO) -> None:
        tee = _Tee(out)
        real(self, blocks, tee)  # raises on failure: nothing to check
        target = self.target.NAME if self.target is not None else self.DIALECT
        if (target in CHECKERS and self.source_dialect != target and not self._failed()
                and not self.ctx.run_data.get("dry_run")):  # (a translation's trial of keeping a program symbolic)
            _check(target, "".join(tee.parts), self.ctx.setup, self.source_dialect)

    write.checks_output_rules = True  # type: ignore[attr-defined]
    cls.write = write


def take_violations() -> list[str]:
    found = violations[:]
    violations.clear()
    return found
