"""Hostile inputs on the newest readers (defects3's hand run): each is a located error in bounded time, never a
traceback. And a program name SINUMERIK cannot take (more than its 24 characters) is refused at the header,
where it was written whole (``%_N_A_A_A..._MPF`` of 10,000 characters).
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events

CASES = [
    ("siemens", "%_N_A_MPF\nN10 G17 G90 G0 X0 Y0 Z10\nN20 CYCLE81(" + "," * 40 + ")\nM30\n",
     "in.nc:3:5: error: CYCLE81 with parameters after DPR (GMODE, DMODE...) (not modelled) cannot be simulated"),
    ("siemens", "%_N_A_MPF\nR1=1\n" + "IF R1==1\n" * 2000 + "M30\n",
     "in.nc:3:1: error: IF is never closed (ENDIF missing)"),
    ("siemens", "%_N_A_MPF\nN10 G0 X0\nN20 GOTOB N20\nM30\n", "in.nc:3:1: error: jump 'N20 GOTOB N20' never ends"),
    ("siemens", "%_N_A_MPF\nR999=1\nR999=R999*1E300\nM30\n",
     "in.nc:2:1: error: R999: only R0-R499 have a neutral number here"),
    ("siemens", "%_N_A_MPF\nR1=" + "(" * 5001 + "1" + ")" * 5001 + "\nM30\n",
     "in.nc:2:68: error: expression nested deeper than 64 levels"),
    ("isg", "%L sub\nN10 LL sub\nM29\n%main\nN10 LL sub\nM30\n", "in.nc:2:1: error: 'N10 LL sub' exceeds the set-up's "
     "bound of 64 nested calls"),
]


@pytest.mark.parametrize("dialect, text, message", CASES)
def test_a_hostile_input_is_a_located_error(dialect: str, text: str, message: str) -> None:
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect))
    assert str(caught.value.errors[0]).startswith(message)


def _to_siemens(name: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(f"%{name}\nN10 G0 X0\nM30\n"), out, file="in.nc", source="isg", target="siemens",
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def test_a_program_name_of_24_characters_is_written_and_25_refused() -> None:
    assert _to_siemens("abcdefghij klmnopqrstuvw").startswith("%_N_ABCDEFGHIJ_KLMNOPQRSTUVW_MPF\n")
    with pytest.raises(ErrorList) as caught:
        _to_siemens("a " * 5000)
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:1:1: error: the siemens dialect cannot express a program name of 9999 characters "
        "(A_A_A_A_A_A_A_A_A_A_A_A_...): SINUMERIK takes 24"]
