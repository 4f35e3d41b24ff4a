"""Lathe tool offsets (``<Tool number="n" x=".." z=".." xWear zWear/>``) applied by the simulation: Fanuc T
and GSK ``T0102`` (tool 1, offset 2) from the next move, LinuxCNC's lathe ``G43 H2`` where the axis is next
programmed (rs274 as the oracle, its tool table in inches). X offsets follow the set-up's X: a diameter on
a diameter lathe (LinuxCNC's table X is a radius: [V] rs274 adds entry X to its canonical radius).
Expected points are worked out by hand in the comments."""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274, straight_moves_with_length


def _lathe(tools: dict[int, tuple[float, float]], wear: dict[int, tuple[float, float]] | None = None) -> MachineSetup:
    setup = MachineSetup(input=InputSettings(machine_type="lathe"))
    wear = wear or {}
    setup.tools = {str(n): ToolData(number=n, x=x, z=z, x_wear=wear.get(n, (None, None))[0],
                                    z_wear=wear.get(n, (None, None))[1]) for n, (x, z) in tools.items()}
    return setup


def _moves(text: str, dialect: str, setup: MachineSetup) -> list[tuple[float, float, float, float]]:
    """(programmed X, Z, controlled X, Z) of each move; X as the program writes it (a diameter)."""
    out = []
    for ev in toolpath_events(io.StringIO(text), file="l.nc", dialect=dialect, setup=setup):
        if "move" in ev:
            c: dict[str, Any] = ev.get("controlled", ev)
            out.append((ev["x"], ev["z"], c["x"], c["z"]))
    return out


FANUC_T = ("O0001\nG21 G18 G99\nG0 X100. Z50.\nT0102\nM03 S1000\nG0 X50. Z5.\nG1 X40. F0.2\nZ-10.\nM05\nT0103\n"
           "G0 Z10.\nT0100\nG0 X70.\nM30\n")


def test_fanuc_t_applies_the_offset_with_the_next_move() -> None:
    """Offset 2: X +4 (diameter), Z -1.5. Offset 3: X 0 + wear 0.2, Z 2 - wear 0.1 = 1.9. T0103 alone moves
    nothing; the Z10 traverse takes the controlled point to X 40 + 0.2 = 40.2 (the X it stood at, now under
    offset 3's X) and Z 11.9; T0100 cancels, the X70 traverse ends on the programmed point."""
    setup = _lathe({2: (4.0, -1.5), 3: (0.0, 2.0)}, {3: (0.2, -0.1)})
    assert _moves(FANUC_T, "fanuc", setup) == [
        (100, 50, 100, 50), (50, 5, 54, 3.5), (40, 5, 44, 3.5), (40, -10, 44, -11.5),
        (40, 10, 40.2, 11.9), (70, 10, 70, 10)]


def test_gsk_applies_the_offset_as_fanuc_t() -> None:
    setup = _lathe({2: (4.0, -1.5), 3: (0.0, 2.0)}, {3: (0.2, -0.1)})
    assert _moves(FANUC_T, "gsk", setup) == _moves(FANUC_T, "fanuc", setup)


def test_a_register_the_set_up_does_not_give_stays_a_compared_setting() -> None:
    """No x/z for offset 2: nothing is applied (the selection is compared by verify, as before)."""
    moves = _moves(FANUC_T, "fanuc", _lathe({3: (0.0, 2.0)}))
    assert moves[1] == (50, 5, 50, 5)


def test_the_set_up_refuses_x_without_z() -> None:
    with pytest.raises(ValueError, match="a lathe offset gives x without z"):
        ToolData(number=2, x=1.0)


# -- LinuxCNC lathe against rs274 -------------------------------------------------------------------------

TABLE_INCH = {1: (0.0, 0.0), 2: (0.1, 0.2), 3: (-0.05, 0.3), 4: (0.25, -0.15)}
"""rs274's table: X (a radius) and Z in inches, exact in its 4 printed decimals of mm."""


def _linuxcnc_setup() -> MachineSetup:
    """The same table in the set-up: X as a diameter (twice the radius), mm."""
    return _lathe({n: (round(2 * x * 25.4, 6), round(z * 25.4, 6)) for n, (x, z) in TABLE_INCH.items()})


def _rs274(text: str) -> list[tuple[float, float, float, float]]:
    """rs274's moves as (X diameter, Z, controlled X diameter, controlled Z), mm."""
    table = "".join(f"T{n} P{n} X{x} Z{z} D0\n" for n, (x, z) in TABLE_INCH.items())
    out: list[tuple[float, float, float, float]] = []
    for x, _, z, ox, oz in straight_moves_with_length(run_rs274(text, tool_table=table)):
        point = (round(2 * x, 4), z, round(2 * (x + ox), 4), round(z + oz, 4))
        if out and (out[-1][2], out[-1][3]) == point[2:]:
            continue  # the machine does not move
        out.append(point)
    return out


def _program(rng: random.Random) -> str:
    lines = ["G18 G7 G21 G90", "G0 X100 Z50", "T1 M6"]
    for _ in range(rng.randint(6, 14)):
        op = rng.random()
        if op < 0.25:
            lines.append(f"G43 H{rng.choice(list(TABLE_INCH))}")
        elif op < 0.32:
            lines.append("G49")
        elif op < 0.55:
            lines.append(f"G1 X{rng.randint(10, 90)} F100")
        elif op < 0.75:
            lines.append(f"G0 Z{rng.randint(-30, 40)}")
        elif op < 0.9:
            lines.append(f"G1 X{rng.randint(10, 90)} Z{rng.randint(-30, 40)} F80")
        else:
            lines.append(f"G91 G1 Z{rng.randint(-5, 5) or 2} F80")
            lines.append("G90")
    lines.append("M2")
    return "\n".join(lines) + "\n"


def _ours(text: str) -> list[tuple[float, float, float, float]]:
    return [tuple(round(float(v), 4) for v in m) for m in _moves(text, "linuxcnc", _linuxcnc_setup())]  # type: ignore[misc]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_linuxcnc_lathe_offset_by_hand_and_rs274() -> None:
    """Entry 2: X +0.1 in (radius: +5.08 on the diameter), Z +5.08. ``G43 H2`` moves nothing: the X60
    traverse keeps machine Z 50 (programmed 50 - 5.08 = 44.92) and goes to machine diameter 60 + 5.08."""
    text = "G18 G7 G21 G90\nG0 X100 Z50\nT2 M6\nG43 H2\nG0 X60\nG1 Z5 F100\nG49\nG0 Z60\nM2\n"
    ours = _ours(text)
    assert ours == [(100, 50, 100, 50), (60, 44.92, 65.08, 50), (60, 5, 65.08, 10.08), (65.08, 60, 65.08, 60)]
    assert _rs274(text)[1:] == ours[1:]  # rs274's first move starts from its own zero


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("batch", range(2))
def test_linuxcnc_lathe_offsets_equal_rs274(batch: int) -> None:
    for seed in range(batch * 25, (batch + 1) * 25):
        text = _program(random.Random(seed))
        ours, theirs = _ours(text), _rs274(text)
        assert ours == theirs, f"seed {seed}\n{text}\nours   {ours}\nrs274  {theirs}"


# -- translations -----------------------------------------------------------------------------------------

def _translate(text: str, target: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="l.nc", source="fanuc", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _verified(text: str, target: str, setup: MachineSetup) -> list[str]:
    out = _translate(text, target, setup)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="l.nc", file_out="out", source="fanuc",
                          target=target, setup=setup, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out
    return [line for line in out.splitlines() if "TOOL CHANGE" not in line]


PER_MINUTE = FANUC_T.replace("G99", "G98").replace("F0.2", "F200.")


def test_towards_grbl_the_offsets_are_written_into_the_coordinates() -> None:
    """grbl takes radii: X50 is 25, + offset 2's 4/2 = 27; Z5 - 1.5 = 3.5 (the X50 Z5 traverse after T0102).
    After T0103 the Z10 traverse takes X too: 40/2 + 0.2/2 = 20.1, Z 10 + 1.9 = 11.9; T0100: the X70
    traverse (35) takes Z back to the programmed 10 as well."""
    lines = _verified(PER_MINUTE, "grbl", _lathe({2: (4.0, -1.5), 3: (0.0, 2.0)}, {3: (0.2, -0.1)}))
    moves = [line for line in lines if line.startswith(("G0 ", "G1 ", "G18 G0"))]
    assert moves == ["G18 G0 X50. Z50.", "G0 X27. Z3.5", "G1 X22. F200.", "G1 Z-11.5", "G0 Z11.9 X20.1", "G0 X35. Z10."]


def test_towards_linuxcnc_the_register_goes_to_the_move_that_applies_it() -> None:
    lines = _verified(FANUC_T, "linuxcnc", _lathe({2: (4.0, -1.5), 3: (0.0, 2.0)}, {3: (0.2, -0.1)}))
    assert "G43 H02 G0 X50. Z5." in lines and "G43 H03 G0 Z10. X40." in lines and "G49 G0 X70. Z10." in lines


TOOL_LINE = "O0001\nG21 G18 G99\nG00 T0102\nM03 S1000\nG00 X50. Z5.\nG01 X40. F0.2\nM30\n"
"""A Haas/Fanuc lathe's usual tool line ``G00 T0102`` at the program start (issue 26, Haas lathe programs
seen in public repositories): a motion code without an axis moves nothing, so the offset waits for the X50
Z5 traverse, which names both axes."""


def test_a_tool_line_with_a_motion_code_and_no_axis_moves_nothing() -> None:
    """Offset 2: X +4 (diameter), Z -1.5; the first move ends at 50 + 4, 5 - 1.5 (hand-derived): the same as
    with ``T0102`` alone, and ``G00 T0102`` itself makes no move."""
    setup = _lathe({2: (4.0, -1.5)})
    assert _moves(TOOL_LINE, "fanuc", setup) == [(50, 5, 54, 3.5), (40, 5, 44, 3.5)]
    assert _moves(TOOL_LINE, "fanuc", setup) == _moves(TOOL_LINE.replace("G00 T0102", "T0102"), "fanuc", setup)


def test_towards_linuxcnc_a_tool_line_with_a_motion_code_gives_the_register_to_the_next_move() -> None:
    """Was refused ("the programmed X and Z is not known where it applies"): the empty ``G00`` was taken
    for the move that applies the offset, at a point not known at the program start."""
    lines = _verified(TOOL_LINE, "linuxcnc", _lathe({2: (4.0, -1.5)}))
    assert "G43 H02 G0 X50. Z5." in lines


def _fanuc_t(rng: random.Random) -> str:
    lines = ["O0001", "G21 G18 G98", "G0 X100. Z50."]
    for _ in range(rng.randint(5, 12)):
        op = rng.random()
        if op < 0.3:
            lines.append(f"T01{rng.choice([0, 1, 2, 3, 4]):02d}")
        elif op < 0.55:
            lines.append(f"G1 X{rng.randint(10, 90)}. F150.")
        elif op < 0.8:
            lines.append(f"G0 Z{rng.randint(-30, 40)}.")
        else:
            lines.append(f"G1 X{rng.randint(10, 90)}. Z{rng.randint(-30, 40)}. F120.")
    lines.append("M30")
    return "\n".join(lines) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_fanuc_t_with_offsets_runs_alike_in_rs274() -> None:
    """Seeded Fanuc T programs with offsets changing mid-program, translated to LinuxCNC: rs274 (its table
    the set-up's offsets) runs the same controlled points as the Fanuc T simulation."""
    setup = _linuxcnc_setup()
    for seed in range(20):
        text = _fanuc_t(random.Random(seed))
        ngc = _translate(text, "linuxcnc", setup)
        ours = [(round(m[2], 4), round(m[3], 4)) for m in _moves(text, "fanuc", setup)]
        theirs = [(m[2], m[3]) for m in _rs274(ngc)]
        assert ours[1:] == theirs[1:], f"seed {seed}\n{text}\n{ngc}\nours   {ours}\nrs274  {theirs}"


# -- the set-up -------------------------------------------------------------------------------------------

LATHE_SETUP = """<?xml version='1.0' encoding='UTF-8'?>
<MachineSetup name="lathe offsets">
  <Input machineType="lathe"/>
  <Tools>
    <Tool number="2" x="4.0" z="-1.5"/>
    <Tool number="3" x="0.0" z="2.0" xWear="0.2" zWear="-0.1"/>
  </Tools>
</MachineSetup>
"""


def test_lathe_offsets_round_trip_through_config_dump(cli: Any, tmp_path: Any) -> None:
    path = tmp_path / "lathe.xml"
    path.write_text(LATHE_SETUP)
    assert cli("config", "check", path).status == 0
    result = cli("config", "dump", path)
    assert result.status == 0 and result.out.decode() == LATHE_SETUP


@pytest.mark.parametrize("tool, message", [
    ('<Tool number="2" x="4.0"/>', "a lathe offset gives x without z"),
    ('<Tool number="2" xWear="0.1"/>', "xWear/zWear without the geometry x and z")])
def test_config_check_names_a_missing_lathe_value(cli: Any, tmp_path: Any, tool: str, message: str) -> None:
    path = tmp_path / "lathe.xml"
    path.write_text(LATHE_SETUP.replace('<Tool number="2" x="4.0" z="-1.5"/>', tool))
    result = cli("config", "check", path)
    assert result.status != 0 and f'lathe.xml:5:1: error: <Tool number="2"> tool 2: {message}' in result.err


ONE_BLOCK = "G18 G7 G21 G90\nG0 X100 Z50\nT2 M6 G43\nG0 X60\nG1 Z5 F100\nT3 M6 G43\nG0 X40\nG0 Z20\nM2\n"
"""``T.. M6 G43`` in one block: M6 runs before G43 (rs274's order of execution), G43 without H takes the tool
just loaded [V: ``interp_convert.cc`` ``convert_tool_length_offset``, ``toolchange_flag``: the current pocket]."""


def test_a_change_and_its_offset_in_one_block_apply_where_each_axis_is_next_programmed() -> None:
    """By hand, as with the offset in a block of its own: entry 2 (X +5.08 on the diameter, Z +5.08) moves
    nothing; the X60 traverse keeps machine Z 50 (programmed 44.92) and goes to diameter 65.08; Z5 is
    machine 10.08. Entry 3 (X -2.54, Z +7.62): the X40 traverse keeps machine Z 10.08 (programmed 2.46) at
    diameter 37.46; Z20 is machine 27.62."""
    assert _ours(ONE_BLOCK) == [(100, 50, 100, 50), (60, 44.92, 65.08, 50), (60, 5, 65.08, 10.08),
                                (40, 2.46, 37.46, 10.08), (40, 20, 37.46, 27.62)]
    assert _ours(ONE_BLOCK.replace("T2 M6 G43", "T2 M6\nG43").replace("T3 M6 G43", "T3 M6\nG43")) == _ours(ONE_BLOCK)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_alone_moves_z_after_a_change_and_its_offset_in_one_block() -> None:
    """rs274 differs here, and only by its stand-alone canon: after a tool change the interpreter re-reads the
    position (``toolchange_flag``: ``execute_block`` returns ``INTERP_EXECUTE_FINISH``, the next read
    synchronises), and ``saicanon.cc``'s ``GET_EXTERNAL_POSITION_Z`` returns the last programmed Z without the
    tool offset, where the machine's canon subtracts it [V: LinuxCNC 2.9.0~pre1 ``emccanon.cc``
    ``GET_EXTERNAL_POSITION`` -> ``unoffset_and_unrotate_pos``, ``res -= canon.toolOffset``]. So rs274 takes the
    X60 traverse to programmed Z 50 (machine 55.08) where LinuxCNC itself keeps machine Z, as it does with G43
    in the next block (the re-read comes before the offset there, and rs274 agrees: pinned both ways)."""
    theirs = _rs274(ONE_BLOCK)
    assert theirs[1] == (60, 50, 65.08, 55.08)  # the stand-alone canon's re-read position
    split = ONE_BLOCK.replace("T2 M6 G43", "T2 M6\nG43").replace("T3 M6 G43", "T3 M6\nG43")
    assert _rs274(split)[1:] == _ours(split)[1:] == _ours(ONE_BLOCK)[1:]


def test_grblhal_lathe_mode_applies_the_change_where_each_axis_is_next_programmed() -> None:
    """grblHAL in lathe mode (a tool table build) follows the same rule ([V] grbl ``gcode.c``: an axis a move
    does not name keeps its machine position, a named one takes the offset; grblHAL's core keeps it, as
    ``postproc.lowering.length_timing`` cites): ``T2 M6 G43`` then X60 keeps machine Z 50, by hand as above."""
    setup = _linuxcnc_setup()
    setup.controller.tool_table = True
    text = "G18 G7 G21 G90\nG0 X100 Z50\nT2 M6 G43\nG0 X60\nG1 Z5 F100\nM2\n"
    assert [tuple(round(float(v), 4) for v in m) for m in _moves(text, "grblhal", setup)] == [
        (100, 50, 100, 50), (60, 44.92, 65.08, 50), (60, 5, 65.08, 10.08)]
