"""Loops, jumps and recursion with random constant and degenerate bounds, in the three families that run
them: ISG ``$WHILE``/``$FOR``/``$REPEAT``/``$DO``/``$IF``, Fanuc ``WHILE``/``GOTO``/``M99``/``M98``
recursion, LinuxCNC o-word ``while``/``repeat``/``do`` and recursive calls; bodies of moves, counters and
canned cycles with repeat counts. These found programs whose run counted iterations, not work (an
endless loop around a 9999-hole cycle, ``$FOR`` with step 0, ``o repeat [99999999]``: minutes of CPU).

Each case translates to a target without control flow (the program is flattened) and to the simulator:
it must end, within the fuzzer's time per case, with output or located errors. The work bound is drawn
small (``<Limits repeatedWork>`` up to 5000, ``movesPerBlock`` 2000: a cycle of 400 holes is 1600 moves)
so that a bounded case ends in a fraction of a second and an unbounded one stands out by its time; the
default's figure is pinned in ``tests/test_interp_work.py``.
"""

from __future__ import annotations

from typing import Callable

from hypothesis import strategies as st

from postproc.setup.machine_setup import Limits, MachineSetup
from tests.support.fuzzing import check_toolpath, check_translation

from . import Case

KIND = "loops"

BOUNDS = ["0", "1", "2", "3", "-1", "0.5", "99999999", "1E9", "7"]
"""Constant bounds and counts: none, one, a few, negative, fractional, huge."""
STEPS = ["1", "0", "-1", "0.5", "3", "-0.25"]
"""Counted-loop steps: 0 never reaches the end, a negative one never reaches a larger end."""

FANUC_BODY = ["G01 X#1 F100", "G00 Y1.", "#1=#1+1", "#2=#2-1", "G81 X0 Y0 Z-1. R1. K400 F100",
              "G81 X1. Y1. Z-1. R1. F100", "G80", "G91 X1.", "G90", "M98 P1000", "M99", "GOTO 10",
              "IF [#1 GT {b}] GOTO 20", "N10 G00 X#2", "N20 G00 Z5."]
ISG_BODY = ["G01 X[P1] F100", "G00 Y1", "P1=P1+1", "P2=P2-1", "G81 Z-1 R1 F100", "G80", "G91 X1", "G90",
            "LL SUB", "$BREAK", "$CONTINUE", "$IF P1 > {b}", "$ENDIF", "N20: G00 Z5", "$GOTO N20"]
NGC_BODY = ["G01 X#1 F100", "G00 Y1", "#1=[#1+1]", "#2=[#2-1]", "G81 X0 Y0 Z-1 R1 L400 F100", "G80",
            "G91 X1", "G90", "o<r> call [#1]", "o9 if [#1 GT {b}]", "o9 endif"]


def _body(lines: list[str]) -> st.SearchStrategy[list[str]]:
    return st.lists(st.tuples(st.sampled_from(lines), st.sampled_from(BOUNDS)).map(
        lambda pair: pair[0].replace("{b}", pair[1])), min_size=0, max_size=4)


@st.composite
def fanuc(draw: st.DrawFn) -> str:
    body = draw(_body(FANUC_BODY))
    bound = draw(st.sampled_from(BOUNDS))
    shape = draw(st.sampled_from(["while", "always", "goto", "m99", "recursion", "nested"]))
    head = ["O1", "G21 G90 G00 X0 Y0 Z10.", "#1=0", "#2=0"]
    if shape == "while":
        loop = [f"WHILE [#1 LT {bound}] DO1", *body, "#1=#1+1", "END1"]
    elif shape == "always":
        loop = ["WHILE [1 EQ 1] DO1", *body, "END1"]
    elif shape == "goto":
        loop = ["N30 G00 X1.", *body, f"IF [#1 LT {bound}] GOTO 30"]
    elif shape == "m99":
        loop = [*body, "M99"]
    elif shape == "recursion":  # each level calls itself twice down to the bound
        loop = ["M98 P1000", "M30", "O1000", "#1=#1+1", f"IF [#1 GT {bound}] GOTO 9", *body, "M98 P1000",
                "M98 P1000", "N9 #1=#1-1", "M99"]
        return "\n".join(head + loop) + "\n"
    else:
        loop = [f"WHILE [#1 LT {bound}] DO1", "#2=0", f"WHILE [#2 LT {bound}] DO2", *body, "#2=#2+1", "END2",
                "#1=#1+1", "END1"]
    return "\n".join(head + loop + ["M30", "O1000", "G00 Z1.", "M99"]) + "\n"


@st.composite
def isg(draw: st.DrawFn) -> str:
    body = draw(_body(ISG_BODY))
    bound, step = draw(st.sampled_from(BOUNDS)), draw(st.sampled_from(STEPS))
    shape = draw(st.sampled_from(["while", "always", "for", "repeat", "do", "goto"]))
    loop = {
        "while": [f"$WHILE P1 < {bound}", *body, "P1=P1+1", "$ENDWHILE"],
        "always": ["$WHILE 1", *body, "$ENDWHILE"],
        "for": [f"$FOR P3 = 0, {bound}, {step}", *body, "$ENDFOR"],
        "repeat": ["$REPEAT", *body, "P1=P1+1", f"$UNTIL P1 > {bound}"],
        "do": ["$DO", *body, "P1=P1+1", f"$ENDDO P1 < {bound}"],
        "goto": ["N30: G00 X1", *body, "P1=P1+1", f"$IF P1 < {bound} $GOTO N30"],
    }[shape]
    sub = ["%L SUB", "G00 Z1", "M17"]
    return "\n".join([*sub, "%1", "G71 G90 G00 X0 Y0 Z10", "P1=0", "P2=0", *loop, "M30"]) + "\n"


@st.composite
def linuxcnc(draw: st.DrawFn) -> str:
    body = draw(_body(NGC_BODY))
    bound = draw(st.sampled_from(BOUNDS))
    shape = draw(st.sampled_from(["while", "always", "repeat", "do", "recursion"]))
    sub = ["o<r> sub", "#<d>=[#1+1]", f"o8 if [#<d> LT {bound}]", "o<r> call [#<d>]", "o<r> call [#<d>]",
           "o8 endif", "G00 Z1", "o<r> endsub"] if shape == "recursion" else \
        ["o<r> sub", "G00 Z1", "o<r> endsub"]
    loop = {
        "while": [f"o1 while [#1 LT {bound}]", *body, "#1=[#1+1]", "o1 endwhile"],
        "always": ["o1 while [1]", *body, "o1 endwhile"],
        "repeat": [f"o1 repeat [{bound}]", *body, "o1 endrepeat"],
        "do": ["o1 do", *body, "#1=[#1+1]", f"o1 while [#1 LT {bound}]"],
        "recursion": ["o<r> call [0]", *body],
    }[shape]
    return "\n".join([*sub, "G21 G90 G00 X0 Y0 Z10", "#1=0", "#2=0", *loop, "M2"]) + "\n"


def _run(source: str, setup: MachineSetup) -> Callable[[str], object]:
    def run(program: str) -> object:
        check_toolpath(source, program, setup)
        return check_translation(source, "grbl", program, setup, warn=True)
    return run


def cases() -> st.SearchStrategy[Case]:
    bounds = st.integers(1, 5000).map(lambda n: MachineSetup(limits=Limits(repeated_work=n, call_depth=16,
                                                                           moves_per_block=2000)))
    return st.one_of(
        st.tuples(st.just("fanuc"), fanuc(), bounds),
        st.tuples(st.just("isg"), isg(), bounds),
        st.tuples(st.just("linuxcnc"), linuxcnc(), bounds),
    ).map(lambda c: Case(f"loops {c[0]}", "grbl", c[1], _run(c[0], c[2]), c[2]))
