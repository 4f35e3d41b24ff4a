"""End to end through the command line: Fanuc programs translated to grbl, then ``postproc verify``.

Every Fanuc example uses tool length offsets (``G43 H``), which grbl has no table for: each becomes
grbl's ``G43.1 Z<length>`` with the set-up's value, and the toolpaths agree exactly; a set-up without
the value is a located error, and a router whose tools are touched off drops them with a note.
The hole-cycle goldens are translated with a set-up that gives their Fanuc parameters and says how the
grbl machine stands in for an oriented spindle stop.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples" / "fanuc").glob("*.nc"))
CYCLES = sorted((ROOT / "tests" / "golden" / "fanuc" / "cycles").glob("*.nc"))
ORIENTING = ("g76_fine_boring.nc", "g87_back_boring.nc")
LOCATED = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<col>\d+): (?P<level>error|warning): (?P<message>.+)$")


def _setup(tmp_path: Path, orientation: str) -> Path:
    """The cycle goldens' Fanuc parameters (their README) and the grbl machine's orientation handling."""
    path = tmp_path / f"grbl-{orientation}.xml"
    path.write_text("<?xml version='1.0' encoding='UTF-8'?>\n<MachineSetup name=\"golden to grbl\">\n"
                    f"  <Cycles peckRetract=\"0.5\" peckClearance=\"0.3\" orientation=\"{orientation}\"/>\n"
                    "</MachineSetup>\n")
    return path


def _point_mix(diagnostic: dict[str, str]) -> bool:
    """O1004's warning about point-less words beside pointed ones (issue 12 item 3), which it mixes on
    purpose; tests/test_fanuc_writer.py pins its text."""
    return diagnostic["level"] == "warning" and "has no decimal point, so it counts least input" in diagnostic["message"]


def _located(err: str) -> list[dict[str, str]]:
    found = []
    for line in err.splitlines():
        m = LOCATED.match(line)
        assert m, f"not a located diagnostic: {line!r}"
        found.append(m.groupdict())
    return found


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_fanuc_example_to_grbl_verifies_with_zero_deviation(cli: Any, tmp_path: Path, path: Path) -> None:
    """Each ``G43 H<n>`` becomes ``G43.1 Z<length>`` from the set-up's table: long_tools.xml gives tool n
    100 + n mm (in an inch program, that over 25.4), so the length written is known without the code."""
    support = Path(__file__).resolve().parent / "support"
    out = tmp_path / (path.stem + ".gcode")
    result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn", "-o", out,
                 "--machine", support / "long_tools.xml")
    assert result.status == 0, result.err
    warnings = [w for w in _located(result.err) if not _point_mix(w)]
    assert all(w["level"] == "warning" and w["file"] == str(path) for w in warnings)
    source = path.read_text().splitlines()
    for w in warnings:  # only the block delete grbl ignores is refused
        assert source[int(w["line"]) - 1].startswith("/") and "block delete" in w["message"], w
    code = [re.sub(r"\([^)]*\)", "", line).strip() for line in out.read_text().splitlines()]
    for line in code:  # what grbl's parser sees: nothing it rejects
        assert not re.search(r"G8[1-9]|G7[346]|G9[5-9]|G4[1-4]\b(?!\.1)|M0?6\b|M19|%|O\d|[HDQ]\d|^/", line), line
    inch = any(re.search(r"G20\b", line) for line in source)
    registers = [int(m.group(1)) for line in source for m in [re.search(r"G43\b.*?H0*(\d+)", line)] if m]
    written = [float(m.group(1)) for line in code for m in [re.search(r"\bG43\.1 Z(\S+)", line)] if m]
    assert written == pytest.approx([(100 + n) / (25.4 if inch else 1.0) for n in registers], abs=1e-5)
    for machine in ("long_tools.xml", "zero_tools.xml"):
        if machine == "zero_tools.xml":
            result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn",
                         "-o", out, "--machine", support / machine)
            assert result.status == 0, result.err
        verify = cli("verify", path, out, "--from", "fanuc", "--to", "grbl", "--machine", support / machine)
        assert verify.status == 0, verify.out.decode() + verify.err
        assert verify.out.decode().startswith("max deviation 0.0000 mm"), verify.out.decode()
        assert verify.out.decode().splitlines()[0].endswith(": ok")


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_fanuc_example_to_grbl_without_tool_lengths_is_a_located_error(cli: Any, tmp_path: Path, path: Path) -> None:
    """A set-up without the registers' lengths: every G43 is a located error naming the element to add."""
    out = tmp_path / "never.gcode"
    result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "-o", out)
    assert result.status == 1
    assert not out.exists()
    errors = [e for e in _located(result.err) if not _point_mix(e)]
    source = path.read_text().splitlines()
    g43_lines = [n for n, line in enumerate(source, 1) if "G43" in line]
    missing = [e for e in errors if "<Tool number=" in e["message"] and "length=" in e["message"]]
    assert [int(e["line"]) for e in missing] == g43_lines
    assert all(source[int(e["line"]) - 1][int(e["col"]) - 1] == "H" for e in missing)
    assert all(e["level"] == "error" for e in errors)


def test_touched_off_router_drops_the_lengths_with_a_note_and_verifies(cli: Any, tmp_path: Path) -> None:
    path = EXAMPLES[1]
    setup = tmp_path / "router.xml"
    setup.write_text('<MachineSetup name="router">\n  <Machine toolLengths="touched_off"/>\n</MachineSetup>\n')
    out = tmp_path / "out.gcode"
    result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "--machine", setup, "-o", out)
    assert result.status == 0, result.err
    text = out.read_text()
    assert "G43" not in text.replace("TOOL LENGTH", "")
    notes = [line for line in text.splitlines() if "DROPPED: TOOLS ARE TOUCHED OFF" in line]
    assert len(notes) == sum("G43" in line for line in path.read_text().splitlines())
    verify = cli("verify", path, out, "--from", "fanuc", "--to", "grbl", "--machine", setup)
    assert verify.status == 0, verify.out.decode()
    assert "tools are touched off at their change" in verify.out.decode()
    # the same output on a machine with tool lengths is caught: each move runs 100 mm and more too low
    support = Path(__file__).resolve().parent / "support"
    verify = cli("verify", path, out, "--from", "fanuc", "--to", "grbl", "--machine", support / "long_tools.xml")
    assert verify.status == 1 and "exceeds tolerance" in verify.out.decode()


@pytest.mark.parametrize("path", CYCLES, ids=lambda p: p.name)
def test_cycle_golden_to_grbl_verifies_with_zero_deviation(cli: Any, tmp_path: Path, path: Path) -> None:
    setup = _setup(tmp_path, "m19" if path.name in ORIENTING else "error")
    out = tmp_path / (path.stem + ".gcode")
    result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "--machine", setup, "-o", out)
    assert result.status == 0, result.err
    assert result.err == ""
    verify = cli("verify", path, out, "--from", "fanuc", "--to", "grbl", "--machine", setup)
    assert verify.status == 0, verify.out.decode() + verify.err
    assert verify.out.decode().startswith("max deviation 0.0000 mm")


@pytest.mark.parametrize("name", ORIENTING)
def test_orienting_cycles_need_the_setup_to_say_how(cli: Any, tmp_path: Path, name: str) -> None:
    path = ROOT / "tests" / "golden" / "fanuc" / "cycles" / name
    result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "--machine", _setup(tmp_path, "error"))
    assert result.status == 1
    errors = _located(result.err)
    assert errors and all("needs an oriented spindle stop" in e["message"] for e in errors)


@pytest.mark.parametrize("name", ORIENTING)
def test_orientation_by_hand_is_a_pause_that_verify_reports(cli: Any, tmp_path: Path, name: str) -> None:
    """With orientation="stop" the operator orients the spindle during an M0: the motion is the same, and
    verify names the one structural difference (a pause where the source orients)."""
    path = ROOT / "tests" / "golden" / "fanuc" / "cycles" / name
    setup = ROOT / "examples" / "setups" / "grbl-manual-orient.xml"
    out = tmp_path / "out.gcode"
    result = cli("translate", path, "--from", "fanuc", "--to", "grbl", "--machine", setup, "-o", out)
    assert result.status == 0, result.err
    code = [re.sub(r"\([^)]*\)", "", line).strip() for line in out.read_text().splitlines()]
    assert "M0" in code and "M19" not in code
    verify = cli("verify", path, out, "--from", "fanuc", "--to", "grbl", "--machine", _setup(tmp_path, "stop"))
    assert verify.status == 1
    assert "IN has a spindle orientation to 0 deg" in verify.out.decode()


def test_m19_is_a_located_error_or_a_warned_comment(cli: Any, tmp_path: Path) -> None:
    program = tmp_path / "orient.nc"
    program.write_text("G21 G90\nS500 M03\nG00 X10. Y10. Z5.\nM19\nM05\nM30\n")
    result = cli("translate", program, "--from", "fanuc", "--to", "grbl")
    assert result.status == 1
    assert _located(result.err) == [{"file": str(program), "line": "4", "col": "1", "level": "error",
                                     "message": "the grbl dialect cannot express an oriented spindle stop (M19); "
                                                "a set-up with <Cycles orientation=\"stop\"/> pauses for the "
                                                "operator instead"}]
    out = tmp_path / "orient.gcode"
    result = cli("translate", program, "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn", "-o", out)
    assert result.status == 0
    assert [w["line"] for w in _located(result.err)] == ["4"]
    assert "(UNSUPPORTED LINE 4: M19)" in out.read_text().splitlines()
