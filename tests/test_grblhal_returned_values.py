"""``#<_value>`` and ``#<_value_returned>`` on grblHAL and LinuxCNC (issue 26, found by ``make fuzz``: a LinuxCNC
program reading ``#<_value>`` reached grblHAL native and ran otherwise there).

grblHAL's side is derived by hand from its source (github.com/grblHAL/core, stored commit
f80fc34d503bd62391a23b197b3e0ee66ce00cb7, ``ngc_flowctrl.c``): ``NGCFlowCtrl_Call`` sets both to 0 once the
callee's level is open; ``NGCFlowCtrl_EndSub``/``NGCFlowCtrl_Return`` call ``stack_unwind_sub`` (the callee's
parameters are gone) and only then evaluate the value, setting ``_value`` and ``_value_returned`` 1, or, without
one, only ``_value_returned`` 0; the flow passing a definition (``skip_sub``) evaluates nothing; an argument a call
does not give is the caller's (``ngc_param_get`` before ``stack_push``). LinuxCNC's side is rs274's run of the same
text.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274

EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))

WHEN = """G21 G90 G0 X0 Y0 Z10
o1 sub
  G0 X#<_value> Y#<_value_returned> Z1
o1 endsub
o4 sub
o4 endsub [3]
o4 call
o2 sub
o2 endsub [5]
G0 X#<_value> Y#<_value_returned> Z2
o2 call
o1 call
G0 X#<_value> Y#<_value_returned> Z3
o3 sub
  o2 call
o3 endsub
o3 call
G0 X#<_value> Y#<_value_returned> Z4
M2
"""
"""When a call, a return and a definition the flow passes set the two."""

WHERE = """G21 G90 G0 X0 Y0 Z10
#1 = 7
o100 sub
  #1 = 3
o100 endsub [#1*10]
o100 call [4]
G0 X#<_value>
o101 sub
  o102 if [1]
    o101 return [#1+1]
  o102 endif
o101 endsub
o101 call [2]
G0 Y#<_value>
M2
"""
"""With whose parameters a return's value is evaluated."""

FUZZ = """G21 G90 G0 X0 Y0 Z5
o2000 sub
G91 G1 X#1 Y[#2/2] F100
G90
#<local>=[#1+1]
G0 Z#<local>
o2000 endsub
o12345 sub
G91 G1 X#1 Y[#2/2] F100
G90
o9123 if [#1 GT 1]
o12345 return [-1.5]
o9123 endif
#<local>=[#1+1]
G0 Z#<local>
o12345 endsub [-1.5]
o12345 call [2.5] [#<_value>]
o12345 call [1]
M2
"""
"""The fuzz's case (grblhal targets, linuxcnc source, build 'everything'): the first call's second argument is
the value the definition's ``endsub [-1.5]`` left on LinuxCNC, 0 on grblHAL."""

Move = tuple[str, float, float, float]


def _moves(text: str, dialect: str) -> list[Move]:
    return [(e["move"], round(e["x"], 3), round(e["y"], 3), round(e["z"], 3))
            for e in toolpath_events(io.StringIO(text, newline=""), file="t", dialect=dialect, setup=EXPRESSIONS)
            if "move" in e]


def _rs274_moves(text: str) -> list[Move]:
    return [(e["move"], round(e["x"], 3), round(e["y"], 3), round(e["z"], 3))
            for e in rs274.canonical_moves(rs274.run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]


def test_grblhal_sets_the_returned_value_at_a_call_and_not_at_a_definition() -> None:
    """By hand: o4's return sets 3 and 1, the definition of o2 sets nothing (Z2 at 3, 1); o2's return sets 5 and 1;
    o1's call zeroes both (Z1 at 0, 0) and its plain endsub sets only _value_returned (Z3 at 0, 0); o3's plain
    endsub keeps the 5 its call of o2 left (Z4 at 5, 0). (rs274: Z2 at 5, 1, Z1 at 5, 1, Z4 at 0, 0.)"""
    assert _moves(WHEN, "grblhal") == [("rapid", 0, 0, 10), ("rapid", 3, 1, 2), ("rapid", 0, 0, 1),
                                       ("rapid", 0, 0, 3), ("rapid", 5, 0, 4)]


def test_grblhal_has_no_returned_value_before_a_call() -> None:
    """Nothing sets ``_value`` before a call (``ngc_params_init`` does not), and ``ngc_expr.c`` reads a name never
    set as "bad number format": an error where rs274 reads 0."""
    text = "G21 G90 G0 X0 Y0 Z10\nG0 X#<_value>\nM2\n"
    with pytest.raises(ErrorList) as caught:
        _moves(text, "grblhal")
    assert [str(e) for e in caught.value.errors] == ["t:2:4: error: named parameter #<_value> is not defined"]
    assert _moves(text, "linuxcnc") == [("rapid", 0, 0, 10)]


def test_grblhal_evaluates_a_return_value_with_the_callers_parameters() -> None:
    """By hand: both returns read the caller's #1 (7): 7*10 and 7+1."""
    assert _moves(WHERE, "grblhal") == [("rapid", 0, 0, 10), ("rapid", 70, 0, 10), ("rapid", 70, 8, 10)]


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("program", [WHEN, WHERE, FUZZ])
def test_the_linuxcnc_simulation_is_rs274s(program: str) -> None:
    assert _moves(program, "linuxcnc") == _rs274_moves(program)


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("program, line", [(WHEN, 3), (WHERE, 7), (FUZZ, 17)])
def test_a_linuxcnc_program_reading_the_returned_value_reaches_grblhal_flattened(program: str, line: int) -> None:
    """Kept native, grblHAL would run it otherwise (the tests above): it is flattened, with the reason, and its
    moves are rs274's run of the source (rs274 runs the flattened output too: it is plain G-code)."""
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(program, newline=""), out, file="t.ngc", source="linuxcnc", target="grblhal",
              setup=EXPRESSIONS, diagnostics=diagnostics)
    text = out.getvalue()
    code = [row for row in text.splitlines() if not row.startswith("(")]  # (each call is noted in a comment)
    assert not any("#" in row or row.startswith("o") for row in code), text
    warnings = [str(w) for w in diagnostics.warnings]
    assert len(warnings) == 1 and warnings[0].startswith(
        "t.ngc:2:1: warning: the program is flattened (its evaluated motion is written): "
        f"line {line}: it reads #<_value>, which grblhal sets otherwise ("), warnings
    assert "linuxcnc sets them where the flow passes a definition's end, grblhal does not" in warnings[0]
    expected = _rs274_moves(program)
    assert _rs274_moves(text) == expected
    assert [m for m in _moves(text, "grblhal") if m != ("rapid", 0, 0, 0)] == \
        [m for m in expected if m != ("rapid", 0, 0, 0)]
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="t.ngc", file_out="t.gcode",
                          source="linuxcnc", target="grblhal", setup=EXPRESSIONS, tolerance=0.0)
    assert report.ok, report.summary()


def test_a_linuxcnc_program_returning_values_it_never_reads_stays_native() -> None:
    """Nothing reads the value, so where and when it is set changes no move."""
    program = "G21 G90 G0 X0 Y0 Z10\no100 sub\n  G1 X#1 F100\no100 endsub [#1*2]\no100 call [3]\nM2\n"
    out = io.StringIO(newline="")
    translate(io.StringIO(program, newline=""), out, file="t.ngc", source="linuxcnc", target="grblhal",
              setup=EXPRESSIONS, diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert "o100 endsub [#1*2.]" in out.getvalue() and "o100 call [3.]" in out.getvalue(), out.getvalue()


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
"""By hand from ``NGCFlowCtrl_Call``: the first call's #2 is the caller's 7 on grblHAL (rs274 would read 0)."""


def _to_linuxcnc(text: str) -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text, newline=""), out, file="t.gcode", source="grblhal", target="linuxcnc",
              setup=EXPRESSIONS, diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_grblhal_call_reaches_linuxcnc_with_the_arguments_it_inherits() -> None:
    """Each argument not given is written as the caller's parameter, which rs274 evaluates before the call (before:
    ``o100 call [3.]``, which rs274 runs with #2 = 0)."""
    text, warnings = _to_linuxcnc(INHERIT)
    assert warnings == []
    inherited = " ".join(f"[#{k}]" for k in range(3, 31))
    assert f"o100 call [3.] [#2] {inherited}" in text and f"o100 call [4.] [5.] {inherited}" in text, text
    expected = [("rapid", 0, 0, 5), ("feed", 3, 7, 5), ("feed", 4, 5, 5)]
    assert _moves(INHERIT, "grblhal") == expected
    assert _rs274_moves(text) == expected


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_grblhal_program_reading_the_returned_value_reaches_linuxcnc_flattened() -> None:
    text, warnings = _to_linuxcnc(WHERE)
    assert len(warnings) == 1 and "line 7: it reads #<_value>, which linuxcnc sets otherwise (" in warnings[0], warnings
    assert "grblhal evaluates a return value with the caller's parameters" not in warnings[0]  # (named the other way)
    assert "linuxcnc evaluates a return value with the callee's parameters, grblhal with the caller's" in warnings[0]
    assert _rs274_moves(text) == [m for m in _moves(WHERE, "grblhal")]
