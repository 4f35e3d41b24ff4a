"""A lathe's turret index with the spindle turning, towards grblHAL (issue 29; the held-back lathes' grblHAL
build, ``tests/heldout/setups/grblhal_lathe.xml``).

What grblHAL does with a T word and M6, read in github.com/grblHAL/core at f80fc34 [V]:

* ``$341`` (``Setting_ToolChangeMode``, ``settings.c``) chooses among "Normal, Manual touch off, Manual touch off
  @ G59.3, Automatic touch off @ G59.3, Ignore M6" (``toolchange_mode_t``, 0-4, ``settings.h``).
* With no ATC plugin and ``$341=4`` (Ignore M6) the T word selects the tool at once (``gcode.c``, step 5 "Select
  tool": "If M6 not available or M61 commanded set new tool immediately", ``tool_set`` and ``gc_tool_changed``,
  no pause) and ``M6`` is read and does nothing (``gcode.c`` ``case 6``: the tool change is flagged only with an
  ATC or another mode).
* The core stops spindle and coolant at a tool change only in ``tool_change.c``'s ``tool_change``
  (``spindle_all_off(false)``), which ``tc_init`` installs as ``hal.tool.change`` for modes 1-3 only (for 0 and
  4 it sets ``hal.tool.change = NULL``): under ``$341=4`` nothing stops the spindle.
* ``G43 H<n>`` applies table entry n's offsets on every axis (``tool_offset_apply``); an axis the block does not
  name keeps its machine position ("No axis word in block. Keep same axis position.", ``gcode.c``), so the
  offset reaches an axis when the program next names it.

So a set-up whose build is so (``<Controller toolChangeWithSpindleOn="true"/>``) takes a Fanuc T index made with
the spindle turning as grblHAL's tool change, ``T2 M6`` with the spindle left on, and the offset as ``G43 H02``
on the next move with both axes (Fanuc T applies it there, to X and Z). Expected lines and moves are derived
by hand from those rules (X a diameter, G7); every output is held to grblHAL's parser rules
(``tests/support/grblhal_rules``).
"""

from __future__ import annotations

import dataclasses
import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.grblhal_rules import grblhal_problems
from tests.test_grblhal_lathe import BUILD, lathe

ROOT = Path(__file__).resolve().parents[1]
RETROFIT = load_setup(str(ROOT / "tests" / "heldout" / "setups" / "grblhal_lathe.xml"))
"""The held-back lathes' grblHAL build: encoder, tool table, tools indexed with the spindle on."""
TURNING = "O0001\nG21 G18 G99\nG0 X50. Z5.\nM03 S1000\nT0202\nG1 X40. F0.2\nZ-10.\nM30\n"
"""Tool 2 (offset 2) indexed while the spindle turns, as a Fanuc T program does."""


def _write(text: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="l.nc", source="fanuc", target="grblhal", setup=setup)
    return out.getvalue()


def _code(text: str) -> list[str]:
    return [line for line in text.splitlines() if line[:1] not in ("(", "%", "")]


def test_the_retrofit_says_what_its_build_has() -> None:
    controller = RETROFIT.controller
    assert RETROFIT.input.machine_type == "lathe" and RETROFIT.dialect == "grblhal"
    assert (controller.tool_table, controller.spindle_sync, controller.tool_change_with_spindle_on) == (True, True, True)


def test_an_index_with_the_spindle_turning_is_grblhals_tool_change_with_the_spindle_left_on() -> None:
    setup = lathe("fanuc_0i_tf.xml", RETROFIT.controller)
    text = _write(TURNING, setup)
    # G7 and the ZX plane first; G99 is G95; the index after the spindle start, no M5; offset 02 on the next
    # move, which names X only in the source: Fanuc T applies the offset there to both axes, grblHAL to the
    # axes the block names, so the move gets the Z the program stands at (5)
    assert _code(text) == ["G18 G7", "G18 G21 G95", "G0 X50. Z5.", "S1000 M3", "T2 M6", "G43 H02 G1 X40. Z5. F0.2",
                           "G1 Z-10.", "M30"]
    assert grblhal_problems(text, tool_table=True, spindle_sync=True, lathe=True) == []
    events = list(toolpath_events(io.StringIO(text), file="o.nc", dialect="grblhal", setup=setup))
    # the tool change stops nothing: no spindle event after the start (offsets of the harness's table are zero)
    assert [(e["event"], e.get("dir", e.get("number"))) for e in events if e.get("event") in ("spindle", "tool")] \
        == [("spindle", "cw"), ("tool", 2)]
    assert [(e["move"], e["x"], e["z"]) for e in events if "move" in e] == [
        ("rapid", 50, 5), ("feed", 40, 5), ("feed", 40, -10)]
    report = verify_lines(io.StringIO(TURNING), io.StringIO(text), file_in="l.nc", file_out="o.nc", source="fanuc",
                          target="grblhal", setup=setup, tolerance=0.0)
    assert report.ok, report.summary()


def test_checked_on_a_build_that_stops_the_spindle_the_same_output_differs() -> None:
    """Under ``$341`` 1-3 grblHAL's ``tool_change`` stops the spindle: a set-up without
    ``toolChangeWithSpindleOn`` simulates that, and verify finds the stop the source does not make."""
    keeps = lathe("fanuc_0i_tf.xml", RETROFIT.controller)
    text = _write(TURNING, keeps)
    stops = lathe("fanuc_0i_tf.xml", dataclasses.replace(RETROFIT.controller, tool_change_with_spindle_on=False))
    report = verify_lines(io.StringIO(TURNING), io.StringIO(text), file_in="l.nc", file_out="o.nc", source="fanuc",
                          target="grblhal", setup=stops, tolerance=0.0)
    assert not report.ok and "spindle stop" in report.summary()


def test_without_it_the_index_is_refused_where_it_stands() -> None:
    setup = lathe("fanuc_0i_tf.xml", BUILD)
    with pytest.raises(ErrorList) as caught:
        _write(TURNING, setup)
    assert [str(e) for e in caught.value.errors] == [
        "l.nc:5:1: error: a turret index (T0202) with the spindle turning: a mill control changes the tool "
        "with the spindle stopped, the lathe keeps it turning (stop the spindle before the index, or give a set-up "
        "whose machine changes tools with the spindle on: <Controller toolChangeWithSpindleOn=\"true\"/>)"]
