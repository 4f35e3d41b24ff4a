"""What hand-written shop programs spell (issue #31, item 16 and the Fanuc power-on motion mode): Haas and
Fanuc programs as operators type them. Expected values come from the manuals cited beside each fact in
the code (Fanuc 0i-F operator's manual, Haas mill operator's manual) and are derived by hand here."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.setup import ControllerSettings, MachineSetup, load_setup
from postproc.toolpath import toolpath_events

HAAS = MachineSetup(controller=ControllerSettings(variant="haas"))


def lines(text: str) -> list[str]:
    return [line + "\n" for line in text.strip("\n").splitlines()]


def events(text: str, setup: MachineSetup | None = None, dialect: str = "fanuc") -> list[dict[str, Any]]:
    diag = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    return list(toolpath_events(lines(text), file="t.nc", dialect=dialect, setup=setup, diagnostics=diag))[1:]


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
    assert translated("G43 H1 Z1.\nX1.\nM30", "linuxcnc").splitlines()[:2] == ["G43 H01 G0 Z1.", "G0 X1."]


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
