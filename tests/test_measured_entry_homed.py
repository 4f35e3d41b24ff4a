"""A tool entry measured where the tool stands (LinuxCNC ``G10 L10``) after a reference return, written for Fanuc
(``postproc.frames.measured_entries``). The step follows plain moves only while a reference return has taken an axis
home (its ``moves``, lowerfast3): these cases hold it to the rule either way.

Hand-derived from the rule the module cites [V: LinuxCNC ``convert_setup_tool``]: the entry is the tool's point
without its offset, less the word. With no offset in force the tool's Z is the programmed Z: after ``G0 Z5.``,
``G10 L10 P1 Z0.5`` sets length 5 - 0.5 = 4.5 (Fanuc's ``G10 L10 P1 R4.5``). After ``G28 Z0.`` the Z is the
machine's home, not known in work coordinates, until Z is programmed absolutely again: an X move or an incremental
Z leaves it unknown, a located error.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList

START = "G21 G90\nG0 X1. Y1. Z1.\nG28 Z0.\n"


def _fanuc(text: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    try:
        translate(io.StringIO(text), out, file="t.ngc", source="linuxcnc", target="fanuc")
    except ErrorList as raised:
        return out.getvalue(), [str(err) for err in raised.errors]
    return out.getvalue(), []


def test_an_absolute_z_after_the_return_makes_the_entry_known_by_hand() -> None:
    out, errors = _fanuc(START + "G0 X2.\nG0 Z5.\nG10 L10 P1 Z0.5\nM2\n")
    assert errors == []
    assert "G10 L10 P1 R4.5" in out.splitlines()


@pytest.mark.parametrize("between", ["G0 X2.\n", "G91 G0 Z5.\nG90\n", "G0 X2.\nG0 Y3.\n"])
def test_a_move_that_leaves_z_unknown_after_the_return_is_a_located_error(between: str) -> None:
    _, errors = _fanuc(START + between + "G10 L10 P1 Z0.5\nM2\n")
    line = 4 + between.count("\n")
    assert len(errors) == 1 and errors[0].startswith(f"t.ngc:{line}:1: error:") and "tool's Z is not known" in errors[0]


def test_before_any_return_the_entry_follows_the_plain_moves_by_hand() -> None:
    out, errors = _fanuc("G21 G90\nG0 X1. Y1. Z1.\nG0 Z7.\nG10 L10 P1 Z2.\nM2\n")
    assert errors == []
    assert "G10 L10 P1 R5." in out.splitlines()
