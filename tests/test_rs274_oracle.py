"""The LinuxCNC interpreter as a test oracle: the canonical-call parser against the shared conformance
data, and (when ``rs274`` is installed) the live interpreter against the same data."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))  # tests/ has no __init__.py
from support import rs274  # noqa: E402
from support.rs274 import canonical_moves, motions  # noqa: E402

SHARED = Path(os.environ.get("POSTPROC_SHARED") or Path(__file__).resolve().parents[2] / "shared")
CASES_DIR = SHARED / "conformance" / "linuxcnc"
CASES = sorted(p for p in CASES_DIR.glob("*") if (p / "expected").is_file()) if CASES_DIR.is_dir() else []
NO_SHARED = f"shared conformance data not found at {CASES_DIR} (set POSTPROC_SHARED)"
NO_RS274 = "LinuxCNC interpreter rs274 not installed (apt-get install linuxcnc-uspace, or .ci/install-oracle.sh)"
TOL_MM = 1e-4

_TSV_UNITS = {"INCH": 25.4, "MM": 1.0}
_TSV_PLANE = {"XY": "XY", "XZ": "ZX", "YZ": "YZ"}


def tsv_motions(path: Path) -> list[dict]:
    """Motion rows of a ``moves.tsv`` (program units, see shared/tools/canon2moves.py) in mm."""
    scale, rows = 1.0, []
    for line in path.read_text().splitlines():
        f = line.split("\t")
        kind = f[0]
        if kind == "units":
            scale = _TSV_UNITS[f[1]]
        elif kind in ("rapid", "feed", "sync", "arc"):
            row = {"move": {"sync": "feed", "arc": None}.get(kind, kind),
                   "x": float(f[1]) * scale, "y": float(f[2]) * scale, "z": float(f[3]) * scale}
            if kind == "arc":
                row["plane"] = _TSV_PLANE[f[4]]
                row["move"] = "cw" if f[5] == "CW" else "ccw"
                for key, text in zip(("cx", "cy", "cz"), f[6:9]):
                    if text != "":
                        row[key] = float(text) * scale
            rows.append(row)
    return rows


def diff_motions(expected: list[dict], actual: list[dict], tol: float = TOL_MM) -> list[str]:
    out = []
    if len(expected) != len(actual):
        out.append(f"move count: expected {len(expected)}, got {len(actual)}")
    for i, (e, a) in enumerate(zip(expected, actual)):
        if e["move"] != a["move"]:
            out.append(f"#{i} kind: expected {e['move']}, got {a['move']}")
        if "plane" in e and e["plane"] != a.get("plane"):
            out.append(f"#{i} plane: expected {e['plane']}, got {a.get('plane')}")
        for k in ("x", "y", "z", "cx", "cy", "cz"):
            if k in e and (k not in a or abs(e[k] - a[k]) > tol):
                out.append(f"#{i} {k}: expected {e[k]:.4f}, got {a.get(k)}")
        if len(out) > 20:
            out.append("...")
            break
    return out


# -- (a) the parser against the conformance data (no interpreter needed) ---------------------------------

@pytest.mark.parametrize("case", CASES or [None], ids=[p.name for p in CASES] or ["no-shared-data"])
def test_parse_expected_matches_moves_tsv(case):
    if case is None:
        pytest.skip(NO_SHARED)
    events = canonical_moves((case / "expected").read_text().splitlines())
    expected = tsv_motions(case / "moves.tsv")
    assert expected, f"{case.name}: moves.tsv has no motion rows"
    problems = diff_motions(expected, motions(events))
    assert not problems, f"{case.name}:\n" + "\n".join(problems)


def test_parse_units_planes_arcs_and_events():
    lines = """\
 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)
 N..... STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)
 N..... STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)
 N..... SELECT_PLANE(CANON_PLANE_XZ)
 N..... ARC_FEED(3.0000, 2.0000, 3.0000, 1.5000, -1, 2.0000, 0.0000, 0.0000, 0.0000)
 N..... SELECT_PLANE(CANON_PLANE_YZ)
 N..... ARC_FEED(2.0000, 3.0000, 2.0000, 2.5000, 2, 2.0000, 0.0000, 0.0000, 0.0000)
 N..... DWELL(0.5000)
 N..... START_SPINDLE_COUNTERCLOCKWISE(0)
 N..... ORIENT_SPINDLE(0, 90.0000, 0)
 N..... FLOOD_ON()
 N..... MIST_ON()
 N..... MIST_OFF()
 N..... FLOOD_OFF()
 N..... PROGRAM_STOP()
 N..... OPTIONAL_PROGRAM_STOP()
 N..... STOP_SPINDLE_TURNING(0)
 N..... PROGRAM_END()
X SUB O1 PARAM1 = 1.000000
"""
    ev = canonical_moves(lines)
    assert ev[0] == {"move": "rapid", "x": 25.4, "y": 50.8, "z": 76.2}  # second traverse: zero length
    # G18 arcs print (Z, X) first; the centre's Y (normal axis) is the start value
    assert ev[1] == {"move": "cw", "x": 50.8, "y": 50.8, "z": 76.2,
                     "cx": 38.1, "cy": 50.8, "cz": 76.2, "plane": "ZX"}
    assert ev[2] == {"move": "ccw", "x": 50.8, "y": 50.8, "z": 76.2,
                     "cx": 50.8, "cy": 50.8, "cz": 63.5, "plane": "YZ", "turns": 2}
    assert ev[3:] == [
        {"event": "dwell", "seconds": 0.5},
        {"event": "spindle", "dir": "ccw"},
        {"event": "orient", "angle": 90.0},
        {"event": "coolant", "on": True},
        {"event": "coolant", "on": False},
        {"event": "stop", "optional": False},
        {"event": "stop", "optional": True},
        {"event": "spindle", "dir": "stop"},
        {"event": "end"},
    ]


def test_parse_accepts_raw_rs274_output_with_line_counters():
    raw = ["    11 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)",
           "    12 N..... STRAIGHT_FEED(0.0000, 0.0000, -1.0000, 0.0000, 0.0000, 0.0000)"]
    assert canonical_moves(raw) == [{"move": "rapid", "x": 0.0, "y": 0.0, "z": 2.0},
                                    {"move": "feed", "x": 0.0, "y": 0.0, "z": -1.0}]


# -- (b) the live interpreter ----------------------------------------------------------------------------

needs_rs274 = pytest.mark.skipif(not rs274.available(), reason=NO_RS274)


def test_rs274_reproduces_g81_g17_g98():
    if not rs274.available():
        pytest.skip(NO_RS274)
    case = CASES_DIR / "g81-g17-g98"
    if not case.is_dir():
        pytest.skip(NO_SHARED)
    programs = sorted(case.glob("*.ngc"))
    assert programs
    expected = canonical_moves((case / "expected").read_text().splitlines())
    for prog in programs:
        calls = rs274.run_rs274(prog.read_text())
        assert canonical_moves(calls) == expected, prog.name


@needs_rs274
def test_rs274_error_is_reported_with_interpreter_text():
    with pytest.raises(rs274.RS274Error) as info:
        rs274.run_rs274("G21 G90 F100\nG0 X0 Y0 Z10\nG81 X1 Y1 Z1 R0\nM2\n")
    assert "R less than z" in str(info.value)
    assert "G81 X1 Y1 Z1 R0" in str(info.value)


@needs_rs274
def test_rs274_inch_program_comes_out_in_mm_and_g83_clearance():
    # Pins the packaged version's G83 behaviour documented in support/RS274_NOTES.md.
    calls = rs274.run_rs274("G20 G17 G90 G99 F10\nG0 X0 Y0 Z1\nG83 X1 Y1 Z-0.25 R0.2 Q0.1\nG80\nM2\n")
    z = [round(m["z"] / 25.4, 4) for m in motions(canonical_moves(calls)) if m["x"] == 25.4]
    assert z == [1.0, 0.2, 0.1, 0.2, 0.11, 0.0, 0.2, 0.01, -0.1, 0.2, -0.09, -0.2, 0.2, -0.19, -0.25, 0.2]


@needs_rs274
def test_rs274_runs_in_a_home_of_its_own(tmp_path, monkeypatch):
    """rs274 maps its tool table at ``$HOME/.tool.mmap``; runs sharing a HOME corrupt each other
    (bus errors, wrong Z, "tool not found"), so every run must leave the caller's HOME alone."""
    monkeypatch.setenv("HOME", str(tmp_path))
    rs274.run_rs274("G21 G90\nT1 M6\nG43\nG0 X1\nM2\n")
    assert list(tmp_path.iterdir()) == []


@needs_rs274
def test_rs274_parallel_runs_keep_their_own_tool_tables():
    """Eight runs at once, each with its own tool table, each sees its own tool length."""
    from concurrent.futures import ThreadPoolExecutor

    def length(n: int) -> str:
        calls = rs274.run_rs274("G20 G90\nT1 M6\nG43 H1\nG0 X1\nM2\n", tool_table=f"T1 P1 Z{n} D0.1\n")
        return next(c for c in calls if "USE_TOOL_LENGTH_OFFSET" in c)

    with ThreadPoolExecutor(8) as pool:
        seen = list(pool.map(length, range(1, 33)))
    assert all(f"{n}.0000" in text for n, text in zip(range(1, 33), seen)), seen
