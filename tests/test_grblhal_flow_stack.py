"""grblHAL's flow control stack holds 20 open constructs: ``stack_push`` (if, do, while, repeat, call) refuses the
21st with "flow control stack overflow" (``NGC_STACK_DEPTH`` 20, ``ngc_flowctrl.c``, grblHAL core stored commit
f80fc34) [V]. A grblHAL program nesting deeper is a located error where it is read; a LinuxCNC program nesting
deeper (rs274 has no such bound) reaches grblHAL flattened, with a warning at the construct. Depths counted by
hand from the programs below.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events

EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))


def _nested(depth: int, body: str = "G1 X1. F100.") -> list[str]:
    opened = [f"o{100 + i} if [#1 GT 0]" for i in range(depth)]
    return opened + [body] + [f"o{100 + i} endif" for i in reversed(range(depth))]


def _program(depth: int) -> str:
    return "\n".join(["G21 G90 G0 X0 Y0 Z5", "#1=1", *_nested(depth), "M2"]) + "\n"


def _moves(text: str) -> list[tuple[object, ...]]:
    events = toolpath_events(io.StringIO(text), file="in.nc", dialect="grblhal", setup=EXPRESSIONS)
    return [(e["move"], e["x"]) for e in events if "move" in e]


def test_twenty_open_conditions_run() -> None:
    assert _moves(_program(20)) == [("rapid", 0), ("feed", 1)]


def test_the_twenty_first_is_refused_where_it_stands() -> None:
    """Line 3 is o100 (entry 1), line 23 o120 (entry 21)."""
    with pytest.raises(ErrorList) as caught:
        _moves(_program(21))
    assert str(caught.value.errors[0]).startswith("in.nc:23:1: error: 'o120 if [#1 GT 0]' would hold entry 21 of the "
                                                  "controller's flow control stack, which has 20")


def test_a_call_adds_what_its_sub_opens() -> None:
    """The sub opens 19 conditions; called inside one condition: 1 + the call + 19 = 21 (line 45, the call)."""
    sub = ["o10 sub", *_nested(19), "o10 endsub"]
    text = "\n".join(["G21 G90 G0 X0 Y0 Z5", "#1=1", *sub, "o1 if [#1 GT 0]", "o10 call", "o1 endif", "M2"]) + "\n"
    with pytest.raises(ErrorList) as caught:
        _moves(text)
    assert str(caught.value.errors[0]).startswith("in.nc:45:1: error: 'o10 call' would hold entry 21")
    assert _moves(text.replace("o1 if [#1 GT 0]\no10 call\no1 endif", "o10 call")) == [("rapid", 0), ("feed", 1)]


def test_a_linuxcnc_program_nesting_deeper_reaches_grblhal_flattened() -> None:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(_program(21)), out, file="in.ngc", source="linuxcnc", target="grblhal", setup=EXPRESSIONS,
              diagnostics=Diagnostics(warn_stream=warnings))
    assert out.getvalue() == "G21 G90 G0 X0. Y0. Z5.\nG1 X1. F100.\nM2\n"
    assert "line 23: 'o120 if [#1 GT 0]' would hold entry 21" in warnings.getvalue()
    out = io.StringIO()
    translate(io.StringIO(_program(20)), out, file="in.ngc", source="linuxcnc", target="grblhal", setup=EXPRESSIONS,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert "o119 if [#1 GT 0.]" in out.getvalue()


RECURSION = ("G21 G90 G0 X0 Y0 Z5\no100 sub\no101 if [#1 GT 0]\no102 if [#1 GT 0]\nG1 X#1 F100.\no100 call [#1 - 1]\n"
             "o102 endif\no101 endif\no100 endsub\no100 call [{n}]\nM2\n")
"""A sub that calls itself inside two conditions, called with n from the main program: level k (the main
program's call is level 1) holds the stack's entry 3k - 2 for its call, 3k - 1 and 3k for its two conditions
(grblHAL pushes a condition whatever its value, ``ngc_flowctrl.c`` ``NGCFlowCtrl_If``: ``stack_push`` unless
the branch around it is skipped [V]). The last level (#1 = 0) opens only its first condition, the second being
in a skipped branch: call [n] reaches entry 3(n + 1) - 1 = 3n + 2, within 20 for n = 6, entry 21 for n = 7 at
level 7's second condition (line 4). The text nests only 1 + 3 deep: the overflow shows only as the sub runs."""


def test_a_sub_calling_itself_overflows_the_stack_as_it_runs() -> None:
    assert _moves(RECURSION.format(n=6)) == [("rapid", 0)] + [("feed", x) for x in range(6, 0, -1)]
    with pytest.raises(ErrorList) as caught:
        _moves(RECURSION.format(n=7))
    (error,) = caught.value.errors
    assert str(error).startswith("in.nc:4:1: error: 'o102 if [#1 GT 0]' would hold entry 21 of the controller's "
                                 "flow control stack, which has 20")



def test_a_linuxcnc_sub_calling_itself_reaches_grblhal_flattened() -> None:
    """Kept as o-words, grblHAL would stop at entry 21 (the test above), and how deep a recursion goes shows only
    as it runs: the sub's body counts as nested to rs274's 9 nested calls, 3 entries a level (its two conditions
    and its call): 1 + 8 x 3 + 3 = 28 at the main program's call, over 20, so the program is flattened, the moves
    as the source runs them. A recursion one condition shallower, 1 + 8 x 2 + 2 = 19, stays o-words
    (tests/test_grblhal_subroutines.py, a sub that calls itself)."""
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(RECURSION.format(n=7)), out, file="in.ngc", source="linuxcnc", target="grblhal",
              setup=EXPRESSIONS, diagnostics=Diagnostics(warn_stream=warnings))
    assert [line for line in out.getvalue().splitlines() if not line.startswith("(")] == (
        ["G21 G90 G0 X0. Y0. Z5."] + [f"G1 X{x}. F100." for x in range(7, 0, -1)] + ["M2"])
    assert "line 10: 'o100 call [7]' would hold entry 28 of the controller's flow control stack" in warnings.getvalue()
