"""Capability probes: a neutral program per capability flag, and what the writer must do with it.

A flag that says the controller has a feature promises that the writer spells it (and, for a dialect
that reads, that the text reads back as the same feature); a flag that says it lacks one promises that
the construct never reaches the writer's output: it is refused at its line, or lowered into something
else first. A probe that reaches the writer and is written anyway is a flag that lies.
"""

from __future__ import annotations

import copy

import io
from dataclasses import dataclass
from typing import Any, Callable

from ..api import read_program
from ..interp.control import Assign
from ..cycles.section import CannedCycle
from ..dialect import Dialect
from ..errors import ErrorList
from ..ir.expr import Binary, Num, Var
from ..ir import (
    CutterCompensation, Dwell, Feed, Motion, Section, SpindleControl, SpindleOrientation, SpindleSpeed, ToolChange,
    ToolLengthOffset, ToolSelect,
)
from ..setup.machine_setup import MachineSetup
from .neutral import NeutralProgram, Op, cycle_rules, drill_cycle, write_neutral

PROBE_LINE = 3
"""The probe's block: after the prologue (units, plane, distance mode) and the first rapid."""
START = {"X": 0.0, "Y": 0.0, "Z": 50.0}


@dataclass
class Probe:
    flag: str
    """The capability the probe tests (an UPPER_CASE attribute of ``Dialect``)."""
    what: str
    section: str
    """The section key that carries the feature to the writer."""
    ops: Callable[[type[Dialect]], list[Op]]
    present: Callable[[type[Dialect]], bool]
    """Whether the flag says the dialect has the feature."""
    only_present: bool = False
    """Probe only a dialect that has the feature: without it the construct never reaches the writer
    (a program that computes is executed while it is read, for such a target)."""
    read_back: bool = True
    """Read the written text back and find the feature (False: only that the writer spells it)."""


def _ops(*sections: Section) -> Callable[[type[Dialect]], list[Op]]:
    return lambda dialect: [("section", *sections)]


CYCLE_KINDS: dict[str, dict[str, float]] = {
    "drill": {}, "peck_deep": {"q": 3.5}, "peck_chip": {"q": 2.0}, "bore_feed": {},
}
"""Hole cycles probed against ``NATIVE_CYCLES``, with the words each needs besides X Y Z R F (G83's Q makes
whole pecks of the 7 from R to Z: SINUMERIK's CYCLE83 is read only so, ``dialects/siemens/deep_hole.py``; cycles
with a dwell are left out: their P word is spelt in the reading dialect's unit, which a neutral
program has none of)."""
SPELT_ONLY = ("drill_dwell", "tap", "tap_left", "bore_stop", "bore_manual", "bore_dwell_feed")
"""The other milling hole cycles without a shift: a dialect that lists one in ``NATIVE_CYCLES`` must at
least spell it (its code table has a row), or a translation that keeps it native fails at the writer.
(The shifting G76/G87 need an orientation and levels a neutral probe does not make.)"""
SPELT_DWELL = frozenset(("drill_dwell", "bore_stop", "bore_dwell_feed"))
"""Of those, the ones RS274/NGC runs only with a dwell P (rs274: "Dwell time p word missing with g82",
g86, g89): their probe has one, so that what is written runs. Only its spelling is probed, not its unit."""
TURNING = {"tap": "cw", "tap_left": "ccw", "bore_stop": "cw"}
"""Cycles RS274/NGC runs only with the spindle turning (rs274: "Spindle not turning in G84", G74, G86): their
probe's block starts it, in a tap's direction."""


def _cycle(kind: str) -> Callable[[type[Dialect]], list[Op]]:
    def ops(dialect: type[Dialect]) -> list[Op]:
        extra = CYCLE_KINDS.get(kind, {})
        dwell = 1.0 if kind in SPELT_DWELL else extra.get("dwell")
        cycle = drill_cycle(kind, START, (10.0, 10.0), bottom=-5.0, r=2.0, feed=100.0,
                            semantics=cycle_rules(dialect), q=extra.get("q"), dwell=dwell)
        turning = TURNING.get(kind)
        if turning is None:
            return [("cycle", cycle)]
        return [("cycle", cycle, SpindleSpeed(500.0), SpindleControl(turning))]
    return ops


def _program_ops(dialect: type[Dialect]) -> list[Op]:
    var = Var(Num(501.0))
    axes: dict[str, Any] = {"X": Binary("add", var, Num(1.0))}
    return [("section", Assign([(var, Num(12.5))])), ("section", Motion("linear", axes), Feed(100.0))]


def _flag(name: str) -> Callable[[type[Dialect]], bool]:
    return lambda dialect: bool(getattr(dialect, name))


PROBES: tuple[Probe, ...] = (
    Probe("CUTTER_COMPENSATION", "cutter radius compensation (left, register 1)", "CutterCompensation",
          _ops(CutterCompensation("left", 1), Motion("linear", {"X": 10.0}), Feed(100.0)), _flag("CUTTER_COMPENSATION")),
    Probe("TOOL_LENGTH_OFFSET", "a tool length offset from register 1", "ToolLengthOffset",
          _ops(ToolLengthOffset("positive", 1), Motion("rapid", {"Z": 40.0})), _flag("TOOL_LENGTH_OFFSET")),
    Probe("SPINDLE_ORIENTATION", "an oriented spindle stop", "SpindleOrientation",
          _ops(SpindleOrientation(0.0)), _flag("SPINDLE_ORIENTATION")),
    Probe("TOOL_CHANGER", "a tool change (tool 2)", "ToolChange", _ops(ToolSelect(2), ToolChange()),
          _flag("TOOL_CHANGER")),
    Probe("DWELL_UNIT", "a dwell of 1.5 s", "Dwell", _ops(Dwell(1.5)), lambda d: True),
    Probe("PROGRAMS", "a variable and an expression (#501 = 12.5, X[#501 + 1])", "Assign", _program_ops,
          _flag("PROGRAMS"), only_present=True),
    *(Probe("NATIVE_CYCLES", f"the {kind} cycle", "CannedCycle", _cycle(kind),
            lambda d, kind=kind: kind in d.NATIVE_CYCLES)  # type: ignore[misc]
      for kind in CYCLE_KINDS),
    *(Probe("NATIVE_CYCLES", f"the {kind} cycle", "CannedCycle", _cycle(kind),
            lambda d, kind=kind: kind in d.NATIVE_CYCLES, only_present=True, read_back=False)  # type: ignore[misc]
      for kind in SPELT_ONLY),
)


def probe_problems(dialect: type[Dialect], probe: Probe, setup: MachineSetup) -> list[str]:
    """What is wrong between ``probe.flag`` and what the writer does with the probe."""
    has = probe.present(dialect)
    if probe.only_present and not has:
        return []
    program = NeutralProgram(probe.ops(dialect), start=dict(START))
    if has:
        setup = _with_probe_tool(setup)
    written = write_neutral(program.blocks(), dialect, setup, file="probe.nc")
    if written.crash is not None:
        return [f"{dialect.NAME}: writing {probe.what}, the writer crashed: {written.crash}"]
    flag = f"{probe.flag} = {getattr(dialect, probe.flag)!r}"
    unlocated = [e for e in written.errors if e.location is None or e.location.line < 1]
    if unlocated:
        return [f"{dialect.NAME}: writing {probe.what}, an error without a location: {e}" for e in unlocated]
    reached = any(probe.section in keys for _, keys in written.reached)
    refused_here = [e for e in written.errors if e.location is not None and e.location.line >= PROBE_LINE]
    other = [e for e in written.errors if e not in refused_here]
    if other:
        return [f"{dialect.NAME}: the probe's prologue (units mm, XY plane, absolute, a rapid) is refused: "
                + "; ".join(str(e) for e in other)]
    if has:
        if not reached:
            return [f"{dialect.NAME}: {flag}, but {probe.what} was lowered away before the writer"]
        if refused_here:
            return [f"{dialect.NAME}: {flag}, but the writer refuses {probe.what}: {refused_here[0]}"]
        return _reads_back(dialect, probe, written.text, setup) if probe.read_back else []
    if reached and not refused_here:
        return [f"{dialect.NAME}: {flag}, but the writer wrote {probe.what}:\n{written.text}"]
    return []


def _with_probe_tool(setup: MachineSetup) -> MachineSetup:
    """The set-up, with register 1 (the probes' length and radius register) measured as zero where it gives
    none: a dialect that writes tool data from the set-up's table (D on ISG, G43.1 on grbl) needs its
    values, and the probes are about the spelling, not the values."""
    if "1" in setup.tools:
        return setup
    from ..setup.machine import ToolData
    out = copy.copy(setup)
    out.tools = {**setup.tools, "1": ToolData(number=1, length=0.0, radius=0.0)}
    return out


_PLAIN_WHEN_NO_DWELL = {"drill_dwell": "drill", "bore_dwell_feed": "bore_feed"}
"""A dwelling cycle with no dwell moves as its plain kind (Fagor writes G81 for both, with K0 or none)."""


def _same_cycle(cycle: CannedCycle, kind: str) -> bool:
    return cycle.kind == kind or (_PLAIN_WHEN_NO_DWELL.get(cycle.kind) == kind and not cycle.dwell)


def _reads_back(dialect: type[Dialect], probe: Probe, text: str, setup: MachineSetup) -> list[str]:
    if dialect.READER is None:
        return []
    try:
        blocks = read_program(io.StringIO(text), file="probe.nc", dialect=dialect.NAME, setup=setup)
    except ErrorList as errs:
        return [f"{dialect.NAME}: the reader refuses the writer's {probe.what}: {errs.errors[0]}\n{text}"]
    found = [b.sections.get(probe.section) for b in blocks if probe.section in b.sections]
    if not found:
        return [f"{dialect.NAME}: {probe.what} was written, but reading it back gives no {probe.section}:\n{text}"]
    if probe.section == "Dwell" and not any(abs(getattr(s, "seconds", 0.0) - 1.5) < 1e-9 for s in found):
        unit = dialect.DWELL_UNIT
        return [f"{dialect.NAME}: a dwell of 1.5 s reads back as {[getattr(s, 'seconds') for s in found]} s "
                f"(DWELL_UNIT = {unit!r}: writer and reader disagree on the unit):\n{text}"]
    if probe.section == "CannedCycle" and not any(isinstance(s, CannedCycle) and _same_cycle(s, probe.what.split()[1])
                                                  for s in found):
        return [f"{dialect.NAME}: {probe.what} reads back as another cycle: {found}\n{text}"]
    return []
