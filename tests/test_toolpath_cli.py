"""`postproc toolpath`: formats, exit statuses and located messages (the stable command line)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable

PROGRAM = """%
O0001
G21 G17 G90
G00 X10. Y0. Z5.
G01 Z-1. F100.
G03 X0. Y10. I-10. J0.
G00 Z5.
M30
%
"""


def write(tmp_path: Path, text: str, name: str = "p.nc") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_jsonl_to_stdout(cli: Callable[..., Any], tmp_path: Path) -> None:
    r = cli("toolpath", write(tmp_path, PROGRAM), "--dialect", "fanuc")
    assert r.status == 0, r.err
    lines = r.out.decode().splitlines()
    assert lines[0] == '{"toolpath": 1, "units": "mm", "dialect": "fanuc"}'
    assert lines[1] == '{"line": 4, "move": "rapid", "x": 10, "y": 0, "z": 5}'
    assert json.loads(lines[3]) == {"line": 6, "move": "ccw", "x": 0, "y": 10, "z": -1, "cx": 0, "cy": 0,
                                    "cz": -1, "plane": "XY", "f": 100}
    assert lines[-1] == '{"line": 8, "event": "end"}'
    assert r.err == ""


def test_jsonl_to_a_file(cli: Callable[..., Any], tmp_path: Path) -> None:
    out = tmp_path / "p.jsonl"
    r = cli("toolpath", write(tmp_path, PROGRAM), "--dialect", "fanuc", "--format", "jsonl", "-o", out)
    assert r.status == 0 and r.out == b""
    assert len(out.read_text().splitlines()) == 6


def test_errors_are_located_exit_1_and_leave_no_output(cli: Callable[..., Any], tmp_path: Path) -> None:
    src = write(tmp_path, "G21 G90\nG00 X1.\nN30 G31 X1.\nG02 X10. Y0. R1. F100.\n")
    out = tmp_path / "bad.jsonl"
    r = cli("toolpath", src, "--dialect", "fanuc", "-o", out)
    assert r.status == 1
    assert r.err_lines == [
        f"{src}:3:5: error: G31 (skip function) cannot be simulated",
        f"{src}:4:14: error: arc radius 1.0000 mm is too small for a chord of 9.0000 mm",
    ]
    assert not out.exists()


def test_svg_and_png(cli: Callable[..., Any], tmp_path: Path) -> None:
    src = write(tmp_path, PROGRAM)
    svg, png = tmp_path / "p.svg", tmp_path / "p.png"
    assert cli("toolpath", src, "--dialect", "fanuc", "--format", "svg", "-o", svg).status == 0
    assert svg.read_text().startswith("<?xml")
    assert cli("toolpath", src, "--dialect", "fanuc", "--format", "png", "-o", png).status == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_svg_to_stdout(cli: Callable[..., Any], tmp_path: Path) -> None:
    r = cli("toolpath", write(tmp_path, PROGRAM), "--dialect", "fanuc", "--format", "svg")
    assert r.status == 0 and r.out.rstrip().endswith(b"</svg>")


def test_usage_errors_exit_2(cli: Callable[..., Any], tmp_path: Path) -> None:
    src = write(tmp_path, PROGRAM)
    assert cli("toolpath", src, "--dialect", "fanuc", "--format", "png").status == 2  # png needs -o
    assert cli("toolpath", src, "--dialect", "nosuch").status == 2
    assert cli("toolpath", tmp_path / "missing.nc", "--dialect", "fanuc").status == 2
    assert cli("toolpath", src, "--dialect", "fanuc", "--format", "gif").status == 2
