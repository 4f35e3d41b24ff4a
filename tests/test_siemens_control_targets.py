"""SINUMERIK control flow kept symbolic towards Fanuc Macro B, LinuxCNC o-words and ISG (issue 28, item 2).

* Fanuc: ``IF``/``ELSE``/``ENDIF``, ``REPEAT``/``UNTIL`` and named labels become jumps to block numbers above
  the program's highest (``postproc.rs274.macro_jumps``); ``WHILE``, ``FOR`` and ``LOOP`` stay ``WHILE .. DOm``.
  The expected texts are written by hand from that spelling.
* LinuxCNC: forward jumps become ``o.. if`` .. ``endif`` where they have that shape, ``UNTIL`` an
  ``o.. do`` .. ``while`` (``postproc.rs274.oword_jumps``); a jump back is flattened with the warning.
  ``rs274`` runs each translation to the moves of postproc's own SINUMERIK toolpath.
* A frame command that runs once where the text has it stays in a symbolic program
  (``postproc.frames.run_order``); in a loop or across a jump back it flattens the program.

Expected points are derived by hand from the source programs; the random differential compares the
toolpath of each translation with the source's (``verify`` at 0) and LinuxCNC's interpreter with both.
"""

from __future__ import annotations

import io
import math
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
SETUP = load_setup(str(ROOT / "tests" / "support" / "zero_tools.xml"))
TOOL_TABLE = "".join(f"T{n} P{n} Z0 D0\n" for n in range(1, 10))
"""The tools of ``zero_tools.xml`` as rs274 reads a table."""
RS274_MM = 2e-4
"""rs274 prints 4 decimals."""

FLOW = """%_N_FLOW_MPF
N10 G17 G90 G710 G54
N20 T1 D1 M6
N30 S3000 M3
N40 G0 X0 Y0 Z5
R1=0
R2=0
WHILE R1<3
R1=R1+1
G1 Z=-R1 F150
IF R1==2
G1 X40
ELSE
G1 X0
ENDIF
ENDWHILE
REPEAT
R2=R2+1
G1 Y=R2*5
UNTIL R2>=2
LOOP
R2=R2+1
IF R2>3 GOTOF OUT
G1 X=R2
ENDLOOP
OUT:
BACK: R1=R1-1
G1 Z=-R1
IF R1>1 GOTOB BACK
N50 G0 Z50
N70 M30
"""
FLOW_MOVES = [("rapid", 0, 0, 5), ("feed", 0, 0, -1), ("feed", 0, 0, -2), ("feed", 40, 0, -2),
              ("feed", 40, 0, -3), ("feed", 0, 0, -3), ("feed", 0, 5, -3), ("feed", 0, 10, -3), ("feed", 3, 10, -3),
              ("feed", 3, 10, -2), ("feed", 3, 10, -1), ("rapid", 3, 10, 50)]
"""By hand: three passes down (X0, X40 on the second, X0), Y5 and Y10 in the REPEAT, X3 in the LOOP before
R2=4 leaves it, then Z-2 and Z-1 while R1 counts down from 3, and the retract (the toolpath leaves out the
first pass's X0, which does not move)."""
FLOW_FORWARD = FLOW.replace("BACK: R1=R1-1\nG1 Z=-R1\nIF R1>1 GOTOB BACK\n", "")
FORWARD_MOVES = FLOW_MOVES[:9] + [FLOW_MOVES[-1]]


def _translate(text: str, target: str) -> tuple[str, str]:
    """The translation and its warnings."""
    out, warnings = io.StringIO(newline=""), io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target, setup=SETUP,
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def _verified(text: str, out: str, target: str) -> None:
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="in.mpf",
                          file_out="out", source="siemens", target=target, setup=SETUP, tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary()


def _moves(text: str, dialect: str) -> list[tuple[str, float, float, float]]:
    return [(e["move"], e["x"], e["y"], e["z"]) for e in
            toolpath_events(io.StringIO(text, newline=""), file="p", dialect=dialect, setup=SETUP) if "move" in e]


def _same_in_rs274(text: str, out: str) -> None:
    """rs274 runs the LinuxCNC text through the moves of the SINUMERIK toolpath."""
    theirs = [e for e in canonical_moves(run_rs274(out, tool_table=TOOL_TABLE), start=(0.0, 0.0, 0.0))
              if "move" in e]
    ours: list[dict[str, Any]] = [e for e in toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens",
                                                             setup=SETUP) if "move" in e]
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274\n{text}\n{out}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b, text, out)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= RS274_MM and not math.isnan(dev), (n, a, b, text, out)


def _code(out: str) -> list[str]:
    return [line for line in out.splitlines() if not line.startswith("(")]


# -- Fanuc Macro B ------------------------------------------------------------------------------------------

def test_the_siemens_toolpath_is_the_hand_derived_one() -> None:
    assert _moves(FLOW, "siemens") == FLOW_MOVES
    assert _moves(FLOW_FORWARD, "siemens") == FORWARD_MOVES


def test_if_else_repeat_loop_and_labels_are_macro_b_jumps_above_the_highest_block_number() -> None:
    out, warnings = _translate(FLOW, "fanuc")
    assert "flattened" not in warnings, warnings
    code = _code(out)
    start = code.index("WHILE [#501 LT 3.] DO1")
    assert code[start:] == [
        "WHILE [#501 LT 3.] DO1", "#501=#501+1.", "G01 Z-#501 F150.",
        "IF [#501 NE 2.] GOTO 71", "G01 X40.", "GOTO 72", "N71", "G01 X0.", "N72",
        "END1",
        "N73", "#502=#502+1.", "G01 Y[#502*5.]", "IF [#502 LT 2.] GOTO 73",
        "WHILE [1. NE 0.] DO1", "#502=#502+1.", "IF [#502 GT 3.] GOTO 74", "G01 X#502", "END1",
        "N74",
        "N75", "#501=#501-1.", "G01 Z-#501", "IF [#501 GT 1.] GOTO 75",
        "N50 G00 Z50.", "N70 M30"], out
    _verified(FLOW, out, "fanuc")
    assert _moves(out, "fanuc") == FLOW_MOVES


def test_the_jumps_numbers_start_above_a_block_number_before_the_first_statement() -> None:
    text = FLOW_FORWARD.replace("N40 G0 X0 Y0 Z5", "N900 G0 X0 Y0 Z5")
    out, warnings = _translate(text, "fanuc")
    assert "flattened" not in warnings and "IF [#501 NE 2.] GOTO 901" in out and "\nN904\n" in out, out
    _verified(text, out, "fanuc")


def test_numbers_beyond_fanuc_s_last_block_number_flatten_the_program() -> None:
    text = FLOW_FORWARD.replace("N70 M30", "N99998 M30")
    out, warnings = _translate(text, "fanuc")
    assert "the program is flattened" in warnings and "Fanuc's block numbers end at N99999" in warnings, warnings
    assert "GOTO" not in "\n".join(_code(out))
    _verified(text, out, "fanuc")


def test_an_else_if_chain_from_linuxcnc_is_jumps_too() -> None:
    """Another source's ``elseif``: each branch's test jumps past it, a branch taken jumps to the end."""
    text = ("G21 G90 G17\n#500=3\nG0 X0 Y0 Z5\no1 if [#500 LT 1]\nG1 X1 F100\no1 elseif [#500 LT 5]\nG1 X2 F100\n"
            "o1 else\nG1 X3 F100\no1 endif\nM2\n")
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(text), out, file="in.ngc", source="linuxcnc", target="fanuc", setup=SETUP,
              diagnostics=Diagnostics(warn_stream=warnings))
    assert "flattened" not in warnings.getvalue()
    assert _code(out.getvalue())[-11:] == [
        "IF [#500 GE 1.] GOTO 1", "G01 X1. F100.", "GOTO 2", "N1", "IF [#500 GE 5.] GOTO 3", "G01 X2. F100.",
        "GOTO 2", "N3", "G01 X3. F100.", "N2", "M02"], out.getvalue()
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="in.ngc", file_out="out.nc",
                          source="linuxcnc", target="fanuc", setup=SETUP, tolerance=0.0)
    assert report.ok, report.summary()


# -- LinuxCNC o-words ---------------------------------------------------------------------------------------

def test_forward_jumps_and_until_are_o_words_and_move_in_rs274_as_the_siemens_toolpath() -> None:
    out, warnings = _translate(FLOW_FORWARD, "linuxcnc")
    assert "flattened" not in warnings, warnings
    code = _code(out)
    assert "o2 if [#501 LE 2. AND #501 GE 2.]" in code and "o2 else" in code  # R1==2 exactly: LE and GE
    assert code[code.index("o3 do"):code.index("o3 do") + 4] == [
        "o3 do", "#502=[#502+1.]", "G1 Y[#502*5.]", "o3 while [#502 LT 2.]"]
    assert code[code.index("o4 while [1.]"):] == [  # LOOP .. IF c GOTOF OUT .. ENDLOOP OUT: leaves by break
        "o4 while [1.]", "#502=[#502+1.]", "o5 if [#502 GT 3.]", "o4 break", "o5 endif", "G1 X#502",
        "o4 endwhile", "N50 G0 Z50.", "N70 M30"]
    _verified(FLOW_FORWARD, out, "linuxcnc")
    assert _moves(out, "linuxcnc") == FORWARD_MOVES
    if available():
        _same_in_rs274(FLOW_FORWARD, out)


@pytest.mark.parametrize("text, why", [
    (FLOW, "a jump back"),
    (FLOW_FORWARD.replace("ENDLOOP\n", "ENDLOOP\nG1 Y0\n"), "a jump out of a construct to other than the block after"),
    (FLOW_FORWARD.replace("ENDIF\n", "IF R1>5 GOTOF SKIP\nENDIF\nSKIP:\n"), "a jump out of a construct or over"),
    ("G710 G90 G0 X0 Y0 Z5\nR1=1\nIF R1>0 GOTOF IN\nWHILE R1<3\nIN: R1=R1+1\nG1 X=R1 F100\nENDWHILE\nM30\n",
     "a jump into a construct"),
])
def test_a_jump_without_an_if_shape_flattens_the_linuxcnc_translation(text: str, why: str) -> None:
    out, warnings = _translate(text, "linuxcnc")
    assert "the program is flattened" in warnings and why in warnings, warnings
    assert not any(line.startswith("o") for line in _code(out)), out
    _verified(text, out, "linuxcnc")
    if available():
        _same_in_rs274(text, out)


# -- seeded random differential -----------------------------------------------------------------------------

class _Gen:
    """Small SINUMERIK programs of nested control flow over R1, R2 and counters R10..: IF/ELSE, WHILE, FOR,
    REPEAT/UNTIL, LOOP left by GOTOF, a forward GOTOF over blocks, and (``back``) a GOTOB loop. Every loop
    ends by its counter."""

    def __init__(self, seed: int, back: bool) -> None:
        self.r = random.Random(seed)
        self.back = back
        self.counter = 10
        self.labels = 0

    def value(self) -> str:
        return self.r.choice(["R1", "R2", "R1+R2", "2*R1-R2", str(self.r.randint(-4, 4))])

    def cond(self) -> str:
        return f"{self.r.choice(['R1', 'R2'])}{self.r.choice(['<', '>', '<=', '>=', '==', '<>'])}{self.r.randint(-2, 4)}"

    def move(self) -> list[str]:
        kind = self.r.random()
        if kind < 0.4:
            return [f"G1 X={self.value()} Y={self.value()} F{self.r.randint(50, 400)}"]
        if kind < 0.7:
            return [f"R{self.r.choice([1, 2])}=R{self.r.choice([1, 2])}+{self.r.randint(-2, 3)}", f"G1 Z=-{self.r.randint(0, 5)}-R1*0.1"]
        return [f"G0 X{self.r.randint(-20, 20)} Y={self.value()}"]

    def fresh(self) -> str:
        self.counter += 1
        return f"R{self.counter}"

    def label(self) -> str:
        self.labels += 1
        return f"LBL{self.labels}"

    def body(self, depth: int) -> list[str]:
        lines: list[str] = []
        for _ in range(self.r.randint(1, 3)):
            lines += self.statement(depth)
        return lines

    def statement(self, depth: int) -> list[str]:
        kinds = ["move", "move", "if", "skip"] + (["while", "for", "repeat", "loop"] if depth < 2 else [])
        kind = self.r.choice(kinds + (["back"] if self.back and depth == 0 else []))
        if kind == "move" or depth > 2:
            return self.move()
        if kind == "if":
            other = ["ELSE", *self.body(depth + 1)] if self.r.random() < 0.6 else []
            return [f"IF {self.cond()}", *self.body(depth + 1), *other, "ENDIF"]
        n, c = self.r.randint(1, 3), self.fresh()
        if kind == "while":
            return [f"{c}=0", f"WHILE {c}<{n}", f"{c}={c}+1", *self.body(depth + 1), "ENDWHILE"]
        if kind == "for":
            return [f"FOR {c}=1 TO {n}", *self.body(depth + 1), "ENDFOR"]
        if kind == "repeat":
            return [f"{c}=0", "REPEAT", f"{c}={c}+1", *self.body(depth + 1), f"UNTIL {c}>={n}"]
        label = self.label()
        if kind == "loop":
            return [f"{c}=0", "LOOP", f"{c}={c}+1", f"IF {c}>{n} GOTOF {label}", *self.body(depth + 1), "ENDLOOP",
                    f"{label}:"]
        if kind == "skip":
            return [f"IF {self.cond()} GOTOF {label}", *self.body(depth + 1), f"{label}:"]
        return [f"{c}=0", f"{label}: {c}={c}+1", *self.body(depth + 1), f"IF {c}<{n} GOTOB {label}"]

    def program(self) -> str:
        lines = ["%_N_RANDOM_MPF", "N10 G17 G90 G710 G94", "N20 T1 D1 M6", "N30 G0 X0 Y0 Z5 F300",
                 f"R1={self.r.randint(-2, 3)}", f"R2={self.r.randint(-2, 3)}"]
        for _ in range(self.r.randint(2, 4)):
            lines += self.statement(0)
        return "\n".join(lines + ["G0 Z50", "M30"]) + "\n"


@pytest.mark.parametrize("seed", range(12))
def test_random_control_flow_keeps_the_toolpath_on_fanuc_and_linuxcnc(seed: int) -> None:
    """Fanuc keeps every construct (the text keeps WHILE/IF/GOTO, no flattening); LinuxCNC keeps what has an
    o-word shape and flattens a GOTOB loop with the warning. Each translation moves as the source (verify at
    0), and rs274 runs the LinuxCNC one through the SINUMERIK toolpath's moves."""
    back = seed % 3 == 2
    text = _Gen(2800 + seed, back).program()
    fanuc, warnings = _translate(text, "fanuc")
    assert "flattened" not in warnings, (text, warnings)
    assert ("IF [" in fanuc or "WHILE [" in fanuc), (text, fanuc)
    _verified(text, fanuc, "fanuc")
    ngc, warnings = _translate(text, "linuxcnc")
    if "GOTOB" in text:
        assert "the program is flattened" in warnings and "a jump back" in warnings, (text, warnings)
    else:
        assert "flattened" not in warnings, (text, warnings)
    _verified(text, ngc, "linuxcnc")
    if available():
        _same_in_rs274(text, ngc)


# -- ISG --------------------------------------------------------------------------------------------------

def test_isg_gets_if_else_repeat_a_loop_left_by_break_and_a_goto_back_outside_loops() -> None:
    """``$GOTO`` may not jump inside a loop (TF5200 ID 21480): the LOOP's exit is ``$IF`` ``$BREAK``; the GOTOB
    loop at the top level stays a ``$GOTO`` to its label; REPEAT .. UNTIL is ``$DO`` .. ``$ENDDO``."""
    out, warnings = _translate(FLOW, "isg")
    assert "flattened" not in warnings, warnings
    code = _code(out)
    start = code.index("$WHILE P1 < 3")
    assert code[start:] == [
        "$WHILE P1 < 3", "P1=P1+1", "G01 Z-P1 F150.", "$IF P1 == 2", "G01 X40.", "$ELSE", "G01 X0.", "$ENDIF",
        "$ENDWHILE", "$DO", "P2=P2+1", "G01 Y[P2*5]", "$ENDDO P2 < 2",
        "$WHILE 1 != 0", "P2=P2+1", "$IF P2 > 3", "$BREAK", "$ENDIF", "G01 XP2", "$ENDWHILE",
        "[out] ", "[back] P1=P1-1", "G01 Z-P1", "$IF P1 > 1 $GOTO [back]", "N50 G00 Z50.", "N70 M30"], out
    _verified(FLOW, out, "isg")
    assert _moves(out, "isg") == FLOW_MOVES


def test_an_isg_jump_inside_a_loop_without_an_if_shape_flattens() -> None:
    text = ("G710 G90 G0 X0 Y0 Z5 F100\nR1=0\nWHILE R1<2\nR1=R1+1\nAGAIN: G1 X=R1\nR2=R1\nIF R2>5 GOTOB AGAIN\n"
            "ENDWHILE\nM30\n")
    out, warnings = _translate(text, "isg")
    assert "the program is flattened" in warnings and "GOTO may not stay in a loop" in warnings, warnings
    assert "$" not in "\n".join(_code(out))
    _verified(text, out, "isg")


# -- frames in a program kept symbolically ------------------------------------------------------------------

PLATE = (ROOT / "examples" / "siemens" / "plate.mpf").read_text(encoding="utf-8")


@pytest.mark.parametrize("target, loop, jump", [("fanuc", "WHILE [#501 LT 2.] DO1", "IF [#501 GE 2.] GOTO 310"),
                                                ("linuxcnc", "o1 while [#501 LT 2.]", "o3 if [#501 LT 2.]"),
                                                ("isg", "$WHILE P1 < 2", "$IF P1 < 2")])
def test_the_plate_keeps_its_loops_and_its_frame_after_them_runs_where_it_stands(target: str, loop: str,
                                                                                 jump: str) -> None:
    """TRANS X5 Y5 / AROT RPL=30 after the loops and the jump run once, where the text has them: the
    program stays symbolic and the rotated move is the hand-derived point (10, 0) turned 30 degrees about
    the origin, then moved by (5, 5): (5 + 10 cos 30, 5 + 10 sin 30) = (13.660254, 10)."""
    out, warnings = _translate(PLATE, target)
    assert "flattened" not in warnings, warnings
    code = _code(out)
    assert any(line.endswith(loop) for line in code) and any(line.endswith(jump) for line in code), out
    assert ("feed", 13.660254, 10.0, -1.0) in [(m, round(x, 6), round(y, 6), z) for m, x, y, z in
                                                _moves(out, target)]
    _verified(PLATE, out, target)
    if target == "linuxcnc" and available():
        _same_in_rs274(PLATE, out)


@pytest.mark.parametrize("text, target", [
    ("G710 G90 G17 G0 X0 Y0 Z5 F100\nR1=0\nWHILE R1<2\nR1=R1+1\nATRANS X5\nG1 X=R1\nENDWHILE\nTRANS\nG0 X0\nM30\n",
     "fanuc"),
    ("G710 G90 G17 G0 X0 Y0 Z5 F100\nR1=0\nBACK: R1=R1+1\nATRANS X5\nG1 X=R1 Y0\nIF R1<2 GOTOB BACK\nTRANS\nM30\n",
     "fanuc"),
    ("G710 G90 G17 G0 X0 Y0 Z5 F100\nR1=0\nIF R1>0 GOTOF SKIP\nTRANS X5\nSKIP: G1 X1 Y0\nTRANS\nM30\n",
     "linuxcnc"),
])
def test_a_frame_command_that_a_run_repeats_or_skips_flattens_the_program(text: str, target: str) -> None:
    """In a loop, after a label a jump comes back to, or over a jump: evaluated once in the text's order it
    would move otherwise than the run, so the program is flattened with the warning and moves as the source."""
    out, warnings = _translate(text, target)
    assert "the program is flattened" in warnings and "a coordinate frame in a program kept symbolically" in warnings, \
        warnings
    _verified(text, out, target)


@pytest.mark.parametrize("assignments, kept", [("R1=40 R2=30 R3=R4+1", True), ("R1=5 R2=R1", False)])
def test_assignments_of_one_block_are_fanuc_lines_when_none_reads_what_another_set(assignments: str,
                                                                                   kept: bool) -> None:
    """The neutral block reads every right-hand side first: ``R1=5 R2=R1`` sets R2 to the R1 from before (1
    here), which two Fanuc lines would not: that block flattens the program."""
    text = f"G710 G90 G0 X0 Y0 Z5 F100\nR1=1\nR4=2\n{assignments}\nWHILE R1>0\nR1=R1-10\nG1 X=R2 Y=R1\nENDWHILE\nM30\n"
    out, warnings = _translate(text, "fanuc")
    if kept:
        assert "flattened" not in warnings and "\n#501=40.\n#502=30.\n#503=#504+1.\n" in out, (warnings, out)
    else:
        assert "the program is flattened" in warnings and "reads a variable another sets first" in warnings
        assert ("feed", 1.0, -5.0, 5.0) in _moves(text, "siemens")
    _verified(text, out, "fanuc")
