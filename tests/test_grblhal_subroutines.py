"""grblHAL's numbered o-word subroutines (a build with ``NGC_EXPRESSIONS_ENABLE``): read, simulated and written.

Expected moves are derived by hand from grblHAL's source (github.com/grblHAL/core, stored commit f80fc34,
``ngc_flowctrl.c`` ``NGCFlowCtrl_Call``/``NGCFlowCtrl_Sub``, ``ngc_params.c``): a call fills the arguments it
does not give with the caller's values, and finds only a sub whose definition the flow has passed. rs274 is
the oracle where grblHAL and LinuxCNC run the same text alike (a call that gives all 30 arguments).
"""

from __future__ import annotations

import io
import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274
from tests.support.grblhal_rules import grblhal_problems

EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))

INHERIT = """G21 G17 G90
#2 = 7
o100 sub
  G1 X#1 Y#2 F100
o100 endsub
G0 X0 Y0 Z5
o100 call [3]
o100 call [4] [5]
M2
"""
"""The second argument is not given to the first call: grblHAL hands the sub the caller's #2 (7), rs274 0."""

SLOTS = """G21 G17 G90
o200 sub
  G91 G1 Z-2 F50
  G1 X#1 F100
  G0 Z2
  G90
  o200 if [#1 GT 8]
    o200 return
  o200 endif
  G91 G0 Y5
  G90
o200 endsub
G0 X0 Y0 Z5
#<w> = 4
o1 repeat [3]
  o200 call [#<w>]
  #<w> = [#<w> + 3]
o1 endrepeat
G0 Z10
M2
"""
"""A sub with a return in its body, called in a loop with a computed argument."""


def _moves(text: str, dialect: str) -> list[tuple[str, float, float, float]]:
    return [(e["move"], round(e["x"], 3), round(e["y"], 3), round(e["z"], 3))
            for e in toolpath_events(io.StringIO(text, newline=""), file="t", dialect=dialect, setup=EXPRESSIONS)
            if "move" in e]


def _rs274_moves(text: str) -> list[tuple[str, float, float, float]]:
    return [(e["move"], round(e["x"], 3), round(e["y"], 3), round(e["z"], 3))
            for e in rs274.canonical_moves(rs274.run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]


def _translate(text: str, source: str) -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text, newline=""), out, file="t.ngc", source=source, target="grblhal", setup=EXPRESSIONS,
              diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def _errors(text: str) -> list[str]:
    with pytest.raises(ErrorList) as info:
        read_program(io.StringIO(text), file="t.gcode", dialect="grblhal", setup=EXPRESSIONS)
    return [str(e) for e in info.value.errors]


def test_an_argument_not_given_is_the_callers_on_grblhal_and_zero_on_linuxcnc() -> None:
    assert _moves(INHERIT, "grblhal") == [("rapid", 0, 0, 5), ("feed", 3, 7, 5), ("feed", 4, 5, 5)]
    assert _moves(INHERIT, "linuxcnc") == [("rapid", 0, 0, 5), ("feed", 3, 0, 5), ("feed", 4, 5, 5)]


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_reads_an_argument_not_given_as_zero() -> None:
    """The LinuxCNC side of the difference above, from LinuxCNC's own interpreter."""
    assert _rs274_moves(INHERIT) == [("rapid", 0, 0, 5), ("feed", 3, 0, 5), ("feed", 4, 5, 5)]


def test_a_grblhal_program_with_subs_is_simulated_as_grblhal_runs_it() -> None:
    expected: list[tuple[str, float, float, float]] = [("rapid", 0, 0, 5)]
    x, y = 0.0, 0.0
    for w in (4, 7, 10):  # the argument: X moves by it; from 10 on (> 8) the sub returns before its Y step
        expected += [("feed", x, y, 3), ("feed", x + w, y, 3), ("rapid", x + w, y, 5)]
        x += w
        if w <= 8:
            expected.append(("rapid", x, y + 5, 5))
            y += 5
    expected.append(("rapid", x, y, 10))
    assert _moves(SLOTS, "grblhal") == expected


def test_a_linuxcnc_program_with_subs_reaches_grblhal_native_and_moves_alike() -> None:
    text, warnings = _translate(INHERIT, "linuxcnc")
    assert warnings == []
    zeros = " [0.]" * 29
    assert text == ("G17 G21 G90\n#2=7.\no100 sub\nG1 X#1 Y#2 F100.\no100 endsub\nG0 X0. Y0. Z5.\n"
                    f"o100 call [3.]{zeros}\no100 call [4.] [5.]{zeros[5:]}\nM2\n")
    assert grblhal_problems(text) == []
    assert _moves(text, "grblhal") == _moves(INHERIT, "linuxcnc")
    report = verify_lines(io.StringIO(INHERIT), io.StringIO(text), file_in="t.ngc", file_out="t.gcode",
                          source="linuxcnc", target="grblhal", setup=EXPRESSIONS, tolerance=0.0)
    assert report.ok and report.moves == 3


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_written_subs_run_in_rs274_as_grblhal_is_simulated() -> None:
    """With every argument given, grblHAL's call is rs274's: LinuxCNC's interpreter runs the output."""
    for source in (INHERIT, SLOTS):
        text, _ = _translate(source, "linuxcnc")
        assert "call" in text and grblhal_problems(text) == []
        assert _rs274_moves(text) == _moves(text, "grblhal") == _moves(source, "linuxcnc")


def test_a_grblhal_program_with_subs_translates_to_itself_verbatim() -> None:
    text, warnings = _translate(INHERIT, "grblhal")
    assert warnings == [] and text == INHERIT


def test_a_call_before_its_definition_is_refused_when_read_and_flattened_when_written() -> None:
    later = "G21\nG0 X0 Y0 Z5\no100 call [1]\nM2\no100 sub\nG1 X#1 F100\no100 endsub\n"
    assert _errors(later)[0].startswith("t.gcode:3:1: error: grblHAL finds a sub only once the program has passed "
                                        "its definition")
    assert _moves(later, "linuxcnc") == [("rapid", 0, 0, 5), ("feed", 1, 0, 5)]  # rs274 looks ahead
    text, warnings = _translate(later, "linuxcnc")
    code = [row for row in text.splitlines() if not row.startswith("(")]
    assert code == ["G21", "G0 X0. Y0. Z5.", "G1 X1. F100.", "M2"]
    assert "before its sub's definition" in warnings[0]


@pytest.mark.parametrize("program, message", [
    ("G21\no100 sub\nG0 X#30\no100 endsub\no100 call" + " [1]" * 29 + "\nM2\n",
     "t.gcode:5:1: error: a grblHAL call with 29 arguments leaves #30 unset"),
    ("G21\no100 return\nM2\n", "t.gcode:2:1: error: a grblHAL return outside the body of the sub it names"),
    ("G21\no100 sub\no101 return\no100 endsub\nM2\n",
     "t.gcode:3:1: error: a grblHAL return outside the body of the sub it names"),
    ("G21\no<probe> call\nM2\n", "t.gcode:2:1: error: a named grblHAL subroutine"),
])
def test_what_grblhal_runs_otherwise_is_a_located_error(program: str, message: str) -> None:
    assert _errors(program)[0].startswith(message)


def test_the_checker_refuses_a_call_before_its_sub() -> None:
    assert grblhal_problems("G21\no100 call\no100 sub\no100 endsub\nM2\n") == [
        "2: o100 call before its sub's definition (flow control syntax error)"]
    assert grblhal_problems("G21\no100 sub\no100 endsub\no100 call\nM2\n") == []

