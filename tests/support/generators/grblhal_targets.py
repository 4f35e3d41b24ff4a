"""Fuzz kind "grblhal targets": the grblHAL plugin as a target, on each build a set-up describes (expressions
and o-words or not, a tool table or not, a spindle encoder, mist coolant), from Fanuc Custom Macro B
programs (``macros``), LinuxCNC o-word programs (``owords``) and random drilling-cycle programs (G73, G81-G89
with G98/G99, repeats, K/L counts, changes of cycle without a cancel).

A case passes when it is refused with located errors, or when the output reads back in grblHAL, meets
grblHAL's rules for that build (``grblhal_rules``) and verifies; a program grblHAL keeps symbolic (o-words,
expressions: grblHAL's are rs274's, ``ngc_flowctrl.c``/``ngc_expr.c``) is also run by ``rs274``, whose moves
must be the source's: with each call's arguments left out written as the caller's ``[#k]`` (what grblHAL hands the
sub; rs274 reads 0), and not where the text reads a returned value (``#<_value>``: set otherwise than rs274 does).
"""

from __future__ import annotations

import io
import re

from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup

from ..fuzzing import check_translation
from ..tools import with_tools
from . import Case
from .macros import moves_agree_with_rs274, programs as macro_programs, runs
from .owords import programs as oword_programs

KIND = "grblhal targets"
_COMPUTES = re.compile(r"(?im)^\s*o\S+\s+(sub|call|if|while|do|endsub|return)\b|#")
"""A grblHAL program that computes (an o-word or a parameter)."""
_BUILDS = {
    "plain": {},
    "expressions": {"expressions": True},
    "tool table": {"tool_table": True},
    "everything": {"expressions": True, "tool_table": True, "spindle_sync": True, "mist_coolant": True},
}
"""grblHAL builds (``<Controller>``): compiled with NGC_EXPRESSIONS_ENABLE, N_TOOLS, a spindle encoder."""


def build_setup(build: str) -> MachineSetup:
    setup = with_tools()
    setup.controller = ControllerSettings(**_BUILDS[build])
    return setup


@st.composite
def cycle_programs(draw: st.DrawFn) -> str:
    lines = ["G21 G17 G90 G94", "G0 X0 Y0 Z10", "F120", "S1000 M3"]
    for _ in range(draw(st.integers(1, 6))):
        cycle = draw(st.sampled_from(["G81", "G82", "G83", "G73", "G84", "G85", "G86", "G89", "G81", "G83"]))
        words = {"G81": "", "G82": " P0.5", "G83": " Q2", "G73": " Q1", "G84": "", "G85": "", "G86": " P0.5",
                 "G89": " P0.5"}[cycle]
        level = draw(st.sampled_from(["G98", "G99"]))
        r = draw(st.sampled_from(["2", "5", "12", "-1"]))
        z = draw(st.sampled_from(["-3", "-10", "1"]))
        x, y = draw(st.integers(-20, 20)), draw(st.integers(-20, 20))
        count = draw(st.sampled_from(["", "", " L2", " L3"]))
        lines.append(f"{level} {cycle} X{x} Y{y} Z{z} R{r}{words}{count}")
        for _ in range(draw(st.integers(0, 2))):
            lines.append(draw(st.sampled_from([f"X{x + 5}", f"Y{y - 3}", f"X{x} Y{y + 4} Z-2", "G91 X5 Y5", "G90"])))
        if draw(st.booleans()):
            lines.append("G80")
        if draw(st.booleans()):
            lines.append(draw(st.sampled_from(["G0 Z10", "G1 X3 Y3", "G43 H1", "M8", "M7", "G95 F0.1", "G94 F100"])))
    lines += ["G80", "G0 Z10", "M2"]
    return "\n".join(lines) + "\n"


def check(source: str, program: str, build: str) -> str:
    setup = build_setup(build)
    if not runs(source, program):
        return "refused"
    result = check_translation(source, "grblhal", program, setup, False)
    if result == "ok" and _BUILDS[build].get("expressions"):
        out = io.StringIO()
        try:
            translate(io.StringIO(program), out, file="in.nc", source=source, target="grblhal", setup=setup,
                      diagnostics=Diagnostics(warn_stream=io.StringIO()))
        except ErrorList as errs:
            raise AssertionError(f"a second translation is refused: {errs}") from None
        text = out.getvalue()
        if _COMPUTES.search(text) and not _RETURNED.search(text):
            moves_agree_with_rs274(source, program, as_grblhal_runs(text))
    return result


_RETURNED = re.compile(r"(?i)#<\s*_value(_returned)?\s*>")
"""A read of a returned value: grblHAL sets ``#<_value>`` and ``#<_value_returned>`` otherwise than rs274 (zeroed
at every call, kept by a return without a value, not set by a definition's ``endsub [v]`` that the flow passes,
unset before the first call: ``postproc_grblhal.variables``), which no rewriting of the text makes rs274 do, so
such a text is not run by rs274 (the verify of ``check_translation`` still simulates it as grblHAL runs it)."""
_CALL = re.compile(r"(?i)^(\s*o\S+\s+call)\b(.*)$")
CALL_ARGUMENTS = 30
"""``#1``-``#30``: a call's arguments."""


def as_grblhal_runs(text: str) -> str:
    """``text`` with every call given its 30 arguments, those it leaves out as ``[#k]``: the caller's value, which
    is what grblHAL hands the sub for them [V: ngc_flowctrl.c ``NGCFlowCtrl_Call``, via
    ``postproc_grblhal.variables``], where rs274 reads 0. So rs274 runs the text's calls as grblHAL does."""
    lines = []
    for line in text.splitlines(keepends=True):
        found = _CALL.match(line.rstrip("\r\n"))
        if found is not None:
            head, rest = found.groups()
            given, tail = _arguments(rest)
            if given < CALL_ARGUMENTS:
                extra = "".join(f" [#{k}]" for k in range(given + 1, CALL_ARGUMENTS + 1))
                line = head + rest[:tail].rstrip() + extra + rest[tail:] + line[len(line.rstrip("\r\n")):]
        lines.append(line)
    return "".join(lines)


def _arguments(rest: str) -> tuple[int, int]:
    """The ``[..]`` arguments a call's words after ``call`` give, and where they end (a comment may follow)."""
    depth = given = end = 0
    for i, char in enumerate(rest):
        if char == "[":
            given += depth == 0
            depth += 1
        elif char == "]":
            depth -= 1
            if depth == 0:
                end = i + 1
        elif depth == 0 and not char.isspace():
            break
    return given, end


def _case(source: str, program: str, build: str) -> Case:
    return Case(f"grblhal {source} ({build})", "grblhal", program, lambda p: check(source, p, build),
                f"grblHAL build: {build}")


def cases() -> st.SearchStrategy[Case]:
    builds = st.sampled_from(sorted(_BUILDS))
    return st.one_of(st.builds(_case, st.just("fanuc"), macro_programs(), builds),
                     st.builds(_case, st.just("linuxcnc"), oword_programs(), builds),
                     st.builds(_case, st.sampled_from(["linuxcnc", "fanuc"]), cycle_programs(), builds))
