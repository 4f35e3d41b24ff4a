"""A vacant Fanuc variable in a word: the word is absent there (Custom Macro B, "Undefined variables":
``G90 X#1`` with #1 vacant is ``G90`` [K]), while LinuxCNC reads an unset parameter as 0 and ISG refuses
an unset P. A program kept symbolically would move where the Fanuc does not; it is flattened instead.

Expected moves are derived by hand from that rule; the LinuxCNC output is run by rs274.
"""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

VACANT = ("O0001\n"
          "G21 G90 G0 X5. Y0. Z10.\n"
          "G1 X#1 Y7. F100.\n"      # #1 vacant: X is absent -> feed to (5, 7, 10)
          "#2=#1\n"                 # the copy is vacant too
          "G1 X2. Z#2\n"            # -> feed to (2, 7, 10)
          "G65 P9001 A#1 B3.\n"     # #1 vacant in the macro, #2 = 3 -> feed to (2, 3, 10)
          "M30\n"
          "O9001\n"
          "G1 X#1 Y#2\n"
          "M99\n")
VACANT_MOVES = [("rapid", 5.0, 0.0, 10.0), ("feed", 5.0, 7.0, 10.0), ("feed", 2.0, 7.0, 10.0),
                ("feed", 2.0, 3.0, 10.0)]


def _translate(text: str, target: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = translate(io.StringIO(text), out, file="v.nc", source="fanuc", target=target)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def _moves(events: list[dict[str, object]]) -> list[tuple[object, float, float, float]]:
    return [(e["move"], round(float(e["x"]), 4), round(float(e["y"]), 4), round(float(e["z"]), 4))  # type: ignore[arg-type]
            for e in events if "move" in e]


def test_the_fanuc_simulation_omits_a_vacant_word() -> None:
    assert _moves(list(toolpath_events(io.StringIO(VACANT), file="v.nc", dialect="fanuc"))) == VACANT_MOVES


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_vacant_words_reach_linuxcnc_flattened_and_rs274_moves_as_the_fanuc() -> None:
    text, warnings = _translate(VACANT, "linuxcnc")
    assert any("line 3: X#1 is vacant" in w for w in warnings), warnings
    assert "#" not in re.sub(r"\([^)]*\)", "", text), text  # no variable left for rs274 to read as 0
    assert _moves(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0))) == VACANT_MOVES


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_vacant_argument_is_found_in_the_macro_it_reaches() -> None:
    program = "O0001\nG21 G90 G0 X5. Y0. Z10.\nG65 P9001 A#1 B3.\nM30\nO9001\nG1 X#1 Y#2 F100.\nM99\n"
    text, warnings = _translate(program, "linuxcnc")
    assert any("line 6: X#1 is vacant" in w for w in warnings), warnings
    assert _moves(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0))) == [
        ("rapid", 5.0, 0.0, 10.0), ("feed", 5.0, 3.0, 10.0)]


def test_a_vacant_common_variable_does_not_reach_isg_as_an_unset_p_parameter() -> None:
    program = "O0001\nG21 G90 G0 X5. Y0. Z10.\nG1 X#501 Y7. F100.\nM30\n"
    text, warnings = _translate(program, "isg")
    assert "P1" not in text and any("X#501 is vacant" in w for w in warnings), (text, warnings)
    moves = _moves(list(toolpath_events(io.StringIO(text), file="o.nc", dialect="isg")))
    assert moves == [("rapid", 5.0, 0.0, 10.0), ("feed", 5.0, 7.0, 10.0)]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_word_that_is_set_when_it_runs_stays_symbolic() -> None:
    program = "O0001\nG21 G90 G0 X5. Y0. Z10.\n#1=3.\nG1 X#1 F100.\nM30\n"
    text, warnings = _translate(program, "linuxcnc")
    assert warnings == [] and "G1 X#1 F100.\n" in text, text
    assert _moves(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)))[-1] == ("feed", 3.0, 0.0, 10.0)


def test_a_run_that_cannot_tell_whether_a_word_is_vacant_is_refused_where_it_stops() -> None:
    """The current position is known only to the machine: whether #3 is vacant cannot be known."""
    program = "O0001\nG21 G90 G0 X5. Y0. Z10.\n#3=#5041\nG1 X#3 F100.\nM30\n"
    with pytest.raises(ErrorList) as caught:
        _translate(program, "linuxcnc")
    assert str(caught.value.errors[0]).startswith("v.nc:3:"), caught.value
    assert "#5041" in str(caught.value.errors[0])
