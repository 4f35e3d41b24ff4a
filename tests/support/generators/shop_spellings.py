"""Shop spellings: Haas and Fanuc programs as operators type them at the machine (issue #31, item 16).

Comments in both places (``(..)`` alone and after a ``;``), ``;`` ends, optional leading zeros (``G0``,
``G00``, ``M9``, ``M09``, ``H1``, ``H01``), ``H0``/``D0``, a first move without a motion code, the Haas
NGC's ``#10000``-range variables, macro alarms ``#3000`` in an ``IF``, dwells in both units. Each program is
read under the Haas and the Fanuc variant and translated to every writer; it must be refused with located
errors, or be read back by the target and verify against its source (a source the simulator refuses, with
located errors, for a value only the machine knows, may still travel symbolically: then its output must be
valid and read back).
"""

from __future__ import annotations

import io
from typing import Callable

from hypothesis import strategies as st

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import ControllerSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.fuzzing import WRITERS, check_translation, located
from tests.support.output_rules import problems

from . import Case

KIND = "shop spellings"

VARIANTS = ("haas", "fanuc", "fanuc-0m")

MOVES = [
    "X1. Y2.", "Z.1", "X-1.5", "Y.25", "Z-0.5", "X0 Y0", "Z25.", "X10 Y-5",
]
"""Axis words a shop writes (points, leading points, point-less under least-increment input)."""

CODES = [
    "G0", "G00", "G000", "G1", "G01", "G90", "G91", "G17", "G20", "G21", "G40", "G49", "G54", "G80", "G98", "G99",
    "M3", "M03", "M5", "M05", "M8", "M08", "M9", "M09", "S1000", "F100.", "F20", "T1 M6", "T01 M06",
]

BLOCKS = [
    "G53 G0 Z0 H0", "G53 G00 Z0. H00", "G28 G91 Z0", "G43 H1 Z25.", "G43 H01 Z1.", "G44 H2 Z5.", "H0", "H3",
    "G41 D1 X1.", "G41 D0 X1.", "G42 H19 X2.", "G40 X0", "G04 P0.5", "G04 P500", "G04 X1.", "G04 P1.",
    "G81 Z-1. R.1 F10.", "G82 Z-1. R.1 P0.3 F10.", "G83 Z-2. R.1 Q.5 F10.",
    "#10100=5.", "#10200=[#10100*2.]", "G00 X#10100", "G01 Z-#10200 F10.", "#100=1.", "G00 Y#100", "#1=30.",
    "G00 X#10150", "#1=#0",
    "IF [#1 EQ #0] THEN #3000=1(NEED ROTATION AXIS)", "IF [#10100 GT 100.] THEN #3000=2 (TOO BIG)",
    "IF [#100 LT 0] THEN #3000=3",
]
"""Whole blocks shops write: length offsets by register and H0, cutter registers, dwells, cycles, the Haas
variables and macro alarms."""

COMMENTS = ["(ROUGH)", "(Retract)", "(T1 .5 EM)", ""]


@st.composite
def _line(draw: st.DrawFn) -> str:
    words = draw(st.lists(st.sampled_from(CODES + MOVES), max_size=4))
    if draw(st.booleans()):
        words.append(draw(st.sampled_from(BLOCKS)))
        words = words[-1:] if words[-1].startswith(("#", "IF")) else words
    text = " ".join(words)
    if draw(st.booleans()):  # a block number, sometimes with leading zeros
        text = f"N{draw(st.sampled_from(['1', '010', '0100', '25']))} {text}".rstrip()
    comment = draw(st.sampled_from(COMMENTS))
    end = draw(st.sampled_from(["", ";", " ;", f"; {comment};" if comment else ";;"]))
    if comment and not end.startswith(("; (",)) and draw(st.booleans()):
        text = f"{text} {comment}".strip()
    return text + end


@st.composite
def _program(draw: st.DrawFn) -> str:
    head = draw(st.sampled_from(["", "%\nO1234 (PART);\n", "O0001\n"]))
    first = draw(st.sampled_from(["X0 Y0 Z1.", "G00 X0 Y0 Z1.", "G0 G90 G54 X0. Y0.;", "G43 H1 Z1.", ""]))
    lines = draw(st.lists(_line(), min_size=1, max_size=8))
    end = draw(st.sampled_from(["M30", "M30;", "M30 ;\n%"]))
    return head + "\n".join(line for line in [first, *lines, end] if line) + "\n"


def _run(variant: str, target: str) -> Callable[[str], object]:
    setup = MachineSetup(controller=ControllerSettings(variant=variant))

    def run(program: str) -> object:
        if _simulates(program, setup):
            return check_translation("fanuc", target, program, setup, warn=False)
        return _reads_back(target, program, setup)

    return run


def _simulates(program: str, setup: MachineSetup) -> bool:
    """Whether the source runs in the simulator; a refusal must be located."""
    try:
        list(toolpath_events(io.StringIO(program), file="fuzz.nc", dialect="fanuc", setup=setup,
                             diagnostics=Diagnostics(warn_stream=io.StringIO())))
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
        return False
    return True


def _reads_back(target: str, program: str, setup: MachineSetup) -> str:
    """A source the simulator refuses (a value only the machine knows) may still travel symbolically to a
    target that has it: then nothing can be verified, but the output must be valid and read back."""
    out = io.StringIO()
    try:
        translate(io.StringIO(program), out, file="fuzz.nc", source="fanuc", target=target, setup=setup,
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
        return "refused"
    text = out.getvalue()
    refused = problems(target, text, setup) if target != "fanuc" else []
    assert not refused, f"the {target} controller refuses the {target} output: {'; '.join(refused)}\n{text}"
    try:
        read_program(io.StringIO(text), file="out.nc", dialect=target, setup=setup)
    except ErrorList as errs:
        raise AssertionError(f"the {target} reader refuses the {target} output: {errs}\n{text}") from None
    return "ok"


@st.composite
def _case(draw: st.DrawFn) -> Case:
    variant = draw(st.sampled_from(VARIANTS))
    target = draw(st.sampled_from(WRITERS))
    program = draw(_program())
    return Case(name=f"shop {variant}-{target}", target=target, program=program, run=_run(variant, target))


def cases() -> st.SearchStrategy[Case]:
    return _case()
