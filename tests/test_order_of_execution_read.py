"""Reading a LinuxCNC or grbl block that moves and stops the spindle or the coolant: RS274/NGC makes the
stop *before* the motion (``G1 X10 M5`` stops and then cuts). The reader flags the section
``before_motion``; the toolpath puts the stop before the move (checked against the LinuxCNC interpreter),
a Fanuc-family target gets it in a block of its own before the moving block, an RS274/NGC target keeps
it in the block, and the IR XML carries the flag."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.commands.program_xml import load_program
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274

HEAD = "G21 G90 G0 X0 Y0 Z5\nS1000 M3 M8\n"
TAIL = "G0 Z10\nM2\n"
STOPS = {"M5": "M05", "M9": "M09", "M5 M9": "M05 M09"}


def _program(words: str, move: str = "G1 X10 F100") -> str:
    return f"{HEAD}{move} {words}\n{TAIL}"


def _translate(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target)
    return out.getvalue()


def _events(text: str, dialect: str) -> list[dict[str, Any]]:
    """The toolpath without its header, source lines and feed rates (rs274's vocabulary)."""
    return [{k: v for k, v in ev.items() if k not in ("line", "f")}
            for ev in toolpath_events(io.StringIO(text), file="p.nc", dialect=dialect) if "toolpath" not in ev]


def _sections(text: str, dialect: str, line: int) -> dict[str, Any]:
    block = next(b for b in read_program(io.StringIO(text), file="p.nc", dialect=dialect) if b.line == line)
    return block.sections


@pytest.mark.parametrize("dialect", ["linuxcnc", "grbl"])
def test_a_moving_blocks_stops_are_flagged(dialect: str) -> None:
    sections = _sections(_program("M5 M9"), dialect, 3)
    assert sections["SpindleControl"].before_motion is True
    assert sections["Coolant"].before_motion is True


@pytest.mark.parametrize("line", ["M5 M9", "G1 F100 M5 M9"])  # a bare G1 needs a feed rate (rs274, grbl)
def test_a_block_without_motion_leaves_them_unflagged(line: str) -> None:
    sections = _sections(f"{HEAD}{line}\n{TAIL}", "linuxcnc", 3)
    assert sections["SpindleControl"].before_motion is False
    assert sections["Coolant"].before_motion is False


def test_fanuc_reading_leaves_them_unflagged() -> None:
    sections = _sections("G21 G90 G00 X0 Y0 Z5.\nS1000 M03 M08\nG01 X10. F100. M05 M09\nM30\n", "fanuc", 3)
    assert sections["SpindleControl"].before_motion is False
    assert sections["Coolant"].before_motion is False


@pytest.mark.parametrize("words", sorted(STOPS))
def test_toolpath_stops_before_the_feed(words: str) -> None:
    """By hand: after the start-up events, the block's stops come first, then the cut."""
    events = _events(_program(words), "linuxcnc")
    feed = events.index({"move": "feed", "x": 10, "y": 0, "z": 5})
    stops = [{"event": "spindle", "dir": "stop"}] * ("M5" in words) + [{"event": "coolant", "on": False}] * ("M9" in words)
    assert events[feed - len(stops):feed] == stops


def _through_last_move(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Events up to the last move: what rs274 prints at M2 (spindle stop, coolant off) is not compared."""
    last = max(i for i, ev in enumerate(events) if "move" in ev)
    return events[:last + 1]


def _without_repeated_stops(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """rs274 prints a stop of a stopped spindle (M5 after M6's own stop); postproc's toolpath makes no
    event of it (``Simulator.spindle_event``)."""
    kept: list[dict[str, Any]] = []
    spindle = None
    for ev in events:
        if ev.get("event") == "spindle":
            if ev["dir"] == "stop" and spindle == "stop":
                continue
            spindle = ev["dir"]
        kept.append(ev)
    return kept


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("dialect", ["linuxcnc", "grbl"])
@pytest.mark.parametrize("text", [
    _program("M5"), _program("M9"), _program("M5 M9"), _program("M5 M9 T2 M6"),
    _program("M5", "G2 X10 Y0 I5 J0 F100"),
    _program("M5 M9", "G98 G81 X5 Y5 Z-1 R2 F100"),
], ids=["m5", "m9", "m5_m9", "tool_change", "arc", "cycle"])
def test_toolpath_order_matches_rs274(dialect: str, text: str) -> None:
    if dialect == "grbl" and ("G81" in text or "M6" in text):
        pytest.skip("grbl has no canned cycles and no tool changer")
    oracle = _without_repeated_stops(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)))
    assert _through_last_move(_events(text, dialect)) == _through_last_move(oracle)


@pytest.mark.parametrize("words", sorted(STOPS))
def test_fanuc_gets_the_stops_before_the_moving_block(words: str) -> None:
    out = _translate(_program(words), "linuxcnc", "fanuc")
    assert f"\n{STOPS[words]}\nG01 X10. F100.\n" in out, out


def test_a_tool_change_stays_before_the_coolant_off() -> None:
    out = _translate(_program("M9 T2 M6"), "linuxcnc", "fanuc")
    assert "\nT2 M06 M09\nG01 X10. F100.\n" in out, out


def test_the_example_dialect_keeps_them_in_the_block() -> None:
    """The example plugin (mach3) stops before the motion as LinuxCNC does (RS274/NGC order; it was a
    Fanuc-order toy before): the stop stays in its block and still runs before the move."""
    out = _translate(_program("M5"), "linuxcnc", "mach3")
    assert "\nG1 X10.0000 F100. M5\n" in out, out


@pytest.mark.parametrize("words", sorted(STOPS) + ["M5 M9 T2 M6"])
def test_verify_source_and_fanuc_output_at_zero(words: str) -> None:
    text = _program(words)
    out = _translate(text, "linuxcnc", "fanuc")
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.ngc", file_out="out.nc",
                          source="linuxcnc", target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()
    assert _events(out, "fanuc") == _events(text, "linuxcnc")


def test_the_stop_left_in_the_fanuc_block_would_be_a_different_toolpath() -> None:
    """The comparison above can fail: Fanuc runs ``G01 X10. M05`` as cut-then-stop."""
    text = _program("M5")
    wrong = "G21 G90 G00 X0 Y0 Z5.\nS1000 M03 M08\nG01 X10. F100. M05\nG00 Z10.\nM02\n"
    assert _events(wrong, "fanuc") != _events(text, "linuxcnc")


@pytest.mark.parametrize("dialect", ["linuxcnc", "grbl"])
@pytest.mark.parametrize("words", sorted(STOPS))
def test_round_trip_is_byte_for_byte(dialect: str, words: str) -> None:
    text = _program(words)
    assert _translate(text, dialect, dialect) == text


@pytest.mark.parametrize("source, target", [("linuxcnc", "grbl"), ("grbl", "linuxcnc")])
def test_an_rs274_target_keeps_them_in_the_block(source: str, target: str) -> None:
    out = _translate(_program("M5 M9"), source, target)
    assert "\nG1 X10. F100. M5 M9\n" in out, out


def test_ir_xml_carries_the_flag(cli: Any, tmp_path: Any) -> None:
    src = tmp_path / "p.ngc"
    src.write_text(_program("M5 M9"))
    xml = tmp_path / "ir.xml"
    result = cli("ir", src, "--dialect", "linuxcnc", "-o", xml)
    assert result.status == 0, result.err
    text = xml.read_text()
    assert '<SpindleControl direction="stop" before_motion="true"/>' in text
    assert '<Coolant mode="off" before_motion="true"/>' in text
    assert text.count("before_motion") == 2  # the spindle start, coolant on and M2 stay as they were
    dialect, loaded = load_program(xml)
    with open(src, encoding="utf-8") as f:
        expected = read_program(f, file=str(src), dialect="linuxcnc")
    assert dialect == "linuxcnc"
    assert loaded == expected
