"""What hand-written shop programs spell (issue #31, item 16 and the Fanuc power-on motion mode): Haas and
Fanuc programs as operators type them. Expected values come from the manuals cited beside each fact in
the code (Fanuc 0i-F operator's manual, Haas mill operator's manual) and are derived by hand here."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.setup.machine import WorkOffsetData
from postproc.setup.machine_setup import ControllerSettings, MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from tests.support.tools import with_tools

HAAS = MachineSetup(controller=ControllerSettings(variant="haas"))


def lines(text: str) -> list[str]:
    return [line + "\n" for line in text.strip("\n").splitlines()]


def events(text: str, setup: MachineSetup | None = None, dialect: str = "fanuc") -> list[dict[str, Any]]:
    diag = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    return list(toolpath_events(lines(text), file="t.nc", dialect=dialect, setup=with_tools(setup),
                                diagnostics=diag))[1:]


def errors(text: str, setup: MachineSetup | None = None, dialect: str = "fanuc") -> list[str]:
    with pytest.raises(ErrorList) as info:
        events(text, setup, dialect)
    return [str(e) for e in info.value.errors]


def translated(text: str, target: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO()
    translate(lines(text), out, file="t.nc", source="fanuc", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


# -- Fanuc powers on in G00 (parameter 3402#0 G01 = 0), or in G01 ----------------------------------------

def test_a_first_move_without_a_motion_code_is_rapid_at_power_on() -> None:
    assert events("G43 H1 Z1.\nX1.\nM30") == [
        {"line": 1, "move": "rapid", "x": 0, "y": 0, "z": 1},
        {"line": 2, "move": "rapid", "x": 1, "y": 0, "z": 1},
        {"line": 3, "event": "end"}]


def test_the_set_up_may_say_the_machine_powers_on_in_g01() -> None:
    setup = MachineSetup(controller=ControllerSettings(start_motion="linear"))
    assert events("G43 H1 Z1. F100.\nX1.\nM30", setup) == [
        {"line": 1, "move": "feed", "x": 0, "y": 0, "z": 1, "f": 100},
        {"line": 2, "move": "feed", "x": 1, "y": 0, "z": 1, "f": 100},
        {"line": 3, "event": "end"}]


def test_a_computed_length_register_before_any_motion_code_round_trips() -> None:
    source = "#1=2\nG43 H#1 Z1.\nM30\n"
    assert translated(source, "fanuc") == source


def test_the_power_on_mode_reaches_a_target_that_needs_a_motion_code() -> None:
    assert translated("G43 H1 Z1.\nX1.\nM30", "linuxcnc").splitlines()[:2] == ["G21 G43 H01 G0 Z1.", "G0 X1."]  # G21: the units read in


def test_a_dialect_without_a_power_on_mode_still_refuses_axis_words_first() -> None:
    # rs274: "Cannot use axis values without a g code that uses them"
    assert errors("X1.\nM2", dialect="linuxcnc") == [
        "t.nc:1:1: error: axis words with no motion mode in force (program G0 or G1 first)"]


def test_start_motion_round_trips_through_the_set_up_file(tmp_path) -> None:
    path = tmp_path / "m.xml"
    path.write_text('<MachineSetup dialect="fanuc"><Controller startMotion="linear"/></MachineSetup>\n')
    assert load_setup(path).controller.start_motion == "linear"
    path.write_text('<MachineSetup dialect="fanuc"><Controller startMotion="G01"/></MachineSetup>\n')
    with pytest.raises(Exception, match="startMotion"):
        load_setup(path)


# -- ';' ends a block; what follows it on the line may only be comments -----------------------------------

SEMICOLONS = "G00 X0 Y0 Z1.;\nG01 Z.1 M09 F100.; (Retract);\nG01 X1.;;\n(only);\nM30\n"


def test_a_comment_after_the_end_of_block_is_read_and_written_back() -> None:
    assert translated(SEMICOLONS, "fanuc") == SEMICOLONS
    assert events(SEMICOLONS) == [
        {"line": 1, "move": "rapid", "x": 0, "y": 0, "z": 1},
        {"line": 2, "move": "feed", "x": 0, "y": 0, "z": 0.1, "f": 100},
        {"line": 2, "event": "coolant", "on": False},
        {"line": 3, "move": "feed", "x": 1, "y": 0, "z": 0.1, "f": 100},
        {"line": 5, "event": "end"}]


def test_the_comment_after_the_end_of_block_reaches_another_dialect() -> None:
    assert "(Retract)" in translated(SEMICOLONS, "linuxcnc").splitlines()[1]


def test_a_second_block_after_the_end_of_block_is_refused_where_it_starts() -> None:
    assert errors("G00 X0 Y0 Z1.\nG00 X2.; G01 X3. F1.\nM30") == [
        "t.nc:2:10: error: only comments may follow ';' (the end of the block) on its line: put the next block "
        "on a line of its own"]


# -- an offset register H without G43/G44/G49 in its block ---------------------------------------------

def test_h0_beside_g53_under_g49_cancels_nothing_and_moves_in_machine_coordinates() -> None:
    # Haas `G53 G0 Z0 H0;`: G49 is in force at power-on, H0's offset is zero: the length offset stays off
    # (machine and work coordinates coincide: the default set-up has no work offset)
    assert events("G00 X1. Z10.\nG53 G0 Z0 H0;\nM30") == [{"line": 1, "move": "rapid", "x": 1, "y": 0, "z": 10},
                                                          {"line": 2, "move": "rapid", "x": 1, "y": 0, "z": 0},
                                                          {"line": 3, "event": "end"}]
    assert translated("G53 G0 Z0 H0;\nM30", "linuxcnc").splitlines()[0] == "G53 G21 G49 G0 Z0."  # G21: the units read in


def test_h_alone_under_g43_selects_that_register() -> None:
    setup = MachineSetup()
    setup.work_offsets = {"1": WorkOffsetData(number=1, x=0.0, y=0.0, z=-100.0)}
    out = translated("G43 H1 Z10.\nG53 G0 Z0 H0\nG00 X1. H2\nM30", "linuxcnc", setup).splitlines()
    # the X move applies H2 on Fanuc: LinuxCNC gets the Z it stands at: machine Z0, G54's Z offset -100, H0 (no
    # length) in force: work Z = 0 - (-100) - 0 = 100 (by hand)
    assert out[1:3] == ["G53 G43 H00 G0 Z0.", "G43 H02 G0 X1. Z100."]
    # without G54 in the set-up the machine Z0 is no known work Z (issue 26: it was written as work Z0)
    with pytest.raises(ErrorList) as info:
        translated("G43 H1 Z10.\nG53 G0 Z0 H0\nG00 X1. H2\nM30", "linuxcnc")
    assert str(info.value.errors[0]).startswith("t.nc:3:9: error: ")


def test_h_alone_under_g49_is_refused_naming_g43() -> None:
    assert errors("G00 X0\nX1. H2\nM30") == [
        "t.nc:2:5: error: H2 with no tool length offset in force: a register takes effect with G43 or G44 (write "
        "it in their block)"]


# -- an error a set-up option would remove names the option ---------------------------------------------

def test_a_dwell_p_in_seconds_names_the_haas_option() -> None:
    message = errors("G04 P0.5\nM30")[0]
    assert message.startswith("t.nc:1:5: error: address P takes no decimal point (P0.5)")
    assert '<Controller dwellSeconds="true"/>' in message
    assert events("G04 P0.5\nM30", HAAS)[0] == {"line": 1, "event": "dwell", "seconds": 0.5}


def test_a_cycle_dwell_names_the_option_and_another_p_does_not() -> None:
    assert '<Controller dwellSeconds="true"/>' in errors("G00 X0 Y0 Z5.\nG82 X1. Z-1. R1. P0.3 F10.\nM30")[0]
    assert errors("G10 L2 P1.5 X1.\nM30") == ["t.nc:1:8: error: address P takes no decimal point (P1.5)"]


def test_g42_h_names_the_0m_option() -> None:
    message = errors("G00 X0 Y0\nG42 H19 G01 X10. F100.\nG40 G00 X0\nM30")[0]
    assert message.startswith("t.nc:2:5: error: G42 takes its radius register from D, not H19")
    assert '<Controller cutterRegisterH="true"/>' in message


# -- a macro's own alarm ---------------------------------------------------------------------------------

ALARM = "IF [#1 EQ #0] THEN #3000=1(NEED ROTATION AXIS)\nG00 X#1\nM30"


def test_a_macro_alarm_is_reported_as_raised_with_its_message() -> None:
    assert errors(ALARM) == ["t.nc:1:20: error: the program raises its alarm #3000=1 (NEED ROTATION AXIS)"]


def test_a_macro_alarm_not_raised_lets_the_program_run() -> None:
    assert events("#1=30.\n" + ALARM) == [{"line": 3, "move": "rapid", "x": 30, "y": 0, "z": 0},
                                          {"line": 4, "event": "end"}]


# -- Haas: the NGC's five-digit general-purpose variables -----------------------------------------------------

def test_haas_general_variables_are_the_programs_own() -> None:
    assert events("#10100=5.\nG00 X#10100\nM30", HAAS)[:1] == [{"line": 2, "move": "rapid", "x": 5, "y": 0, "z": 0}]


def test_the_same_number_is_fanuc_tool_data() -> None:
    assert errors("#10100=5.\nG00 X#10100\nM30") == [
        "t.nc:1:1: error: #10100 (tool compensation value) is known only to the machine: the program cannot be "
        "simulated or flattened"]


def test_haas_probe_results_are_the_machines() -> None:
    assert errors("G00 X#10150\nM30", HAAS) == [
        "t.nc:1:5: error: #10150 (probe value) is known only to the machine: the program cannot be simulated or "
        "flattened"]


def test_haas_tool_timers_are_not_work_offsets() -> None:
    """#5401-#6000 are a Haas's per-tool timers and monitors (Haas mill manual's macro variable table [K]), not
    Fanuc's work offsets: read or written, each is refused naming what it is on the machine the set-up names."""
    assert errors("G00 X#5401\nM30", HAAS) == [
        "t.nc:1:5: error: #5401 (tool feed timer) is known only to the machine: the program cannot be simulated or "
        "flattened"]
    assert errors("#5550=0\nM30", HAAS)[0].startswith("t.nc:1:1: error: #5550 (total tool timer) is known only")
    assert errors("G00 X#5999\nM30", HAAS)[0].startswith("t.nc:1:5: error: #5999 (tool load monitor limit) is")
    assert errors("G00 X#5221\nM30", HAAS)[0].startswith("t.nc:1:5: error: #5221 (work offset) is")
    assert errors("G00 X#5401\nM30")[0].startswith("t.nc:1:5: error: #5401 (work offset) is")  # a Fanuc's


def test_a_haas_program_mixing_both_numberings_is_refused_by_name() -> None:
    (message,) = errors("#100=1.\n#10100=5.\nG00 X#10100\nM30", HAAS)
    assert message.startswith("t.nc:2:1: error: #10100 and #100: a Haas program that uses both")


def test_a_haas_general_variable_translates_flattened_for_linuxcnc() -> None:
    assert translated("#10100=5.\nG00 X#10100\nM30", "linuxcnc", HAAS).splitlines()[-2:] == ["G21 G0 X5.", "M30"]  # G21: the units read in


# -- a macro file run on its own, with G65-style arguments ------------------------------------------------------

MACRO = "IF [#1 EQ #0] THEN #3000=1(NEED ROTATION AXIS)\nG00 X#1 Y#24\nM99"


def test_arguments_set_the_locals_of_argument_specification_i(cli, tmp_path) -> None:
    path = tmp_path / "O9001.nc"
    path.write_text(MACRO + "\n")
    # A -> #1, X -> #24; the macro's M99 returns to its (absent) caller: the run ends there
    result = cli("toolpath", path, "--dialect", "fanuc", "--arg", "A=30", "--arg", "x=2.5")
    assert result.status == 0, result.err
    assert result.out.decode().splitlines()[1:] == ['{"line": 2, "move": "rapid", "x": 30, "y": 2.5, "z": 0}']
    result = cli("verify", path, path, "--from", "fanuc", "--to", "fanuc", "--arg", "A=30")
    assert result.status == 0, result.err


def test_without_its_argument_the_macro_raises_its_alarm(cli, tmp_path) -> None:
    path = tmp_path / "O9001.nc"
    path.write_text(MACRO + "\n")
    result = cli("toolpath", path, "--dialect", "fanuc")
    assert result.status == 1
    first = result.err.splitlines()[0]
    assert first == f"{path}:1:20: error: the program raises its alarm #3000=1 (NEED ROTATION AXIS)"


@pytest.mark.parametrize("args, message", [
    (["--arg", "P=3"], "postproc: --arg P: not an argument address of the fanuc dialect"),
    (["--arg", "A"], "postproc: --arg takes LETTER=NUMBER (A=30), got 'A'"),
    (["--arg", "A=1", "--arg", "a=2"], "postproc: --arg A is given twice"),
])
def test_bad_arguments_are_usage(cli, tmp_path, args, message) -> None:
    path = tmp_path / "O9001.nc"
    path.write_text(MACRO + "\n")
    result = cli("toolpath", path, "--dialect", "fanuc", *args)
    assert result.status == 2
    assert result.err.startswith(message)


def test_a_dialect_without_call_arguments_refuses_them(cli, tmp_path) -> None:
    path = tmp_path / "a.ngc"
    path.write_text("G0 X1\nM2\n")
    result = cli("toolpath", path, "--dialect", "linuxcnc", "--arg", "A=1")
    assert result.status == 2
    assert result.err == "postproc: --arg: the linuxcnc dialect has no macro call arguments\n"


def test_a_vacant_value_is_flattened_for_linuxcnc_which_has_no_0() -> None:
    # found by the shop-spellings generator: rs274 refuses '#1=#0' ("Parameter number out of range");
    # by hand: #1 vacant, counted as 0 in [#1+1.] (Fanuc vacancy), so the move goes to X1.
    source = "G0 X0 Y0 Z1.\n#1=#0\nG0 X[#1+1.]\nM30"
    assert translated(source, "linuxcnc") == "G21 G0 X0. Y0. Z1.\nG0 X1.\nM30\n"  # G21: the units read in


def test_a_variable_linuxcnc_lacks_is_never_written_for_it() -> None:
    # found by the shop-spellings generator: 'G1 Z-#10200' reached LinuxCNC, whose parameters end at #5601
    assert translated("#10100=5.\nG1 Z-#10100 F10.\nM30", "linuxcnc", HAAS) == "G21 G1 Z-5. F10.\nM30\n"  # G21: the units read in
    with pytest.raises(ErrorList) as info:
        translated("G1 Z-#10100 F10.\nM30", "linuxcnc")
    assert [str(e) for e in info.value.errors] == [
        "t.nc:1:4: error: #10100 (tool compensation value) is known only to the machine: the program cannot be "
        "simulated or flattened"]
