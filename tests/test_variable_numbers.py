"""Variable numbers carried between dialect families keep their meaning, or the program is flattened.

LinuxCNC's ``#1000`` and ``#3000`` are global parameters a program may set [V: rs274 parameters
#31-#5000]; in Custom Macro B ``#1000`` is an input signal and a write to ``#3000`` raises alarm 3000
[K: Fanuc 0i-F operator's manual, system variables]. A LinuxCNC program kept symbolically for a Fanuc
therefore stopped the machine with an alarm (it was written ``#3000=2.``, exit 0); a Fanuc alarm written
to LinuxCNC set a parameter and ran on. Such programs are flattened: the source's table gives the
values, or names what only the machine knows."""

from __future__ import annotations

import io

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList
from postproc.interp.numbers import COMPUTED, numbered_variables, plain_variable
from postproc.rs274.variables import MacroBVariables, NgcVariables


def _translated(text: str, source: str, target: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    translate(io.StringIO(text), out, file="t.nc", source=source, target=target, diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def test_linuxcnc_globals_that_are_fanuc_system_variables_are_evaluated() -> None:
    text, warnings = _translated("G21 G90 G17\n#1000=5\n#3000=2\nG0 X#1000 Y#3000 Z5.\nM2\n", "linuxcnc", "fanuc")
    assert "#" not in text and "G00 X5. Y2. Z5." in text.splitlines()
    assert any("#1000 is no plain variable of fanuc" in w for w in warnings), warnings


def test_a_fanuc_alarm_is_not_written_as_a_linuxcnc_parameter() -> None:
    program = "O1\nG21 G90 G17\n#1=3\nIF [#1 GT 5] THEN #3000=1 (TOO BIG)\nG0 X#1 Y1. Z5.\nM30\n"
    text, warnings = _translated(program, "fanuc", "linuxcnc")
    assert "#3000" not in text and "G0 X3. Y1. Z5." in text.splitlines()
    assert any("#3000" in w for w in warnings), warnings


def test_a_machine_only_value_is_a_located_error() -> None:
    with pytest.raises(ErrorList) as caught:
        _translated("G21 G90 G17\nT3 M6\n#1=#5400\nG0 X#1 Y0 Z5.\nM2\n", "linuxcnc", "fanuc")
    assert any(str(e).startswith("t.nc:3:") and "#5400" in str(e) for e in caught.value.errors)


def test_plain_numbers_stay_symbolic() -> None:
    text, _ = _translated("G21 G90 G17\n#100=5\n#500=[#100*2]\nG0 X#100 Y#500 Z5.\nM2\n", "linuxcnc", "fanuc")
    assert "#100=5." in text and "G00 X#100 Y#500 Z5." in text


def test_a_computed_number_is_evaluated() -> None:
    text, warnings = _translated("G21 G90 G17\n#1=900\n#[#1+100]=4\nG0 X#1000 Y0 Z5.\nM2\n", "linuxcnc", "fanuc")
    assert "#" not in text and "G00 X4. Y0. Z5." in text.splitlines()
    assert any("computes a variable number" in w for w in warnings), warnings


@pytest.mark.parametrize(("family", "number", "plain"), [
    (MacroBVariables, 1, True), (MacroBVariables, 100, True), (MacroBVariables, 999, True),
    (MacroBVariables, 50, False), (MacroBVariables, 1000, False), (MacroBVariables, 3000, False),
    (MacroBVariables, 5041, False), (NgcVariables, 31, True), (NgcVariables, 3000, True),
    (NgcVariables, 5000, True), (NgcVariables, 5400, False), (NgcVariables, 5041, False)])
def test_plain_variables_of_each_family(family: type, number: int, plain: bool) -> None:
    assert plain_variable(family, number) is plain


def test_numbers_are_found_in_every_construct() -> None:
    blocks = read_program(io.StringIO("#1=#2\nG0 X#3\no100 if [#4 GT 1]\no100 endif\n#[#5]=1\nM2\n"),
                          file="t.ngc", dialect="linuxcnc")
    assert set(numbered_variables(blocks)) == {1, 2, 3, 4, 5, COMPUTED}


def test_a_number_read_only_in_a_word_is_found_too() -> None:
    """``G0 X#3000`` alone in a condition: the keep check sees the word's expression before the block syntax reads it
    into a section (it was kept: ``G00 X#3000`` for Fanuc, where #3000 is the alarm). Flattened, rs274's 0."""
    text, warnings = _translated("G21 G90 G0 X0 Y0 Z10\no100 if [1]\nG0 X#3000\no100 endif\nM2\n", "linuxcnc",
                                 "fanuc")
    assert "#" not in text and "G00 X0." in text.splitlines(), text
    assert any("#3000 is no plain variable of fanuc" in w for w in warnings), warnings
