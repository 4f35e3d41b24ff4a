"""Hostile SINUMERIK input: deep nesting of control structures and many parameters end in a translation or
a located error, never a traceback (``RecursionError``) or an unbounded run. (Line length, expression depth,
endless loops and recursive calls: ``test_siemens.py``, ``test_siemens_cycles_proc.py``.)"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList

DEPTH = 1500
"""Deeper than the interpreter's default recursion limit (1000)."""


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("opener, closer", [("IF R1==0", "ENDIF"), ("WHILE R1<1", "ENDWHILE")])
def test_control_structures_nested_thousands_deep_are_read_and_run(opener: str, closer: str) -> None:
    """Each body runs once: the innermost sets R1=1, which ends every loop around it."""
    text = "G710 G90\nR1=0\n" + f"{opener}\n" * DEPTH + "G0 X1\nR1=1\n" + f"{closer}\n" * DEPTH + "G0 X2\nM30\n"
    assert _translate(text, "siemens") == text
    assert _translate(text, "fanuc").splitlines()[-2:] == ["G00 X2.", "M30"]


def test_thousands_of_unclosed_structures_are_a_located_error() -> None:
    with pytest.raises(ErrorList) as caught:
        _translate("G710 G90\nR1=1\n" + "IF R1==1\n" * DEPTH + "M30\n", "fanuc")
    assert str(caught.value.errors[0]).startswith("in.mpf:"), caught.value.errors[0]


def test_a_cycle_with_thousands_of_parameters_is_a_located_error() -> None:
    with pytest.raises(ErrorList) as caught:
        _translate("G710 G90 G0 Z10\nCYCLE83(" + "1, " * 5000 + "1)\nM30\n", "fanuc")
    assert "has more than 64 parameters" in str(caught.value.errors[0]), caught.value.errors[0]
