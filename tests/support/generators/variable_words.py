"""Variable words: Fanuc (mill and lathe), LinuxCNC, ISG and Fagor programs whose words take their values from variables and
bracketed expressions (``H#1``, ``D#517``, ``T[#2+1]``, ``G10 L2 P1 X[1+1]``, ``M19 R#<a>``, ``XP1``),
every letter the dialect reads, through every writer.

A computed word reaches the IR only where the program is kept symbolically (``H#1`` in a
``ToolLengthOffset``), so each section that takes a number from a word must hold an expression too:
these found a register typed ``int`` given an expression (a ``TypeError`` in the compiled build), a
G10 value compared as a float, and, with a modal cycle before a loop, a copy of the modal state the
compiled build refused. The variables are sometimes ones the target can spell (the program kept
symbolically) and sometimes not (it is flattened).

The check: no internal error; a refusal only with located errors; what is written reads back and
verifies (``check_translation``); the sections read from the source hold what their annotations say
(``tests/support/section_types.py``: what the compiled build checks at run time) and come back from
their XML (``postproc ir``) unchanged.
"""

from __future__ import annotations

import io
from pathlib import Path

from hypothesis import strategies as st

from postproc.api import read_program
from postproc.errors import ErrorList
from postproc.ir import Block
from postproc.setup.machine_setup import MachineSetup, load_setup
from tests.support.tools import with_tools

from ..fuzzing import WRITERS, check_translation
from ..section_types import mistyped
from . import Case

KIND = "variable words"

# Each word: (placeholder, the numbers it may take). The numbers keep the programs valid on every
# controller (registers and tools 1-3, a dwell of whole milliseconds, R above the hole bottom...).
VALUES: dict[str, tuple[float, ...]] = {
    "X": (0.0, 1.5, 4.0, 10.0), "Y": (0.0, 2.0, 5.5), "Z": (2.0, 5.0, 10.0), "BOTTOM": (-1.0, -2.5),
    "R": (1.0, 2.0), "Q": (0.5, 1.0), "H": (1.0, 2.0, 3.0), "D": (1.0, 2.0), "T": (1.0, 2.0, 3.0),
    "S": (500.0, 1200.0), "F": (100.0, 250.0), "MS": (100.0, 500.0), "SEC": (0.5, 1.0), "K": (1.0, 2.0),
    "E": (1.0, 2.0, 3.0), "ANGLE": (0.0, 90.0), "M": (8.0, 9.0), "G": (0.0, 1.0), "RAD": (2.0, 3.0),
    "DIA": (10.0, 20.0, 30.0), "FR": (0.1, 0.2), "TURRET": (101.0, 202.0), "STEP": (1.0, 2.0),
}
WHOLE = frozenset(("H", "D", "T", "M", "G", "E", "K", "MS", "TURRET", "S"))
"""Placeholders whose words take whole numbers (written without a decimal point: a Fanuc S takes none)."""

FANUC = [
    "G0 G43 H{H} Z{Z}", "G49", "G41 D{D} G1 X{X} Y{Y} F{F}\nG40 G1 X{X} Y{Y}", "G42 D{D} G1 X{X} F{F}\nG40 G0 Z{Z}",
    "T{T} M6", "S{S} M3", "G1 X{X} F{F}", "G4 P{MS}", "G4 X{SEC}", "M{M}", "G{G} X{X} Y{Y}", "G0 X{X} Y{Y} Z{Z}",
    "G81 X{X} Y{Y} Z{BOTTOM} R{R} F{F}\nX{X}\nG80", "G83 X{X} Z{BOTTOM} R{R} Q{Q} F{F}\nG80",
    "G82 X{X} Z{BOTTOM} R{R} P{MS} F{F}\nY{Y}\nG80", "G81 X{X} Z{BOTTOM} R{R} K{K} F{F}\nG80",
    "G81 X{X} Y{Y} Z{BOTTOM} R{R} F{F}\nX{X}", "G80",
    "G10 L2 P{E} X{X} Y{Y} Z{Z}\nG0 X0 Y0 Z10.", "G10 L10 P{E} R{Q}", "G10 L11 P{E} R{Q}", "G10 L12 P{E} R{Q}",
    "G91 G2 X[2*{RAD}] I{RAD} F{F}\nG90", "G91 G3 X[-2*{RAD}] R{RAD} F{F}\nG90", "M19", "G28 Z{Z}\nG0 X0 Y0 Z10.",
    "G20 G1 X{STEP} F{F}\nG21 G0 X0 Y0 Z10.",
]
LINUXCNC = [
    "G0 G43 H{H} Z{Z}", "G49", "G41 D{D} G1 X{X} Y{Y} F{F}\nG40 G1 X{X} Y{Y}", "T{T} M6", "S{S} M3",
    "G1 X{X} F{F}", "G4 P{SEC}", "M{M}", "G{G} X{X} Y{Y}", "G0 X{X} Y{Y} Z{Z}", "M19 R{ANGLE}",
    "G81 X{X} Y{Y} Z{BOTTOM} R{R} F{F}\nX{X}\nG80", "G83 X{X} Z{BOTTOM} R{R} Q{Q} F{F}\nG80",
    "G82 X{X} Z{BOTTOM} R{R} P{SEC} F{F}\nG80", "G81 X{X} Z{BOTTOM} R{R} L{K} F{F}\nG80",
    "G81 X{X} Y{Y} Z{BOTTOM} R{R} F{F}\nX{X}", "G80", "G10 L2 P{E} X{X} Y{Y} Z{Z}\nG0 X0 Y0 Z10",
    "G91 G2 X[2*{RAD}] I{RAD} F{F}\nG90", "G91 G3 X[-2*{RAD}] R{RAD} F{F}\nG90", "G28 Z{Z}\nG0 X0 Y0 Z10.",
    "G20 G1 X{STEP} F{F}\nG21 G0 X0 Y0 Z10",
]
LATHE = [
    "G50 X{DIA} Z{Z}\nG0 X{DIA} Z{Z}", "G50 S{S}", "G96 S{S} M3\nG97 S500", "G97 S{S} M3", "T{TURRET}",
    "G0 X{DIA} Z{Z}", "G1 U{STEP} W[-{STEP}] F{FR}", "G1 X{DIA} F{FR}", "G4 U{SEC}", "G4 P{MS}", "M{M}",
]
ISG = [
    "G01 X{X} F{F}", "G00 X{X} Y{Y} Z{Z}", "T{T} M06", "S{S} M03", "G04 X{SEC}", "M{M}", "G{G} X{X} Y{Y}",
    "G41 D{D} G01 X{X} Y{Y} F{F}\nG40 G01 X{X} Y{Y}", "G91 G02 X[2*{RAD}] I{RAD} F{F}\nG90",
    "N[10+{E}] G01 X{X}",
]
FAGOR = [
    "G01 X{X} F{F}", "G00 X{X} Y{Y} Z{Z}", "T{T} M06", "S{S} M03", "G04 K{SEC}", "M{M}",
    "G41 D{D} G01 X{X} Y{Y} F{F}\nG40 G01 X{X} Y{Y}", "G91 G02 X[2*{RAD}] I{RAD} F{F}\nG90",
]

# Per source: the header, the variables (some a target can spell, some not), how one is assigned,
# and a loop around some of the lines (the construct a target keeps symbolically or flattens).
SOURCES = {
    "fanuc": ("G21 G90 G17 G0 X0 Y0 Z10.\nF100.", ["#1", "#2", "#24", "#100", "#501", "#517"], "{var}={value}",
              ("#{n}=0\nWHILE[#{n}LT2]DO1", "#{n}=#{n}+1\nEND1"), FANUC, "M30"),
    # LinuxCNC's G99 said: Mach3 starts in G98 (a known defect, tests/support/fuzzing.py)
    "linuxcnc": ("G21 G90 G17 G99 G0 X0 Y0 Z10\nF100", ["#1", "#2", "#100", "#<depth>", "#<_top>"], "{var}={value}",
                 ("#{n}=0\no100 while [#{n} LT 2]", "#{n}=[#{n}+1]\no100 endwhile"), LINUXCNC, "M2"),
    "isg": ("G71 G90 G17 G00 X0 Y0 Z10\nF100", ["P1", "P2", "P17", "P499"], "{var}={value}",
            ("P{n}=0\n$WHILE P{n} < 2", "P{n}=P{n}+1\n$ENDWHILE"), ISG, "M30"),
    "fagor": ("G71 G90 G17 G00 X0 Y0 Z10\nF100", ["P1", "P2", "P17", "P499"], "{var}={value}",
              None, FAGOR, "M30"),  # Fagor's $WHILE is kept verbatim, not run (docs/dialects.md [?])
    "fanuc lathe": ("G21 G0 X40. Z5.\nS500 M3", ["#1", "#2", "#24", "#100", "#501"], "{var}={value}",
                    ("#{n}=0\nWHILE[#{n}LT2]DO1", "#{n}=#{n}+1\nEND1"), LATHE, "M30"),
}
COUNTER = {"fanuc": "530", "linuxcnc": "530", "isg": "30", "fanuc lathe": "530"}
LATHE_SETUP = Path(__file__).resolve().parents[3] / "examples" / "setups" / "fanuc_0i_tf.xml"
"""Fanuc 0i-TF: a lathe programming diameters, G-code system A."""


def _number(value: float) -> str:
    return f"{value:.1f}" if value != int(value) else f"{int(value)}."


@st.composite
def _spelled(draw: st.DrawFn, source: str, value: float, assigned: dict[str, float], name: str) -> str:
    """One word's number: written, a variable, or an expression over one."""
    _, variables, _, _, _, _ = SOURCES[source]
    literal = str(int(value)) if name in WHOLE else _number(value)
    how = draw(st.sampled_from(["literal", "variable", "expression", "expression"]))
    if how == "literal":
        return literal
    var = draw(st.sampled_from(variables))
    if var in assigned and assigned[var] != value:
        return f"[{literal}]" if how == "expression" else literal
    assigned[var] = value
    if how == "variable":
        return var
    return draw(st.sampled_from([f"[{var}+0]", f"[{var}*1]", f"[{var}/2*2]", f"[{var}-1+1]", f"[0+{var}]"]))


@st.composite
def programs(draw: st.DrawFn, source: str) -> str:
    header, _, assign, loop, forms, end = SOURCES[source]
    assigned: dict[str, float] = {}
    lines = []
    for form in draw(st.lists(st.sampled_from(forms), min_size=1, max_size=5)):
        text = form
        chosen: dict[str, float] = {}  # a placeholder met twice in a form is one number (an arc's radius)
        while "{" in text:
            start = text.index("{")
            name = text[start + 1:text.index("}", start)]
            value = chosen.setdefault(name, draw(st.sampled_from(VALUES[name])))
            word = draw(_spelled(source, value, assigned, name))
            text = text[:start] + word + text[text.index("}", start) + 1:]
        lines.append(text)
    if loop is not None and draw(st.booleans()):  # a loop around the last lines (run twice)
        cut = draw(st.integers(0, len(lines) - 1))
        n = COUNTER[source]
        lines[cut:] = [loop[0].format(n=n), *lines[cut:], loop[1].format(n=n)]
    setting = [assign.format(var=var, value=_number(value)) for var, value in assigned.items()]
    return "\n".join([header, *setting, *lines, end]) + "\n"


def _check(source: str, target: str, program: str, setup: MachineSetup, warn: bool) -> str:
    try:
        blocks = read_program(io.StringIO(program), file="fuzz.nc", dialect=source, setup=setup)
    except ErrorList:
        blocks = []  # refused: check_translation checks the errors are located
    for block in blocks:
        bad = mistyped(block)
        assert not bad, f"a section holds what its annotation refuses (compiled: a TypeError): {bad[0]}"
        assert Block.from_xml(block.make_xml_source()) == block, f"the IR's XML loses part of {block!r}"
    return check_translation(source, target, program, setup, warn)


@st.composite
def _case(draw: st.DrawFn) -> Case:
    kind = draw(st.sampled_from(sorted(SOURCES)))
    target = draw(st.sampled_from(WRITERS))
    program = draw(programs(kind))
    warn = draw(st.booleans())
    source, lathe = kind.split()[0], kind.endswith("lathe")
    setup = load_setup(LATHE_SETUP) if lathe else with_tools()  # every register has a (zero) value
    return Case(f"variable words {kind}-{target}", target, program,
                lambda p: _check(source, target, p, setup, warn), setup)


def cases() -> st.SearchStrategy[Case]:
    return _case()
