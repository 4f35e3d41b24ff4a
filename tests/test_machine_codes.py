"""Machine-specific codes (issue 12, item 1): declared in the set-up or by the family's defaults, kept
verbatim within the Fanuc family, left out with a warning (or refused) towards other families, and
simulated by their declared action; plus the set-up's <Controller> and <MachineCodes> elements."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.errors import ConfigError, Diagnostics, ErrorList, ErrorLevel
from postproc.ir import MachineFunction
from postproc.rs274.machine_codes import dwell_in_seconds
from postproc.setup.machine_setup import ControllerSettings, MachineCode, MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"
HAAS = MachineSetup(controller=ControllerSettings(variant="haas"))


def lines(text: str) -> list[str]:
    return [line + "\n" for line in text.strip().splitlines()]


def events(text: str, setup: MachineSetup | None = None, warnings: io.StringIO | None = None) -> list[dict[str, Any]]:
    diag = Diagnostics(ErrorLevel.RAISE, warn_stream=warnings or io.StringIO())
    return list(toolpath_events(lines(text), file="t.nc", dialect="fanuc", setup=setup, diagnostics=diag))[1:]


def to(target: str, text: str, on_unsupported: str = "warn", setup: MachineSetup | None = None) -> tuple[str, str]:
    out, warned = io.StringIO(), io.StringIO()
    diag = Diagnostics(ErrorLevel.RAISE, warn_stream=warned)
    translate(lines(text), out, file="t.nc", source="fanuc", target=target, setup=setup,
              on_unsupported=on_unsupported, diagnostics=diag)
    return out.getvalue(), warned.getvalue()


# -- reading --------------------------------------------------------------------------------------

def test_a_family_default_m_code_reads_as_a_machine_function_beside_the_rest_of_its_block() -> None:
    block = read_program(lines("G00 G43 H01 Z15. M88"), file="t.nc", dialect="fanuc")[0]
    assert block.get("MachineFunction") == MachineFunction("fanuc", "M88", "M88", "coolant-on",
                                                           "through-spindle coolant on")
    assert block.get("Motion").axes == {"Z": 15.0}
    assert block.get("ToolLengthOffset").register == 1


def test_an_undeclared_m_code_keeps_its_p_and_is_marked_undeclared() -> None:
    block = read_program(lines("M77 P3"), file="t.nc", dialect="fanuc")[0]
    assert block.get("MachineFunction") == MachineFunction("fanuc", "M77", "M77 P3", declared=False)


def test_a_haas_g_code_takes_its_declared_words_only_under_the_haas_variant() -> None:
    block = read_program(lines("G187 P1 E0.01"), file="t.nc", dialect="fanuc", setup=HAAS)[0]
    assert block.get("MachineFunction") == MachineFunction(
        "fanuc", "G187", "G187 P1 E0.01", name="smoothness and corner rounding")
    with pytest.raises(ErrorList) as info:
        read_program(lines("G187 P1 E0.01"), file="t.nc", dialect="fanuc")
    assert [str(e) for e in info.value.errors] == ["t.nc:1:1: error: unknown G code G187"]


def test_the_setup_declares_codes_over_the_family_defaults() -> None:
    setup = MachineSetup(machine_codes=[MachineCode(letter="M", number="88", action="none", name="door open"),
                                        MachineCode(letter="G", number="120.1", name="probe macro", words="Q")])
    first, second = read_program(lines("M88\nG120.1 Q5"), file="t.nc", dialect="fanuc", setup=setup)
    assert first.get("MachineFunction").action == "none" and first.get("MachineFunction").name == "door open"
    assert second.get("MachineFunction").text == "G120.1 Q5"


def test_two_machine_codes_in_one_block_are_refused_where_the_second_stands() -> None:
    with pytest.raises(ErrorList) as info:
        read_program(lines("M31 M88"), file="t.nc", dialect="fanuc")
    assert [str(e) for e in info.value.errors] == [
        "t.nc:1:5: error: M88: only one machine-specific function per block is supported"]


# -- translating ------------------------------------------------------------------------------------

def test_machine_codes_pass_verbatim_within_the_family() -> None:
    text = "%\nO1000\nG00 G90 X0. Y0. M31\nG187 P1 E0.01\nM88\nM77 P2\nM30\n%"
    out, warned = to("fanuc", text, "error", HAAS)
    assert (out, warned) == (text + "\n", "")


RIGID = "G21 G90 G0 X0 Y0 Z10.\nM29 S500\nG99 G84 X10. Y10. Z-10. R2. F750.\nG80\nM30"
"""A rigid tap (Fanuc 0i-MF: M29 S.. before G84 makes it follow the spindle [K]); fed as a floating tap's
moves on a machine without the holder's play, the tap breaks."""


@pytest.mark.parametrize("target", ["grbl", "fagor", "mach3"])  # (ISG taps by strokes: test_isg_tap_strokes_26)
@pytest.mark.parametrize("mode", ["warn", "error"])
def test_rigid_tapping_is_refused_towards_another_family_even_with_warn(target: str, mode: str) -> None:
    with pytest.raises(ErrorList) as info:
        to(target, RIGID, mode)
    assert sorted(str(e) for e in info.value.errors) == [
        f"t.nc:2:1: error: M29 (rigid tapping) of the fanuc family makes the tap cycles after it follow the spindle; "
        f"this translation writes no spindle-synchronised tap for {target}, and fed without the spindle in step a "
        "tap breaks: refused, even with --on-unsupported warn",
        f"t.nc:3:1: error: a rigid (spindle-synchronised) tap: this translation writes no synchronised tap for "
        f"{target} ({LACKS[target]}), and a tap fed without the spindle in step breaks: refused, even with "
        "--on-unsupported warn"]


LACKS = {
    "grbl": "grbl 1.1 reads no spindle position: no G33, G33.1 or tap cycle [K: grbl wiki, Commands]",
    "fagor": "the 8070's G84 R word selecting rigid tapping and its G63 rigid tap are [?]: their words and how the "
             "feed follows the pitch are not confirmed from a Fagor manual, DIALECTS.md 2.3",
    "mach3": "its G84 is the floating tap holder's cycle and it has no rigid tap code [V: Dynomotion's Mach3 plugin "
             "help, Mach3 Rigid Tapping]"}
"""Each target's reason, with its source, as the refusal names it (``Dialect.RIGID_TAP_LACK``)."""


@pytest.mark.parametrize("mode", ["warn", "error"])
def test_rigid_tapping_reaches_linuxcnc_as_its_synchronised_tap(mode: str) -> None:
    out, warned = to("linuxcnc", RIGID, mode)
    # F750 / S500 = 1.5 mm per revolution; G84 taps clockwise (the spindle, stopped, is started: G33.1 needs
    # it turning); G99: the tap returns to R2 and stays there
    assert out == ("G21 G90 G0 X0. Y0. Z10.\n"
                   "S500 (M29 [rigid tapping]: the taps after it are written spindle-synchronised)\n"
                   "G99 F750.\n(tap from line 3: G99 G84 X10. Y10. Z-10. R2. F750.)\n"
                   "G0 X10. Y10. Z10.\nG0 Z2.\nM3\nG33.1 Z-10. K1.5\nG0\nG80\nM30\n"), out
    assert warned == ""


def test_rigid_tapping_passes_within_the_family() -> None:
    out, warned = to("fanuc", RIGID, "warn")
    assert (out, warned) == (RIGID + "\n", "")


def test_a_lone_machine_code_becomes_a_comment_never_an_empty_line() -> None:
    out, warned = to("grbl", "G21 G90\nM31\nM30")
    assert out.splitlines()[1] == "(M31 NOT WRITTEN: M31 [part counter] of the fanuc family has no equivalent)"
    assert warned.count("warning:") == 1


def test_a_machine_code_towards_another_family_is_a_located_error_by_default() -> None:
    with pytest.raises(ErrorList) as info:
        to("linuxcnc", "G21 G90\nG00 X1. M88\nM30", "error")
    assert [str(e) for e in info.value.errors] == [
        "t.nc:2:1: error: M88 (through-spindle coolant on), a machine-specific code of the fanuc family, has no "
        "equivalent in linuxcnc (the target machine's set-up can say which of its machine codes it becomes: "
        '<ForeignCodes><M family="fanuc" number="88" to=".."/></ForeignCodes>)']


# -- simulating -------------------------------------------------------------------------------------

def test_machine_codes_are_simulated_by_their_action() -> None:
    got = events("G21 G90 G00 X0 Y0\nM31\nM41\nM88\nM89\nM30")
    assert got == [
        {"line": 2, "event": "machine", "code": "M31", "name": "part counter"},
        {"line": 3, "event": "machine", "action": "gear", "code": "M41", "name": "gear range 1"},
        {"line": 4, "event": "coolant", "on": True, "code": "M88", "name": "through-spindle coolant on"},
        {"line": 5, "event": "coolant", "on": False, "code": "M89", "name": "through-spindle coolant off"},
        {"line": 6, "event": "end"},
    ]


def test_an_undeclared_code_is_warned_about_once_and_moves_nothing() -> None:
    warned = io.StringIO()
    got = events("G21 G90\nM77\nG00 X1. M77\nM30", warnings=warned)
    assert got == [{"line": 2, "event": "machine", "code": "M77"},
                   {"line": 3, "event": "machine", "code": "M77"},
                   {"line": 3, "move": "rapid", "x": 1, "y": 0, "z": 0},
                   {"line": 4, "event": "end"}]
    assert warned.getvalue() == (
        "t.nc:2:1: warning: M77 is not declared for this machine (the set-up's <MachineCodes> or the fanuc "
        "family's defaults): simulated as a code that moves nothing\n")


def test_declared_stops_and_spindle_codes_act_after_and_before_the_motion() -> None:
    setup = MachineSetup(machine_codes=[MachineCode(letter="M", number="60", action="stop", name="pallet pause"),
                                        MachineCode(letter="M", number="13", action="spindle-cw", name="cw + coolant")])
    got = events("G21 G90\nG00 X1. M60\nG00 X2. M13\nM30", setup)
    assert got == [{"line": 2, "move": "rapid", "x": 1, "y": 0, "z": 0},
                   {"line": 2, "event": "stop", "optional": False, "code": "M60", "name": "pallet pause"},
                   {"line": 3, "event": "spindle", "dir": "cw", "code": "M13", "name": "cw + coolant"},
                   {"line": 3, "move": "rapid", "x": 2, "y": 0, "z": 0},
                   {"line": 4, "event": "end"}]


def test_verify_lists_the_machine_codes_it_did_not_compare() -> None:
    source = "G21 G90\nM31\nG00 X1.\nM30\n"
    out, _ = to("linuxcnc", source)
    report = verify_lines(lines(source), io.StringIO(out), file_in="a.nc", file_out="b.ngc", source="fanuc",
                          target="linuxcnc")
    assert report.ok
    assert report.ignored == ["M31 (part counter), a machine-specific code: IN 1x from line 2, OUT none"]


# -- the set-up ------------------------------------------------------------------------------------

def test_controller_and_machine_codes_round_trip_through_xml(tmp_path: Path, cli: Any) -> None:
    text = (DECLARATION + '<MachineSetup name="Haas VF-2" dialect="fanuc">\n'
            '  <Controller variant="haas" dwellSeconds="false"/>\n'
            '  <MachineCodes>\n'
            '    <M number="60" action="stop" name="pallet pause"/>\n'
            '    <G number="120.1" name="probe macro" words="Q"/>\n'
            '  </MachineCodes>\n'
            '</MachineSetup>\n')
    path = tmp_path / "m.xml"
    path.write_text(text)
    setup = load_setup(path)
    assert setup.controller.variant == "haas" and dwell_in_seconds(setup.controller) is False
    assert [c.key() for c in setup.machine_codes] == [("M", "60"), ("G", "120.1")]
    result = cli("config", "dump", path)
    assert (result.status, result.out.decode()) == (0, text)


@pytest.mark.parametrize("body, message, line", [
    ('<MachineCodes>\n    <M number="31.5"/>\n  </MachineCodes>', "<M> an M code number is whole, got '31.5'", 4),
    ('<MachineCodes>\n    <G number="187" action="stop"/>\n  </MachineCodes>',
     "<G> a machine G code has no action but none (it moves nothing)", 4),
    ('<MachineCodes>\n    <M number="31"/>\n    <M number="031"/>\n  </MachineCodes>', "M031 is declared twice", 5),
    ('<MachineCodes>\n    <T number="1"/>\n  </MachineCodes>',
     "unknown element <T> in <MachineCodes> (expected <M> or <G>)", 4),
    ('<MachineCodes>\n    <M number="8" action="flood"/>\n  </MachineCodes>', "<M> action: Input should be ", 4),
    ('<Controller variant="siemens"/>', "<Controller> variant: Input should be ", 3),
])
def test_bad_machine_code_declarations_are_located(tmp_path: Path, body: str, message: str, line: int) -> None:
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + f'<MachineSetup name="m">\n  {body}\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as info:
        load_setup(path)
    assert info.value.message.startswith(message)
    assert info.value.location is not None and info.value.location.line == line
