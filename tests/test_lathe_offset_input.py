"""Fanuc T ``G10 P X Z R Q`` (``postproc.rs274.lathe_offset_input``): a lathe tool offset written by the program,
its X and Z applied by the next T code that selects it, its nose radius and tip used by tool nose radius
compensation, the finishing cycle's included. Expected paths are the hand-derived ones of
``tests/test_fanuc_nose.py`` (its module docstring derives them) and of the lathe offsets (by hand below), here
with the offset given by the program instead of the set-up."""

from __future__ import annotations

import io
import math
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.compensation.tool_table import ToolTable
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.ir import DataSetting
from postproc.setup.machine import ToolData
from tests.support.nose_tips import controlled, one_tool
from tests.test_fanuc_nose import CYCLE, PROFILE, R, _expected

NO_RADIUS = "fanuc_0i_tf.xml"


def _bare(register: int = 2) -> Any:
    """The Fanuc 0i-TF set-up with offset ``register`` declared without radius, tip, X or Z."""
    setup = one_tool(NO_RADIUS, register, R, None)
    setup.tools = {str(register): ToolData(number=register)}
    return setup


def _shifted(expected: list[dict[str, Any]], lines: int = 1) -> list[dict[str, Any]]:
    """The expected moves of a program with ``lines`` more lines before them."""
    return [{**move, "line": move["line"] + lines} for move in expected]


@pytest.mark.parametrize("tip", [1, 2, 3, 4, 5, 6, 7, 8, 9])
def test_the_nose_radius_and_tip_written_by_g10_compensate_as_the_set_ups(tip: int) -> None:
    """``G10 P10002 R0.8 Q<tip>`` (geometry of offset 2) before T0102: the hand-derived path of every tip."""
    text = PROFILE.replace("T0102\n", f"G10 P10002 R{R} Q{tip}\nT0102\n")
    assert controlled(text, "fanuc", _bare(), "t.nc") == _shifted(_expected(tip))


def test_geometry_and_wear_add_and_increments_add_to_them() -> None:
    """Geometry R0.5 then C0.2 (an increment: 0.7), wear P2 R0.1: radius 0.8, the same path as above (tip 3)."""
    text = PROFILE.replace("T0102\n", "G10 P10002 R0.5 Q3\nG10 P10002 C0.2\nG10 P2 R0.1\nT0102\n")
    assert controlled(text, "fanuc", _bare(), "t.nc") == _shifted(_expected(3), 3)


def test_a_written_radius_replaces_the_set_ups() -> None:
    setup = one_tool(NO_RADIUS, 2, 2.5, 6)
    text = PROFILE.replace("T0102\n", f"G10 P10002 R{R} Q3\nT0102\n")
    assert controlled(text, "fanuc", setup, "t.nc") == _shifted(_expected(3))


def test_the_finishing_cycle_takes_the_written_radius() -> None:
    """G42 before G70 over the profile (``test_fanuc_nose.test_finishing_cycle_runs_its_profile_compensated_by_hand``
    derives the nose centres; tip 3 moves each by (-r, -r)), the radius and tip from ``G10 P10002 R0.8 Q3``."""
    centres = [(2.0, 10.0 + R), (-15.0 - R + R * math.sqrt(2.0), 10.0 + R),
               (-25.0 + R, -5.0 + R * math.sqrt(2.0) + 25.0 - R), (-25.0 + R, 30.0)]
    text = CYCLE.replace("T0102\n", f"G10 P10002 R{R} Q3\nT0102\n")
    moves = [m for m in controlled(text, "fanuc", _bare(), "t.nc") if m["line"] == 13]
    assert [m["move"] for m in moves] == ["rapid", "feed", "feed", "feed", "rapid"]
    for move, (z, x) in zip(moves, centres):
        assert move["z"] == pytest.approx(z - R, abs=1e-6) and move["x"] == pytest.approx(2 * (x - R), abs=1e-6)
    assert (moves[-1]["x"], moves[-1]["z"]) == (62, 2)  # the return, the offset temporarily cancelled


OFFSETS = "O0001\nG21 G18 G98\nG10 P10002 X4. Z-1.5\nG10 P2 U0.2 W-0.1\nG0 X100. Z50.\nT0202\nG0 X50. Z5.\n" \
          "G10 P10002 X8.\nG1 X40. F200.\nT0202\nG0 Z10.\nM30\n"
"""By hand: offset 2 = geometry (4, -1.5) + wear (0.2, -0.1) = X +4.2 (diameter), Z -1.6 from the X50 Z5 move:
(54.2, 3.4). Rewritten (X8.) after the T code: the offset in force stays until a T code selects it again
[K: the offset is read when the T code selects it]: X40 at (44.2, 3.4); T0202 again, Z10 at (48.2, 8.4)."""


def test_x_and_z_written_by_g10_apply_with_the_t_code() -> None:
    setup = _bare()
    moves = [(m["x"], m["z"]) for m in controlled(OFFSETS, "fanuc", setup, "t.nc")]
    assert [(round(x, 6), round(z, 6)) for x, z in moves] == [(100.0, 50.0), (54.2, 3.4), (44.2, 3.4), (48.2, 8.4)]


def test_a_copy_keeps_the_block_as_written() -> None:
    out = io.StringIO()
    translate(io.StringIO(OFFSETS), out, file="t.nc", source="fanuc", target="fanuc", setup=_bare())
    assert "\nG10 P10002 X4. Z-1.5\nG10 P2 U0.2 W-0.1\n" in out.getvalue()


@pytest.mark.parametrize("target", ["gsk", "linuxcnc", "grbl"])
def test_a_controller_without_the_form_refuses_it_where_it_stands(target: str) -> None:
    with pytest.raises(ErrorList) as err:
        translate(io.StringIO(OFFSETS), io.StringIO(), file="t.nc", source="fanuc", target=target, setup=_bare(),
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert f"t.nc:3:1: error: the {target} dialect cannot express G10 P10002 X4. Z-1.5 (setting lathe offset 2)" \
        in str(err.value)


@pytest.mark.parametrize("line, message", [
    ("G10 P100 R0.4", "t.nc:3:5: error: G10 P100: a lathe offset is P1-P99 (wear) or P10001-P10099 (geometry)"),
    ("G10 P10002 R0.4 Q12", "t.nc:3:17: error: G10 P10002 Q12: the imaginary tool nose number is 0 to 9"),
    ("G10 P10002 X1. U0.5", "t.nc:3:16: error: G10 P10002: X and U set the same value"),
    ("G10 P10002 Y1.", "t.nc:3:12: error: Y in a lathe offset setting (G10 P10002)"),
    ("G10 P10002", "t.nc:3:1: error: G10 P10002 sets nothing"),
])
def test_refusals_are_located(line: str, message: str) -> None:
    with pytest.raises(PostprocError) as err:
        controlled(OFFSETS.replace("G10 P10002 X4. Z-1.5", line), "fanuc", _bare(), "t.nc")
    assert message in str(err.value)


def test_p0_stays_verbatim_and_unsimulated() -> None:
    """P0 (the work coordinate system shift) is another function: kept as written, refused by the simulation."""
    with pytest.raises(PostprocError, match="t.nc:3:1: error: G10 .* cannot be simulated"):
        controlled(OFFSETS.replace("G10 P10002 X4. Z-1.5", "G10 P0 X1. Z2."), "fanuc", _bare(), "t.nc")


def test_incremental_mode_is_refused_by_name() -> None:
    """G-code system B has G91: whether X, Z and R then add is not in the manual's text [?]: refused, located."""
    setup = _bare()
    setup.input.gcode_system = "B"
    text = OFFSETS.replace("G10 P10002 X4. Z-1.5", "G91 G10 P10002 X4. Z-1.5")
    with pytest.raises(PostprocError) as err:
        controlled(text, "fanuc", setup, "t.nc")
    assert "t.nc:3:5: error: G10 P10002 in incremental mode: whether X, Z and R" in str(err.value)


def test_the_setting_holds_the_offset_by_meaning_not_by_the_letters() -> None:
    """The family base reads Fanuc T's letters (X, U, Z, W, R, C, Q); the neutral setting carries what they mean
    (``postproc.compensation.tool_table.LATHE_VALUES``, ``LATHE_TIP``), so the core's tool table names no family's
    letter. U and C add to X and R, W to Z."""
    text = "O0001\nG21 G18 G98\nG10 P10002 X4. W-1.5 C0.2 Q3\nG10 P2 U0.2 Z-0.1 R0.1\nM30\n"
    settings = [block.sections["DataSetting"] for block in read_program(io.StringIO(text), file="t.nc",
                                                                          dialect="fanuc", setup=_bare())
                if "DataSetting" in block.sections]
    assert [(s.table, s.index, s.values) for s in settings] == [  # type: ignore[attr-defined]
        ("lathe_offset", 2, {"x": 4.0, "z_increment": -1.5, "radius_increment": 0.2, "tip": 3.0}),
        ("lathe_offset_wear", 2, {"x_increment": 0.2, "z": -0.1, "radius": 0.1})]


def test_the_tool_table_reads_the_neutral_keys() -> None:
    """Geometry X4 Z-1.5 R0.5 tip 3, then +0.2 on X and R; wear X0.2 Z-0.1: offset 2 is (4.4/2, -1.6) on a
    diameter lathe, radius 0.7, tip 3 (``ToolTable.write``, by hand)."""
    table = ToolTable(_bare())
    for table_name, values in (("lathe_offset", {"x": 4.0, "z": -1.5, "radius": 0.5, "tip": 3.0}),
                               ("lathe_offset", {"x_increment": 0.2, "radius_increment": 0.2}),
                               ("lathe_offset_wear", {"x": 0.2, "z": -0.1})):
        assert table.write(DataSetting("any", table_name, 2, dict(values), False, ""), 1.0)
    lathe = table.lathe(2, diameter=True)
    assert lathe is not None and lathe == pytest.approx((2.2, -1.6))
    assert table.radius(2) == pytest.approx(0.7)
    assert table.tip(2) == 3
