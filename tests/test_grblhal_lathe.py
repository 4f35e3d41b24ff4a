"""grblHAL's lathe mode (``plugins/grblhal/postproc_grblhal/lathe.py``, issue 29 item 4): Fanuc T and GSK lathe
programs translated to it, and its own lathe words read.

Expected texts are derived by hand from grblHAL's ``gcode.c`` (github.com/grblHAL/core, stored commit f80fc34),
as the plugin's ``lathe`` docstring quotes it: ``G18 G7`` first, ``G96 S.. D..`` with the Fanuc-family clamp
(``G50 S``), a thread as ``G33 .. K..`` with K along the path and its F on a line before it, ``T0101`` as
``T1 M6`` .. ``G43 H1`` on a build with a tool table. grblHAL's lathe words mean what LinuxCNC's do (``gcode.c``
against rs274 2.9), so rs274 in lathe mode runs the grblHAL output as the oracle: the same moves as our
simulation of the source. Every output is checked against grblHAL's rules (``tests/support/grblhal_rules``).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import InputSettings, MachineSetup, load_setup
from postproc.simulate.verify import verify_lines
from tests.support.grblhal_rules import grblhal_problems
from tests.support.rs274 import available
from tests.test_lathe import SEED
from tests.test_lathe_rs274 import difference, ours, theirs

ROOT = Path(__file__).resolve().parents[1]
SETUPS = ROOT / "examples" / "setups"
BUILD = ControllerSettings(tool_table=True, spindle_sync=True)
"""A grblHAL lathe build with a tool table and a spindle encoder."""


def lathe(name: str, controller: ControllerSettings = BUILD) -> MachineSetup:
    """The shipped set-up ``name`` with the grblHAL build ``controller``."""
    setup = load_setup(str(SETUPS / name))
    setup.controller = controller
    return setup


FANUC_T = lathe("fanuc_0i_tf.xml")
GSK = lathe("gsk_980tdc.xml")
PROGRAMS = [("fanuc", FANUC_T, p) for p in sorted((ROOT / "examples" / "fanuc-lathe").glob("*.nc"))] + \
    [("gsk", GSK, p) for p in sorted((ROOT / "examples" / "gsk").glob("*.nc"))]


def write(text: str, source: str = "fanuc", setup: MachineSetup = FANUC_T, target: str = "grblhal") -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def errors(text: str, source: str = "fanuc", setup: MachineSetup = FANUC_T, target: str = "grblhal") -> list[str]:
    with pytest.raises(ErrorList) as info:
        write(text, source, setup, target)
    return [str(e) for e in info.value.errors]


def code_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line[:1] not in ("(", "%", "")]


def grblhal_ok(text: str, setup: MachineSetup = FANUC_T) -> list[str]:
    controller = setup.controller
    return grblhal_problems(text, tool_table=bool(controller.tool_table), spindle_sync=bool(controller.spindle_sync),
                            lathe=True)


# -- done when ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("dialect,setup,path", [*PROGRAMS, ("gsk", GSK, "seed")],
                         ids=[p.name for _, _, p in PROGRAMS] + ["gsk-seed"])
def test_lathe_programs_reach_grblhal_verify_and_run_in_rs274(dialect: str, setup: MachineSetup,
                                                               path: Path | str) -> None:
    text = SEED if path == "seed" else Path(path).read_text()
    out = write(text, dialect, setup)
    assert code_lines(out)[0] == "G18 G7"
    assert grblhal_ok(out, setup) == []
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="out.nc", source=dialect,
                          target="grblhal", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    again = io.StringIO()
    translate(io.StringIO(out), again, file="out.nc", source="grblhal", target="grblhal", setup=setup)
    assert again.getvalue() == out  # read back as grblHAL's lathe mode, written byte for byte
    if available():
        problem = difference(ours(text, dialect, setup), theirs(out))
        assert problem is None, f"{problem}\n\n{out}"


def test_the_thread_programs_keep_g96_g95_and_g33() -> None:
    for dialect, setup, path in PROGRAMS:
        lines = code_lines(write(path.read_text(), dialect, setup))
        if "thread" in path.name:
            assert any(line.startswith("G33 ") and " K" in line for line in lines), path.name
    shaft = code_lines(write((ROOT / "examples" / "fanuc-lathe" / "o2001_stepped_shaft.nc").read_text()))
    assert "G21 G95" in shaft and "G96 D2500 S180 M3" in shaft  # G50 S2500 is the clamp of G96 S180


# -- written by hand from gcode.c ----------------------------------------------------------------------

FANUC = ("G21 G99\nG50 S2000\nG97 S500 M3\nG00 X40. Z2.\nG96 S150\nG01 X30. F0.2\nG32 Z-20. F1.5\nG00 X40.\n"
         "G32 X44. Z-24. F2.\nG00 X50.\nM30\n")


def test_a_fanuc_t_program_with_css_and_threads() -> None:
    """G50 S2000 waits for the G96 (grblHAL clamps on the G96 line: D); G32's F is the lead along Z: K1.5 for
    a straight thread, and for the taper X40 -> X44 (radius 2) over Z 4: K = 2 * sqrt(2^2 + 4^2) / 4 =
    2.236068 along the path; each thread's F on a line before it."""
    assert code_lines(write(FANUC)) == [
        "G18 G7", "G21 G95", "G97 S500 M3", "G0 X40. Z2.", "G96 D2000 S150", "G1 X30. F0.2", "F1.5",
        "G33 Z-20. K1.5", "G0 X40.", "F2.", "G33 X44. Z-24. K2.236068", "G0 X50.", "M30"]


def test_a_turret_index_is_a_tool_change_with_the_offset_from_the_table() -> None:
    """T0203: tool 2, offset 3 (Fanuc T) -> ``T2 M6``, and ``G43 H03`` at the first move (grblHAL's G43 applies
    the table entry's offsets on every axis: ``tool_offset_apply``)."""
    lines = code_lines(write("G21 G98\nT0203\nG00 X40. Z2.\nM30\n"))
    assert lines == ["G18 G7", "G21 G94", "T2 M6", "G43 H03 G0 X40. Z2.", "M30"]


# -- what a build lacks, and what grblHAL refuses ------------------------------------------------------

def test_a_build_without_a_spindle_encoder_has_no_g33() -> None:
    setup = lathe("fanuc_0i_tf.xml", ControllerSettings(tool_table=True))
    assert errors("G21 G98\nS500 M3\nG00 X40. Z2.\nG32 Z-20. F1.5\nM30\n", setup=setup) == [
        "in.nc:4:1: error: the grblhal dialect cannot express a thread move (G33) on a grblHAL spindle without an "
        "encoder: a set-up with <Controller spindleSync=\"true\"/> has one"]


def test_a_build_without_a_tool_table_cannot_apply_a_lathe_offset() -> None:
    setup = lathe("fanuc_0i_tf.xml", ControllerSettings(spindle_sync=True))
    assert errors("G21 G98\nT0101\nG00 X40. Z2.\nM30\n", setup=setup) == [
        "in.nc:3:1: error: a lathe tool's offsets (register 1: X and Z) on a build without a tool table (the dynamic "
        "offset would take only Z): a set-up with <Controller toolTable=\"true\"/> has one"]


def test_no_feed_move_under_css_with_the_spindle_stopped() -> None:
    """grblHAL: error 41 for a G1 under G96 before M3 (``gcode.c``, "check for spindle running for moves in G96
    mode"); the rapid before it is accepted."""
    assert errors("G21 G98\nG50 S2000\nG96 S150\nG00 X40. Z2.\nG01 X30. F100.\nM3\nG1 Z-5.\nM30\n") == [
        "in.nc:5:1: error: the grblhal dialect cannot express a feed move under constant surface speed (G96) while "
        "the spindle is stopped (grblHAL: error 41, spindle not running)"]


# -- reading grblHAL -------------------------------------------------------------------------------------

GRBLHAL_SETUP = MachineSetup(input=InputSettings(machine_type="lathe"), controller=BUILD)


@pytest.mark.parametrize("text,message", [
    ("G18 G7\nG96 D100 M3\nM2\n", "2:1: error: G96 needs S, the surface speed (grblHAL: error 28, a value word "
                                  "missing)"),
    ("G18 G7\nS500 M3\nG0 X20. Z2.\nG33 Z-3.\nM2\n", "4:1: error: G33 needs K, the distance per spindle revolution "
                                                     "(grblHAL would take the last G33's K, which this reader does not model)"),
    ("G18 G7 G8\nM2\n", "1:8: error: G7 and G8 in one block, one modal group"),  # (a switch alone is read:
    # tests/test_linuxcnc_x_mode_switch.py)
    ("G76 P2. Z-20. I-1. J0.3 K1.2\nM2\n", "1:1: error: grblHAL's G76 with the spindle stopped"),
])
def test_grblhal_lathe_words_are_read_or_refused_where_they_stand(text: str, message: str) -> None:
    found = errors(text, "grblhal", GRBLHAL_SETUP)
    assert len(found) == 1 and found[0].startswith("in.nc:" + message), found


def test_the_lathe_words_are_refused_on_a_mill_set_up() -> None:
    assert errors("G7\nM2\n", "grblhal", MachineSetup(), "linuxcnc") == [
        "in.nc:1:1: error: grblHAL runs G7 in lathe mode only ($32, error 20 otherwise): a set-up with <Input "
        "machineType=\"lathe\"/> reads and writes grblHAL's lathe mode"]
    assert errors("G33 Z-3. K1.\nM2\n", "grblhal", MachineSetup(controller=BUILD), "linuxcnc")[0].startswith(
        "in.nc:1:1: error: grblHAL runs G33 in lathe mode only")


def test_a_grblhal_lathe_program_reaches_linuxcnc_with_the_same_words() -> None:
    """The words mean the same on both (``gcode.c`` against rs274): G96 S D, G33 K, G97 pass as they are; the
    program's own G7 agrees with the set-up and is said by the mode line LinuxCNC's writer puts first."""
    text = "G18 G7 G21\nG96 S150 D2200 M3\nG0 X20. Z2.\nG33 X22. Z-2. K1.\nG97 S500\nM2\n"
    setup = MachineSetup(input=InputSettings(machine_type="lathe"), controller=BUILD)
    assert code_lines(write(text, "grblhal", setup, "linuxcnc")) == [
        "G18 G7", "G18 G21", "G96 D2200 S150 M3", "G61 G0 X20. Z2.", "G33 X22. Z-2. K1.", "G97 S500", "M2"]
    # (G61 before the first move: grblHAL powers on in its one mode, the exact path [V: grblHAL core gcode.h,
    # ControlMode_ExactPath "G61 - Default"]; LinuxCNC powers on blending, G64)
