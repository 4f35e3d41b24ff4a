"""A statement under block delete is not flattened away.

The operator's block delete switch skips every ``/`` block, statements included: with the switch on,
``/#1=7.`` leaves #1 at 5 and ``/M98 P100`` runs no subprogram. A flattened program writes what the
run did with the switch off, so such a statement would run always (it wrote ``G00 Y7.`` for both
switch positions, exit 0). It is refused at its line; a ``/`` motion block, whose evaluated copy keeps
its ``/``, and a program kept symbolically (LinuxCNC writes ``/ #1=7.``) still translate."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList

ASSIGNED = "O0001\nG21 G90 G17\n#1=5.\nG0 X0 Y0 Z#1\n/#1=7.\nG0 Y#1\nM30\n"
CALLED = "O0001\nG21 G90 G17\nG0 X0 Y0 Z5.\n/M98 P100\nG0 X1.\nM30\nO100\nG1 X10. Y10. F100\nM99\n"
MOVED = "O0001\nG21 G90 G17\n#1=5.\nG0 X0 Y0 Z#1\n/G0 X#1\nG0 Y#1\nM30\n"


def _translated(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source="fanuc", target=target)
    return out.getvalue()


@pytest.mark.parametrize(("text", "line", "target"), [(ASSIGNED, 5, "isg"), (ASSIGNED, 5, "grbl"),
                                                      (CALLED, 4, "isg"), (CALLED, 4, "linuxcnc")])
def test_a_statement_under_block_delete_is_refused_where_flattened(text: str, line: int, target: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translated(text, target)
    messages = [str(err) for err in caught.value.errors]
    assert any(m.startswith(f"t.nc:{line}:1: error: ") and "block delete" in m for m in messages), messages


def test_a_motion_block_under_block_delete_keeps_its_slash_when_flattened() -> None:
    lines = _translated(MOVED, "isg").splitlines()
    assert "/ G00 X5." in lines and "G00 Y5." in lines


def test_a_program_kept_symbolically_keeps_its_skipped_statement() -> None:
    assert "/ #1=7." in _translated(ASSIGNED, "linuxcnc").splitlines()
