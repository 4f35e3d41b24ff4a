"""The structure of a program that computes is checked in one place (``postproc.interp.structure``) for
``translate`` (to every target, its own dialect included), ``toolpath`` and ``verify``: each refuses a
malformed program with the same located error (issue #31, item 4).

- Fanuc's ``WHILE [..] DOm`` and ``ENDm`` pair one to one (a DO without its END is alarm PS0124 [K]); an
  unclosed LinuxCNC ``o1 while`` was written as it was.
- An expression a part of which is made of constants and fails (``1/0``, ``SQRT[-4]``, ``LN[0]``; Fanuc
  alarms, rs274 "Attempt to divide by zero", "Zero or negative argument to ln") is refused where it is read,
  not kept symbolically for the controller to alarm on (``postproc.interp.evaluation.certain_failure``).
- One program number, one program (Fanuc: a call could not tell two ``O2000`` apart); one ``o<n> sub``
  (rs274: "redefining sub: o|100| already defined"). LinuxCNC's ``O<n>`` .. ``M99`` may stand twice: the
  first after the call wins (``test_linuxcnc_subprograms``, "the first O after the call wins").
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

TARGETS = ("fanuc", "linuxcnc", "isg", "grbl", "mach3")

BAD = {
    "WHILE without END": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=0\nWHILE [#1 LT 3] DO1\nG1 X#1 F100.\n#1=#1+1\nM30\n%\n",
        "in.nc:5:1: error: 'WHILE [#1 LT 3] DO1' is never closed"),
    "END without WHILE": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=1\nEND1\nM30\n%\n",
        "in.nc:5:1: error: 'END1' does not close an open While 1"),
    "a nested loop left open": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=0\nWHILE [#1 LT 3] DO1\nWHILE [#1 LT 2] DO2\n#1=#1+1\n"
                 "END1\nM30\n%\n",
        "in.nc:8:1: error: 'END1' does not close an open While 1"),
    "two O2000": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\nM98 P2000\nM30\nO2000\nG1 X1. F100.\nM99\nO2000\nG1 X2. F100.\n"
                 "M99\n%\n",
        "in.nc:9:1: error: program 2000 is defined twice (first on line 6): a subprogram call could not tell "
        "them apart"),
    "a subprogram numbered as the main program": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\nM98 P1\nM30\nO0001\nG1 X1. F100.\nM99\n%\n",
        "in.nc:6:1: error: program 1 is defined twice (first on line 2): a subprogram call could not tell "
        "them apart"),
    "an unclosed o-word while": (
        "linuxcnc", "G21 G90 G0 X0 Y0 Z5\n#1=0\no1 while [#1 LT 2]\nG1 X#1 F100\n#1=[#1+1]\nM2\n",
        "in.nc:3:1: error: 'o1 while [#1 LT 2]' is never closed"),
    "division by zero": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=1/0\nG1 X#1 F100.\nM30\n%\n",
        "in.nc:4:1: error: division by zero in 1/0: it fails wherever it runs (its operands are constants)"),
    "SQRT of a negative number": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=2.\nG1 X[#1+SQRT[-4]] F100.\nM30\n%\n",
        "in.nc:5:4: error: square root of a negative number in SQRT[-4] (-4): it fails wherever it runs (its "
        "operands are constants)"),
    "LN of 0 in a condition": (
        "fanuc", "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=2.\nIF [LN[2-2] GT 1] GOTO 10\nN10 M30\n%\n",
        "in.nc:5:1: error: logarithm of a number that is not positive in LN[2-2] (0): it fails wherever it runs "
        "(its operands are constants)"),
    "LN of 0 in LinuxCNC": (
        "linuxcnc", "G21 G90 G0 X0 Y0 Z5\n#1=2\no1 if [LN[0] GT 1]\nG1 X#1 F100\no1 endif\nM2\n",
        "in.nc:3:1: error: logarithm of a number that is not positive in LN[0] (0): it fails wherever it runs (its "
        "operands are constants)"),
    "two o100 sub": (
        "linuxcnc", "o100 sub\nG0 X1\no100 endsub\no100 sub\nG0 X2\no100 endsub\nG21 G90\no100 call\nM2\n",
        "in.nc:4:1: error: subprogram 100 is defined twice"),
}


def _errors(run: object) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        run()  # type: ignore[operator]
    return [str(e) for e in caught.value.errors]


@pytest.mark.parametrize("name", BAD)
@pytest.mark.parametrize("target", TARGETS)
def test_translate_refuses_a_malformed_program_towards_every_target(name: str, target: str) -> None:
    source, text, message = BAD[name]

    def run() -> None:
        translate(io.StringIO(text), io.StringIO(), file="in.nc", source=source, target=target)

    assert _errors(run) == [message]


@pytest.mark.parametrize("name", BAD)
def test_toolpath_and_verify_refuse_it_with_the_same_error(name: str) -> None:
    source, text, message = BAD[name]
    assert _errors(lambda: list(toolpath_events(io.StringIO(text), file="in.nc", dialect=source))) == [message]
    both = _errors(lambda: verify_lines(io.StringIO(text), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                                        source=source, target=source))
    assert both == [message, message.replace("in.nc", "out.nc")]


def test_linuxcnc_o_programs_of_one_number_stay_accepted() -> None:
    text = "G21 G90\nM98 P1\nM30\nO1\nG0 X1\nM99\nO1\nG0 Y1\nM99\n"
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.ngc", source="linuxcnc", target="linuxcnc")
    assert out.getvalue() == text
