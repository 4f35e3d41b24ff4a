"""A G83 whose depth is a whole number of Q, converted to inch and written to 8 decimals, stops some 1e-7 mm
short of the bottom at its last whole peck: that is rounding, not one more peck (siemens -> fanuc --units inch
of examples/siemens/deep_hole.mpf failed verify with one extra peck of 8e-7 mm)."""

from __future__ import annotations

import io
import json

from postproc.simulate.toolpath import toolpath_events


def _feeds_down(program: str) -> list[float]:
    events = list(toolpath_events(io.StringIO(program), file="t.nc", dialect="fanuc"))
    return [round(e["z"], 6) for e in events if e.get("move") == "feed"]


def test_a_whole_number_of_inch_pecks_is_that_many_pecks() -> None:
    # R 0.07874016 in (2 mm), Z -0.70866142 in (-18 mm): 20 mm at Q 0.15748031 in (4 mm) = 5 pecks by hand,
    # each bottom at 2 - 4k mm; 0.15748031 in is 3.99999987 mm, so the fifth bottom is 1e-7 mm short of Z
    program = ("O1\nG20 G90 G17 G0 X0 Y0 Z1.\nG98 G83 X0 Y0 Z-0.70866142 R0.07874016 Q0.15748031 F4.\n"
               "G80\nM30\n")
    bottoms = _feeds_down(program)
    assert len(bottoms) == 5, json.dumps(bottoms)
    assert bottoms[-1] == round(-0.70866142 * 25.4, 6)


def test_a_remainder_the_controller_can_command_is_a_peck() -> None:
    # 20.01 mm at Q 4 mm: five whole pecks and a sixth of 0.01 mm (above the finest least increment)
    program = "O1\nG21 G90 G17 G0 X0 Y0 Z25.\nG98 G83 X0 Y0 Z-18.01 R2. Q4. F100.\nG80\nM30\n"
    assert _feeds_down(program) == [-2.0, -6.0, -10.0, -14.0, -18.0, -18.01]
