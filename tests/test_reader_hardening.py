"""What the grbl and LinuxCNC readers do with constructs the other dialects read differently.

* grbl 1.1 has no block delete: protocol.c drops every ``/`` outside comments ("Block delete NOT SUPPORTED.
  Ignore character.", github.com/gnea/grbl), so the block runs; the grbl reader reads it so, with a warning.
  A writer for grbl never writes ``/`` (``test_grbl.py`` pins the refusal).
* LinuxCNC's active comments (``(MSG,..)``, ``(DEBUG,..)``, ``(PRINT,..)``...) become inert in any other
  dialect: a translation keeps the text and warns, naming each; between LinuxCNC programs nothing is said.
"""

from __future__ import annotations

import io
from typing import Any

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.simulate.toolpath import toolpath_events


def events(text: str, dialect: str) -> tuple[list[dict[str, Any]], list[str]]:
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    found = list(toolpath_events(io.StringIO(text), file="t.gcode", dialect=dialect, diagnostics=diagnostics))[1:]
    return found, [str(w) for w in diagnostics.warnings]


def test_grbl_runs_a_block_with_a_slash_and_ignores_the_slash_wherever_it_stands() -> None:
    moves, warnings = events("G21 G0 X0 Y0 Z1\n/G0 X5 (a/b)\nG0 X1/2\n", "grbl")
    assert [m["x"] for m in moves] == [0, 5, 12]
    assert warnings == ["t.gcode:2:1: warning: '/' is ignored by grbl (no block delete): the block runs",
                        "t.gcode:3:6: warning: '/' is ignored by grbl (no block delete): the block runs"]


def test_linuxcnc_still_reads_a_slash_as_block_delete() -> None:
    moves, warnings = events("G21 G0 X0 Y0 Z1\n/G0 X5\n", "linuxcnc")
    assert [m["x"] for m in moves] == [0, 5] and warnings == []  # the switch is off in a simulation


def test_a_grbl_slash_block_translates_as_a_block_that_always_runs() -> None:
    out = io.StringIO()
    translate(io.StringIO("G21 G0 X0 Y0 Z1\n/G0 X5\n"), out, file="t.gcode", source="grbl", target="fanuc",
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    # (G61 first: grbl runs its one mode, the exact path, from power-on [V: grbl gcode.h CONTROL_MODE_EXACT_PATH
    # "G61 (Default)"]; Fanuc powers on in the cutting mode G64 [K], and writes it with its exact stop G61 [K])
    assert out.getvalue() == "G61 G21 G00 X0. Y0. Z1.\nG00 X5.\n"


def linuxcnc_to(target: str, text: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text), out, file="t.ngc", source="linuxcnc", target=target, diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


ACTIVE = ("G21 G0 X0 Y0 Z1\n(MSG, change tool)\n#1=5\n(debug, x is #1) G0 X#1\nG0 X1 (print,done)\n"
          "; (MSG,not active: a semicolon comment)\n(msgs are inert)\no1 while [#1 GT 3]\n(LOGOPEN,f.txt)\n"
          "#1=[#1-1]\no1 endwhile\nM2\n")


def test_active_comments_warn_when_a_translation_makes_them_inert() -> None:
    for target in ("fanuc", "grbl"):
        text, warnings = linuxcnc_to(target, ACTIVE)
        assert "CHANGE TOOL" in text.upper() and "DEBUG, X IS" in text.upper()
        assert warnings == [
            f"t.ngc:2:1: warning: LinuxCNC active comment (MSG,...) is an inert comment in {target}: the operator "
            "no longer sees the message",
            f"t.ngc:4:1: warning: LinuxCNC active comment (DEBUG,...) is an inert comment in {target}: the parameter "
            "values it prints are lost",
            f"t.ngc:5:7: warning: LinuxCNC active comment (PRINT,...) is an inert comment in {target}: its text is no "
            "longer printed",
            f"t.ngc:9:1: warning: LinuxCNC active comment (LOGOPEN,...) is an inert comment in {target}: no log file "
            "is opened"]


def test_active_comments_stay_between_linuxcnc_programs() -> None:
    text, warnings = linuxcnc_to("linuxcnc", ACTIVE)
    assert text == ACTIVE and warnings == []
