"""Variables and control flow written for SINUMERIK (``dialects/siemens/control_writing.py``): Fanuc Macro B,
LinuxCNC o-words and ISG ``$`` statements kept symbolic where each construct has an exact 840D spelling (R
parameters, ``IF``/``ELSE``/``ENDIF``, ``WHILE``/``ENDWHILE``, ``REPEAT``/``UNTIL``, ``FOR .. TO``,
``GOTOF``/``GOTOB``), flattened with the usual warning otherwise.

Expected texts are written by hand from the 840D spellings (``control_writing``'s sources); expected points
are derived by hand from the source programs, and the written program read back by the SINUMERIK reader
must move through them (``verify`` and the SINUMERIK toolpath)."""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines


def _translate(text: str, source: str) -> tuple[str, str]:
    """The SINUMERIK text and the warnings."""
    out, warnings = io.StringIO(newline=""), io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target="siemens",
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def _verified(text: str, out: str, source: str) -> Any:
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="in.nc",
                          file_out="out.mpf", source=source, target="siemens")
    assert report.ok and report.max_deviation == 0, report.summary()
    return report


def _points(out: str) -> list[tuple[float, float, float]]:
    return [(e["x"], e["y"], e["z"]) for e in toolpath_events(io.StringIO(out), file="out.mpf", dialect="siemens")
            if "move" in e]


FANUC_WHILE = ("G21 G90 G17\n#501=0\n#502=5.\nG0 X0 Y0 Z5.\nWHILE [#501 LT 3] DO1\nG1 X[#501*10+#502] Y#502 F100.\n"
               "#501=#501+1\nEND1\nIF [#502 GT 4] GOTO 20\nG0 X99.\nN20 G0 Z10.\nM30\n")


def test_fanuc_macro_b_while_and_conditional_goto_are_written_symbolically() -> None:
    out, warnings = _translate(FANUC_WHILE, "fanuc")
    assert out.splitlines() == ["G17 G710 G90", "R1=0", "R2=5", "G0 X0. Y0. Z5.", "WHILE R1<3",
                                "G1 X=R1*10+R2 Y=R2 F100.", "R1=R1+1", "ENDWHILE", "IF R2>4 GOTOF N20", "G0 X99.",
                                "N20 G0 Z10.", "M30"]
    assert "flattened" not in warnings
    _verified(FANUC_WHILE, out, "fanuc")
    # by hand: X = 10 i + 5 for i = 0, 1, 2 at Y5, then #502 = 5 > 4 jumps over X99 to Z10
    assert _points(out) == [(0, 0, 5), (5, 5, 5), (15, 5, 5), (25, 5, 5), (25, 5, 10)]


def test_a_backward_jump_is_gotob() -> None:
    text = "G21 G90\n#501=0\nN10 #501=#501+1\nG1 X#501 F100.\nIF [#501 LT 3] GOTO 10\nM30\n"
    out, warnings = _translate(text, "fanuc")
    assert out.splitlines() == ["G710 G90", "R1=0", "N10 R1=R1+1", "G1 X=R1 F100.", "IF R1<3 GOTOB N10", "M30"]
    _verified(text, out, "fanuc")
    assert [p[0] for p in _points(out)] == [1, 2, 3]


LINUXCNC_DO_IF = ("G21 G90 G17\n#500 = 0\no100 do\n  #500 = [#500 + 1]\n  o110 if [#500 GT 2]\n"
                  "    G1 X[#500 * 2] Y[COS[60] * 4] F200\n  o110 else\n    G0 X[#500] Y0\n  o110 endif\n"
                  "o100 while [#500 LT 4]\nM2\n")


def test_linuxcnc_do_while_and_if_else_are_written_as_repeat_until_and_if_else() -> None:
    out, warnings = _translate(LINUXCNC_DO_IF, "linuxcnc")
    assert out.splitlines() == ["G17 G710 G90", "R0=0", "REPEAT", "R0=R0+1", "IF R0>2", "G1 X=R0*2 Y=COS(60)*4 F200.",
                                "ELSE", "G0 X=R0 Y0.", "ENDIF", "UNTIL NOT (R0<4)", "M2"]
    assert "flattened" not in warnings
    _verified(LINUXCNC_DO_IF, out, "linuxcnc")
    # by hand: #500 = 1, 2 rapid to X1, X2 at Y0; 3, 4 feed to X6, X8 at Y = cos 60 degrees * 4 = 2
    assert [(round(x, 9), round(y, 9)) for x, y, _ in _points(out)] == [(1, 0), (2, 0), (6, 2), (8, 2)]


ISG_FOR_GOTO = ("%100\nG71 G90 G17\nP1=0\n$FOR P2 = 1, 3, 1\nG01 X[P2*5] Y=P1 F100\nP1=P1+2\n$ENDFOR\n"
                "$IF P1 > 5\nG00 Z10\n$ELSE\nG00 Z20\n$ENDIF\n$GOTO [SKIP]\nG00 X99\n[SKIP] G00 X1 Y1\nM30\n")


def test_isg_for_if_and_named_jump_are_written_as_for_if_and_gotof_to_a_label() -> None:
    out, warnings = _translate(ISG_FOR_GOTO, "isg")
    assert out.splitlines() == ["%_N_PROG100_MPF", "G17 G710 G90", "R1=0", "FOR R2=1 TO 3", "G1 X=R2*5 Y=R1 F100.",
                                "R1=R1+2", "ENDFOR", "IF R1>5", "G0 Z10.", "ELSE", "G0 Z20.", "ENDIF", "GOTOF SKIP",
                                "G0 X99.", "SKIP: G0 X1. Y1.", "M30"]
    assert "flattened" not in warnings
    _verified(ISG_FOR_GOTO, out, "isg")
    # by hand: X5 Y0, X10 Y2, X15 Y4; P1 = 6 > 5: Z10; the jump skips X99
    assert _points(out) == [(5, 0, 0), (10, 2, 0), (15, 4, 0), (15, 4, 10), (1, 1, 10)]


@pytest.mark.parametrize("source, text, why", [
    ("fanuc", "G21 G90\n#1=2.\nG0 X#1\nM30\n", "variable #1 (only #500-#999 are R parameters)"),
    ("linuxcnc", "G21 G90\n#500=0\no1 repeat [2]\nG0 X1\no1 endrepeat\nM2\n", "counted REPEAT loops"),
    ("linuxcnc", "G21 G90\n#500=3\no1 if [#500 LT 1]\nG0 X1\no1 elseif [#500 LT 5]\nG0 X2\no1 endif\nM2\n",
     "ELSEIF branches"),
    ("isg", "%1\nG71 G90\n$FOR P1 = 0, 4, 2\nG00 X=P1\n$ENDFOR\nM30\n", "step is not 1"),
    ("linuxcnc", "G21 G90\n#<depth>=2\nG0 Z#<depth>\nM2\n", "named variable"),
    ("linuxcnc", "G21 G90\n#500=1\n#500=2 G0 X#500 Y1\nG0 X#500\nM2\n", "assignment beside other words"),
    ("fanuc", "G21 G90\n#501=1\nIF [#501 GT 0] GOTO 20\nG0 X9.\nN20 G0 X1.\nN20 G0 X2.\nM30\n",
     "a jump to N20, which is on 2 blocks"),
])
def test_what_has_no_exact_spelling_is_flattened_with_the_warning(source: str, text: str, why: str) -> None:
    out, warnings = _translate(text, source)
    assert "the program is flattened" in warnings and why in warnings, warnings
    code = [line for line in out.splitlines() if not line.startswith(";")]
    assert not any(w in line for line in code for w in ("R1=", "IF", "WHILE", "FOR", "REPEAT", "GOTO")), out
    _verified(text, out, source)


def _random_program(rng: random.Random) -> str:
    """A Fanuc macro program: two R-parameter counters, a WHILE loop, a conditional forward jump."""
    steps = rng.randint(1, 4)
    step = rng.choice([1, 2, 3])
    a, b = rng.randint(-5, 5), rng.randint(1, 9)
    limit = rng.randint(1, 8)
    lines = ["G21 G90 G17", f"#510={a}.", f"#511={b}.", "G0 X0 Y0 Z5.", f"WHILE [#510 LT {a + steps * step}] DO1",
             f"G1 X[#510*{b}+#511] Y[#511-#510] F{rng.randint(50, 500)}.", f"#510=#510+{step}", "END1",
             f"IF [#511 GT {limit}] GOTO 40", f"G0 X{rng.randint(-20, 20)}.", "N40 G0 Z20.", "M30"]
    return "\n".join(lines) + "\n"


def test_random_macro_programs_read_back_to_the_same_toolpath() -> None:
    rng = random.Random(2811)
    for _ in range(25):
        text = _random_program(rng)
        out, warnings = _translate(text, "fanuc")
        assert "flattened" not in warnings and "WHILE R10<" in out, (text, out)
        _verified(text, out, "fanuc")
