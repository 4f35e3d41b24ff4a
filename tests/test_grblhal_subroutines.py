"""grblHAL's numbered o-word subroutines (a build with ``NGC_EXPRESSIONS_ENABLE``): read, simulated and written.

Expected moves are derived by hand from grblHAL's source (github.com/grblHAL/core, stored commit f80fc34,
``ngc_flowctrl.c`` ``NGCFlowCtrl_Call``/``NGCFlowCtrl_Sub``, ``ngc_params.c``): a call fills the arguments it
does not give with the caller's values, and finds only a sub whose definition the flow has passed. rs274 is
the oracle where grblHAL and LinuxCNC run the same text alike (a call that gives all 30 arguments).
"""

from __future__ import annotations

import io
from pathlib import Path
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


def test_a_sub_that_calls_itself_is_read_and_runs_with_its_inherited_argument() -> None:
    """The defect: a call in its own sub's body was refused as "before its definition", though grblHAL registers
    the sub when the flow passes ``o100 sub``, before the body first runs. #1 3 is inherited by the first call
    (``NGCFlowCtrl_Call``), each level counts it down one and calls again while it is above 0: X2, X1, X0."""
    recursive = ("G21 G17 G90\n#1=3\no100 sub\n#1=[#1-1]\nG1 X#1 F100\no101 if [#1 GT 0]\no100 call\n"
                 "o101 endif\no100 endsub\no100 call\nM2\n")
    assert _moves(recursive, "grblhal") == [("feed", 2, 0, 0), ("feed", 1, 0, 0), ("feed", 0, 0, 0)]
    text, warnings = _translate(recursive, "grblhal")
    assert text == recursive and warnings == []
    text, warnings = _translate(recursive, "linuxcnc")  # written as grblHAL's own call, not flattened
    assert "o100 call" in text and warnings == [] and _moves(text, "grblhal") == _moves(recursive, "linuxcnc")


def test_the_sources_bound_of_nested_calls_comes_from_the_run_not_the_default_registry(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """The writer reads the source's bound of nested calls (rs274's 9, which keeps the sub above as o-words) from
    the run's own interpreter step (``SUBPROGRAM_RULES_KEY``), in the run and in its dry run alike: a translation
    given its own registry works with the global one out of reach."""
    import postproc.plugins
    registry = postproc.plugins.default_registry()

    def unreachable() -> None:
        raise AssertionError("the global registry was asked")

    monkeypatch.setattr(postproc.plugins, "default_registry", unreachable)
    recursive = ("G21 G17 G90\n#1=3\no100 sub\n#1=[#1-1]\nG1 X#1 F100\no101 if [#1 GT 0]\no100 call\n"
                 "o101 endif\no100 endsub\no100 call\nM2\n")
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(recursive, newline=""), out, file="t.ngc", source="linuxcnc", target="grblhal",
              setup=EXPRESSIONS, diagnostics=diagnostics, registry=registry)
    assert "o100 call" in out.getvalue() and diagnostics.warnings == []


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


RECURSION = "G21 G90 F100\no100 sub\no101 if [#1 GT 0]\nG1 X#1\no100 call [#1 - 1]\no101 endif\no100 endsub\no100 call [{n}]\nM2\n"
"""A sub that calls itself, bounded by its argument: call [n] nests n + 1 calls (the last, with #1 = 0, moves
nothing). grblHAL registers ``o100 sub`` when the flow passes it, before its body ever runs (``add_sub``), so
the call in the body finds it; ``ngc_call_push`` runs 10 nested calls (``NGC_MAX_CALL_LEVEL``) and refuses the
11th ("flow control stack overflow"): call [9] runs, call [10] does not."""


def test_a_sub_that_calls_itself_is_read_and_run_to_grblhals_depth() -> None:
    assert _moves(RECURSION.format(n=9), "grblhal") == [("feed", x, 0, 0) for x in range(9, 0, -1)]
    assert grblhal_problems(RECURSION.format(n=9)) == []
    with pytest.raises(ErrorList) as info:
        _moves(RECURSION.format(n=10), "grblhal")
    inner = "in o100, called from t line 5"
    assert [str(e) for e in info.value.errors] == [
        "t:5:1: error: 'o100 call [#1 - 1]' exceeds the controller's bound of 10 nested calls (it refuses a deeper "
        f"one) ({inner}; {inner}; {inner}; ... 4 more; {inner}; {inner}; in o100, called from t line 8)"]

LINUXCNC_TOO_DEEP = ("t:5:1: error: 'o100 call [#1 - 1]' exceeds the controller's bound of 9 nested calls (it refuses "
                     "a deeper one)")


def test_linuxcnc_runs_one_nested_call_fewer() -> None:
    assert _moves(RECURSION.format(n=8), "linuxcnc") == [("feed", x, 0, 0) for x in range(8, 0, -1)]
    with pytest.raises(ErrorList) as info:
        _moves(RECURSION.format(n=9), "linuxcnc")
    assert str(info.value.errors[0]).startswith(LINUXCNC_TOO_DEEP)


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_recursion_as_simulated_and_refuses_a_tenth_call() -> None:
    """With its one argument given, the grblHAL text is RS274/NGC that rs274 runs alike, to 9 nested calls."""
    text = RECURSION.format(n=8)
    assert _rs274_moves(text) == _moves(text, "grblhal") == _moves(text, "linuxcnc")
    with pytest.raises(rs274.RS274Error, match="Too many subroutine levels"):
        rs274.run_rs274(RECURSION.format(n=9))


def test_the_checker_refuses_a_call_before_its_sub() -> None:
    assert grblhal_problems("G21\no100 call\no100 sub\no100 endsub\nM2\n") == [
        "2: o100 call before its sub's definition (flow control syntax error)"]
    assert grblhal_problems("G21\no100 sub\no100 endsub\no100 call\nM2\n") == []



# -- Fanuc subprograms (M98 P L, O<n> .. M99) as grblHAL subs ------------------------------------------------

ROOT = Path(__file__).resolve().parents[1]
REPEAT = ROOT / "tests" / "golden" / "macro" / "subprogram_repeat.nc"
"""Fanuc M98 P L and the packed P form; beside it a hand-written LinuxCNC equivalent (``.ngc``)."""
NESTED = """%
O0010
G21 G17 G90
G00 X0 Y0 Z5.
M98 P100 L2
G00 Z20.
M30
O100 (COLUMN OF TWO HOLES)
G91 G00 X10.
M98 P200
G00 Y10.
M98 P200
G00 Y-10.
G90
M99
O200 (ONE HOLE)
G91 G01 Z-3. F80.
G00 Z3. M99
%
"""
"""A subprogram calling one written after it, and an M99 in a block that moves."""
NESTED_MOVES = [("rapid", 0, 0, 5)] + [
    move for column in (10, 20) for move in (
        ("rapid", column, 0, 5), ("feed", column, 0, 2), ("rapid", column, 0, 5),
        ("rapid", column, 10, 5), ("feed", column, 10, 2), ("rapid", column, 10, 5), ("rapid", column, 0, 5))
] + [("rapid", 20, 0, 20)]
"""By hand from the Fanuc program: per call of O100, step X+10, a hole, Y+10, a hole, back to Y0."""


def _fanuc_to(target: str, text: str) -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text, newline=""), out, file="t.nc", source="fanuc", target=target, setup=EXPRESSIONS,
              diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def _verified(source: str, text: str) -> int:
    report = verify_lines(io.StringIO(source), io.StringIO(text), file_in="t.nc", file_out="t.gcode",
                          source="fanuc", target="grblhal", setup=EXPRESSIONS, tolerance=0.0)
    assert report.ok, report
    return report.moves


def test_fanuc_subprograms_become_subs_before_the_first_call() -> None:
    source = REPEAT.read_text()
    text, warnings = _fanuc_to("grblhal", source)
    assert warnings == []
    assert text == ("(%)\n(O2004) (M98 P L REPEATS AND THE PACKED P FORM)\nG17 G21 G90\nG0 X0. Y0. Z5.\nS1000 M3\n"
                    "o2100 sub (ONE SLOT STEP, INCREMENTAL)\nG91 G0 X10.\nG1 Z-7. F100.\nG0 Z7.\nG90\no2100 endsub\n"
                    "o1 repeat [4.]\no2100 call\no1 endrepeat\nG0 X0. Y20.\no2 repeat [3.]\no2100 call\no2 endrepeat\n"
                    "G90 G0 Z50.\nM5\nM30\n(%)\n")
    assert grblhal_problems(text) == []
    assert _verified(source, text) == 23


def test_a_subprogram_that_calls_a_later_one_is_written_after_it() -> None:
    text, warnings = _fanuc_to("grblhal", NESTED)
    assert warnings == []
    code = [row for row in text.splitlines() if not row.startswith("(")]
    assert code[2:] == ["o200 sub (ONE HOLE)", "G91 G1 Z-3. F80.", "G0 Z3.", "o200 endsub",
                        "o100 sub (COLUMN OF TWO HOLES)", "G91 G0 X10.", "o200 call", "G0 Y10.", "o200 call",
                        "G0 Y-10.", "G90", "o100 endsub", "o1 repeat [2.]", "o100 call", "o1 endrepeat", "G0 Z20.",
                        "M30"]
    assert grblhal_problems(text) == []
    assert _moves(NESTED, "fanuc") == _moves(text, "grblhal") == NESTED_MOVES
    assert _verified(NESTED, text) == len(NESTED_MOVES)


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_written_subs_run_in_rs274_as_the_hand_written_linuxcnc_program() -> None:
    """grblHAL's subs without arguments in a program that computes nothing are rs274's: LinuxCNC's interpreter
    runs the output as it runs the hand-written equivalent of the Fanuc program."""
    text, _ = _fanuc_to("grblhal", REPEAT.read_text())
    theirs = _rs274_moves(text.replace("(%)", "%"))
    assert theirs == _rs274_moves(REPEAT.with_suffix(".ngc").read_text()) == _moves(text, "grblhal")
    assert len(theirs) == 24  # 7 slots of three moves, the first rapid, two repositionings
    nested, _ = _fanuc_to("grblhal", NESTED)
    assert _rs274_moves(nested.replace("(%)", "%")) == NESTED_MOVES


def test_grblhal_output_is_shorter_than_grbls_with_the_same_toolpath() -> None:
    for source in (REPEAT.read_text(), NESTED):
        hal, _ = _fanuc_to("grblhal", source)
        grbl, _ = _fanuc_to("grbl", source)
        assert len(hal.splitlines()) < len(grbl.splitlines())
        assert _moves(hal, "grblhal") == _moves(grbl, "grbl")


def test_a_program_that_computes_with_subprograms_is_flattened_with_the_reason() -> None:
    """An M98 subprogram shares its caller's locals, a grblHAL call opens its own: not written as subs."""
    program = "O1\nG21 G90 G0 X0 Y0 Z5.\n#1=2.\nM98 P100\nM30\nO100\nG91 G1 X#1 F100.\nG90\nM99\n"
    text, warnings = _fanuc_to("grblhal", program)
    assert [row for row in text.splitlines() if not row.startswith("(")] == [
        "G21 G90 G0 X0. Y0. Z5.", "G91 G1 X2. F100.", "G90", "M30"]
    assert warnings == ["t.nc:3:1: warning: the program is flattened (its evaluated motion is written): a program "
                        "that computes, with subprograms (an M98 subprogram shares its caller's locals, a grblHAL "
                        "call opens its own)"]


def test_dead_code_after_a_subprograms_m99_stays_a_comment_between_the_subs() -> None:
    program = "O1\nG21 G90 G0 X0 Y0 Z5.\nM98 P100\nM30\nO100\nG91 G1 X1. F100.\nG90\nM99\nG1 X5.\nO200\nM99\n"
    text, _ = _fanuc_to("grblhal", program)
    assert "o100 endsub\n(AFTER PROGRAM END, LINE 9: G1 X5.)\no200 sub\n" in text
    assert _moves(text, "grblhal") == [("rapid", 0, 0, 5), ("feed", 1, 0, 5)]


def _chain(depth: int, times: str = "") -> str:
    """A main program calling O100, which calls O101, ... ``depth`` subprograms deep."""
    lines = ["O1", "G21 G90 G0 X0 Y0 Z5.", "M98 P100" + times, "M30"]
    for number in range(100, 100 + depth):
        lines += [f"O{number}", "G91 G1 X1. F100.", "G90"]
        lines += [f"M98 P{number + 1}{times}"] if number < 99 + depth else []
        lines.append("M99")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("program, kept", [
    (_chain(10), True), (_chain(11), False),  # NGC_MAX_CALL_LEVEL 10
    (_chain(10, " L2"), True),  # 10 calls and 10 repeats: the 20 constructs of NGC_STACK_DEPTH
])
def test_subprograms_nested_deeper_than_grblhal_runs_are_flattened(program: str, kept: bool) -> None:
    text, warnings = _fanuc_to("grblhal", program)
    assert ("o100 call" in text) == kept and bool(warnings) != kept, (text, warnings)
    if not kept:
        assert "subprograms nested 11 calls deep: grblHAL runs 10 nested calls" in warnings[0]


def test_linuxcncs_fanuc_style_subprograms_become_subs_too() -> None:
    """LinuxCNC's M98/M99 (``O<n>`` after the main program) share the caller's parameters as Fanuc's do."""
    program = "G21 G90 G0 X0 Y0 Z5\nM98 P100 L2\nM2\nO100\nG91 G1 X1 F100\nG90\nM99\n"
    text, warnings = _translate(program, "linuxcnc")
    assert warnings == []
    assert text == ("G21 G90 G0 X0. Y0. Z5.\no100 sub\nG91 G1 X1. F100.\nG90\no100 endsub\no1 repeat [2.]\n"
                    "o100 call\no1 endrepeat\nM2\n")
    assert _moves(text, "grblhal") == _moves(program, "linuxcnc") == [
        ("rapid", 0, 0, 5), ("feed", 1, 0, 5), ("feed", 2, 0, 5)]


def test_a_call_in_a_block_that_moves_moves_first_and_l0_calls_nothing() -> None:
    program = "O1\nG21 G90 G0 X0 Y0 Z5.\nG0 X3. M98 P100 L0\nG0 Y2. M98 P100\nM30\nO100\nG91 G1 X1. F100.\nG90\nM99\n"
    text, warnings = _fanuc_to("grblhal", program)
    assert warnings == []
    assert text.endswith("o100 endsub\nG0 X3.\nG0 Y2.\no100 call\nM30\n"), text
    assert _moves(text, "grblhal") == _moves(program, "fanuc") == [
        ("rapid", 0, 0, 5), ("rapid", 3, 0, 5), ("rapid", 3, 2, 5), ("feed", 4, 2, 5)]


def test_a_call_under_block_delete_is_not_split_from_its_block() -> None:
    """Not written as a sub (the '/' would leave its block), and not flattened either: the flattened moves
    would run whatever the operator's switch says (``tests/test_flattened_block_delete.py``)."""
    program = "O1\nG21 G90 G0 X0 Y0 Z5.\n/M98 P100\nM30\nO100\nG91 G1 X1. F100.\nG90\nM99\n"
    with pytest.raises(ErrorList) as caught:
        _fanuc_to("grblhal", program)
    assert [str(err).split(" error: ")[0] for err in caught.value.errors] == ["t.nc:3:1:"]
