"""A Fanuc T ``T0200`` (the station in position, offset 00) towards grbl (issue 29, defects).

Towards grbl a lathe's offsets are written into the coordinates (``postproc.cycles.lathe_offsets``) and a T naming
the station already in position indexes nothing (``lathe_lowering._same_station``): nothing of such a block was
left, and an empty line was written where it stood. grbl takes a T word as a tool number from 0 to 255 and only
stores it [V: grbl 1.1 ``gcode.c``: ``MAX_TOOL_NUMBER 255``, ``gc_state.tool = gc_block.values.t``], so the offset
number has no place there: the block is a comment that says where its meaning went.
"""

from __future__ import annotations

import io

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.verify import verify_lines
from tests.test_lathe_same_station import PROGRAM, _setup


def test_an_offset_only_t_is_a_note_not_an_empty_line() -> None:
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="l.nc", source="fanuc", target="grbl", setup=_setup(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    lines = out.getvalue().splitlines()
    assert "" not in lines, lines
    assert "(T0200: offset 00, in the coordinates)" in lines
    assert "(T0303: offset 03, in the coordinates)" in lines
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(out.getvalue()), file_in="l.nc", file_out="out",
                          source="fanuc", target="grbl", setup=_setup(), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
