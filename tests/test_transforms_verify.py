"""``translate --transform`` checked three ways (issue #27 item 3): ``verify`` with the same transform on the
bundled examples and on random programs (hypothesis), and rs274 as the oracle: a random LinuxCNC program
and its transformed translation both run in the real interpreter, the source's moves carried through the
map by hand here must be the translation's moves."""

from __future__ import annotations

import io
import math
import os
import random
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines
from postproc.transforms import parse_transform
from tests.support.rs274 import available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parent.parent
TOUCHED_OFF = ROOT / "examples" / "setups" / "router_tools_touched_off.xml"


def translated(text: str, source: str, target: str, transform: str, **kw: Any) -> str:
    out = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target, transform=transform,
              **kw)
    return out.getvalue()


def verified(text: str, out: str, source: str, target: str, transform: str, **kw: Any) -> Any:
    return verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="t.nc", file_out="o.nc",
                        source=source, target=target, transform=parse_transform(transform), **kw)


# -- the bundled examples --------------------------------------------------------------------------------
@pytest.mark.parametrize("path, source, target, transform", [
    ("fanuc/o1001_plate_drill_tap.nc", "fanuc", "fanuc", "rotate 30 about 10,20"),
    ("fanuc/o1001_plate_drill_tap.nc", "fanuc", "grbl", "mirror x about 60"),
    ("fanuc/o1002_bracket_inch.nc", "fanuc", "linuxcnc", "rotate -90; translate 100,0"),
    ("fanuc/o1004_flange_least_increment.nc", "fanuc", "fanuc", "rotate 30 about 10,20"),
    ("fanuc/o1005_bolt_circle_macro.nc", "fanuc", "linuxcnc", "mirror y; scale 1.5"),
    ("fanuc/o1006_fixture_frames.nc", "fanuc", "fanuc", "rotate 45 about 150,0"),  # its frames evaluated
    ("linuxcnc/cover_profile.ngc", "linuxcnc", "linuxcnc", "translate 5,-3,1"),
    ("linuxcnc/plate_drill_peck.ngc", "linuxcnc", "fanuc", "mirror xy about 50,40"),
    ("isg/prof_contour_xy.nc", "isg", "isg", "rotate 15"),
    ("fagor/bolt_circle_arcs.nc", "fagor", "fanuc", "scale 2 about 0,0,0"),
    # a reference return (G91 G28 Z0.) on an axis the map moves: kept, the tool held at the reference point
    ("fanuc/o1001_plate_drill_tap.nc", "fanuc", "linuxcnc", "translate 5,-3,1"),
    ("fanuc/o1002_bracket_inch.nc", "fanuc", "grbl", "translate 0,0,-2; rotate 90"),
    ("fanuc/o1005_bolt_circle_macro.nc", "fanuc", "fanuc", "translate 0,0,-0.5"),
])
def test_examples_verify_with_the_same_transform(path: str, source: str, target: str, transform: str) -> None:
    setup = load_setup(str(TOUCHED_OFF))
    text = (ROOT / "examples" / path).read_text()
    out = translated(text, source, target, transform, setup=setup, on_unsupported="warn")
    report = verified(text, out, source, target, transform, setup=load_setup(str(TOUCHED_OFF)), allow_ignored=True)
    assert report.ok and report.moves > 10, report.summary()


def test_verify_fails_with_another_transform() -> None:
    """The comparison is not vacuous: the same output against a transform it was not made with."""
    text = (ROOT / "examples" / "fanuc" / "o1003_pocket_and_edge.nc").read_text()
    out = translated(text, "fanuc", "fanuc", "mirror y", setup=load_setup(str(TOUCHED_OFF)))
    assert verified(text, out, "fanuc", "fanuc", "mirror y", setup=load_setup(str(TOUCHED_OFF))).ok
    wrong = verified(text, out, "fanuc", "fanuc", "mirror x", setup=load_setup(str(TOUCHED_OFF)))
    assert not wrong.ok


# -- random programs and transforms -----------------------------------------------------------------------
def _num(r: random.Random, lo: int = -40, hi: int = 40) -> str:
    return f"{r.randint(lo * 4, hi * 4) / 4:g}"


def program(seed: int, dialect: str) -> str:
    """Moves, incremental moves, full circles, incremental quarter-multiple arcs (helices when Z moves),
    R arcs and a drilling or peck cycle with either return level, in millimetres."""
    r = random.Random(seed)
    dot = (lambda s: s if "." in s else s + ".") if dialect == "fanuc" else (lambda s: s)
    lines = ["G21 G17 G90 G94", f"G0 X{dot('0')} Y{dot('0')} Z{dot('10')}"]
    for _ in range(r.randint(5, 12)):
        kind = r.choice(["move", "move", "inc", "circle", "iarc", "rarc", "cycle"])
        if kind == "move":
            lines.append(f"G90 G1 X{dot(_num(r))} Y{dot(_num(r))} Z{dot(_num(r, 0, 10))} F200")
        elif kind == "inc":
            lines += [f"G91 G1 X{dot(_num(r, -10, 10))} Y{dot(_num(r, -10, 10))} F150", "G90"]
        elif kind == "circle":
            i, j = _num(r, -15, 15), _num(r, -15, 15)
            lines.append(f"G90 G{r.choice([2, 3])} I{dot(i if float(i) or float(j) else '5')} J{dot(j)} F100")
        elif kind == "iarc":
            i, j = float(_num(r, -10, 10)), float(_num(r, -10, 10)) or 3.0
            turn = math.radians(r.choice([45, 90, 135, 180, 270]))
            dx = i - math.cos(turn) * i + math.sin(turn) * j
            dy = j - math.sin(turn) * i - math.cos(turn) * j
            lines += [f"G91 G{r.choice([2, 3])} X{dx:.4f} Y{dy:.4f} Z{dot(_num(r, -2, 2))} I{i:.2f} J{j:.2f} F120",
                      "G90"]
        elif kind == "rarc":
            radius = float(_num(r, 3, 20))
            lines += [f"G91 G{r.choice([2, 3])} X{radius:.2f} Y{radius:.2f} R{radius:.2f} F90", "G90"]
        else:
            cycle = r.choice(["G81", "G83"])
            peck = " Q2." if cycle == "G83" else ""
            lines += [f"G90 G0 Z{dot('12')}", f"{r.choice(['G98', 'G99'])} {cycle} X{dot(_num(r))} Y{dot(_num(r))} Z-3. R2.{peck} "
                      "F100", f"X{dot(_num(r))}", "G80", f"G0 Z{dot('10')}"]
    lines.append("M2")
    return "\n".join(lines) + "\n"


def transform(seed: int) -> str:
    """One to three operations in the XY plane (a cycle's drilling axis stays upright)."""
    r = random.Random(seed)
    ops = []
    for _ in range(r.randint(1, 3)):
        kind = r.choice(["translate", "rotate", "mirror", "scale"])
        if kind == "translate":
            ops.append(f"translate {_num(r)},{_num(r)},{_num(r, -5, 5)}")
        elif kind == "rotate":
            ops.append(f"rotate {r.randint(-360, 360) / 2:g} about {_num(r)},{_num(r)}")
        elif kind == "mirror":
            ops.append(f"mirror {r.choice(['x', 'y'])} about {_num(r)}")
        else:
            # a peck cycle's clearance does not scale: a scaled program drills without pecking
            factor = r.choice(['0.5', '1.5', '2', '3'])
            ops.append(f"scale {factor},{factor},1 about {_num(r)},{_num(r)},0")
    return "; ".join(ops)


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 10**6), st.sampled_from([("fanuc", "fanuc"), ("fanuc", "grbl"), ("linuxcnc", "fanuc"),
                                               ("linuxcnc", "linuxcnc")]))
def test_random_programs_verify_with_the_same_transform(seed: int, pair: tuple[str, str]) -> None:
    source, target = pair
    text, how = program(seed, source), transform(seed)
    out = translated(text, source, target, how)
    report = verified(text, out, source, target, how, tolerance=1e-3)
    assert report.ok, f"{how}\n{text}\n---\n{out}\n{report.summary()}"


# -- rs274 as the oracle -------------------------------------------------------------------------------------
SEEDS = range(int(os.environ.get("POSTPROC_TRANSFORM_PROGRAMS", "60")))
BATCH = 20
RESET = "G90 G80 G17 G21 G94 G54 G92.1 G10 L2 P1 X0 Y0 Z0 R0"


def _carried(events: list[dict[str, Any]], how: str) -> list[dict[str, Any]]:
    """rs274's moves of the source carried through the map here: points and centres by ``Affine.point``,
    an arc's direction turned over where the map's XY determinant is negative."""
    fmap = parse_transform(how).map
    m = fmap.m
    turned = m[0] * m[4] - m[1] * m[3] < 0
    out = []
    for e in events:
        e = dict(e)
        e["x"], e["y"], e["z"] = fmap.point((e["x"], e["y"], e["z"]))
        if "cx" in e:
            e["cx"], e["cy"], e["cz"] = fmap.point((e["cx"], e["cy"], e["cz"]))
            if turned:
                e["move"] = {"cw": "ccw", "ccw": "cw"}[e["move"]]
        out.append(e)
    return out


def _segments(calls: list[str], count: int) -> list[list[str]]:
    parts: list[list[str]] = []
    for line in calls:
        if "SEGMENT" in line:
            parts.append([])
        elif parts:
            parts[-1].append(line)
    assert len(parts) == count
    return parts


def _batch(texts: list[str]) -> str:
    body: list[str] = []
    for n, text in enumerate(texts):
        body += [RESET, f"(SEGMENT {n})", *(line for line in text.splitlines() if line.strip() != "M2")]
    return "\n".join(body + ["M2"]) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("batch", range(math.ceil(len(SEEDS) / BATCH)))
def test_rs274_runs_the_transformed_program_as_the_moved_source(batch: int) -> None:
    seeds = list(SEEDS)[batch * BATCH:(batch + 1) * BATCH]
    texts = [program(seed, "linuxcnc") for seed in seeds]
    hows = [transform(seed) for seed in seeds]
    outs = [translated(text, "linuxcnc", "linuxcnc", how) for text, how in zip(texts, hows)]
    sources = _segments(run_rs274(_batch(texts), timeout=120), len(texts))
    results = _segments(run_rs274(_batch(outs), timeout=120), len(texts))
    for seed, how, text, out, theirs, ours in zip(seeds, hows, texts, outs, sources, results):
        want = _carried([e for e in canonical_moves(theirs) if "move" in e], how)
        got = [e for e in canonical_moves(ours) if "move" in e]
        assert len(got) == len(want), f"seed {seed}: {how}\n{text}\n---\n{out}"
        scale = max(abs(v) for v in parse_transform(how).map.m) + 1.0
        for a, b in zip(want, got):
            assert a["move"] == b["move"], f"seed {seed}: {how}\n{a}\n{b}\n{out}"
            for key in ("x", "y", "z", "cx", "cy", "cz"):
                if key in a:
                    assert abs(a[key] - b[key]) <= 5e-4 * scale, f"seed {seed}: {how}: {key}\n{a}\n{b}\n{out}"


def test_the_generators_cover_every_operation() -> None:
    texts = "".join(program(seed, "linuxcnc") for seed in SEEDS)
    hows = " ".join(transform(seed) for seed in SEEDS)
    for word in ("G91 G2", "G91 G3", " R", "G81", "G83", "G98", "G99", "G90 G2 I", "G90 G3 I"):
        assert word in texts, word
    for op in ("translate", "rotate", "mirror x", "mirror y", "scale"):
        assert op in hows, op


# -- the command line --------------------------------------------------------------------------------------
@pytest.mark.parametrize("args, fragment", [
    (["--transform", "rotate 30 about 1"], "argument --transform: --transform 'rotate 30 about 1': '1' should be 2"),
    (["--transform", "G0 X5"], "argument --transform: --transform: unknown operation 'G0' in 'G0 X5'"),
    (["--units", "cm"], "argument --units: invalid choice: 'cm'"),
])
def test_bad_options_are_usage_errors(cli: Any, tmp_path: Path, args: list[str], fragment: str) -> None:
    out = tmp_path / "o.nc"
    result = cli("translate", ROOT / "examples/fanuc/o1003_pocket_and_edge.nc", "--from", "fanuc", "--to", "fanuc",
                 "-o", out, *args)
    assert result.status == 2 and fragment in result.err, result.err
    assert not out.exists()


def test_translate_then_verify_on_the_command_line(cli: Any, tmp_path: Path) -> None:
    source = ROOT / "examples/fanuc/o1003_pocket_and_edge.nc"
    out = tmp_path / "o.ngc"
    how = ["--transform", "mirror y about 40; translate 3,0", "--units", "inch"]
    assert cli("translate", source, "--from", "fanuc", "--to", "linuxcnc", "-o", out, *how).status == 0
    assert "G20" in out.read_text()
    machine = ["--machine", TOUCHED_OFF]
    assert cli("verify", source, out, "--from", "fanuc", "--to", "linuxcnc", *machine, *how).status == 0
    assert cli("verify", source, out, "--from", "fanuc", "--to", "linuxcnc", *machine).status == 1


# -- a reference return under a tool length ------------------------------------------------------------------
HELD_UNDER_LENGTH = """%
O0001
G21 G90 G17 G54
T1 M6
G43 H1 G0 X10. Y5. Z50.
G1 Z-2. F100.
X20.
G91 G28 Z0.
G90 G0 X30. Y10.
M30
%
"""


def test_a_reference_return_under_a_tool_length_is_held_where_the_map_moves_its_axis() -> None:
    """``G91 G28 Z0.`` with H1's length in force, translated with ``translate 0,0,-1``: the return goes to the
    machine's Z reference whatever the map does (the translation keeps ``G91 G28 Z0.``: an incremental 0 is the
    tool's own position, moved with it), and ``X30. Y10.`` after it stays at that Z. By hand, the right output
    is the source with Z50. -> Z49. and Z-2. -> Z-3.; verify held the return's leg only when no length was in
    force (the compensated leg bypassed the marking) and said 1 mm off for it."""
    setup = load_setup(str(ROOT / "benchmarks" / "machine.xml"))
    right = translated(HELD_UNDER_LENGTH, "fanuc", "fanuc", "translate 0,0,-1", setup=setup)
    zs = [word for line in right.splitlines() for word in line.split() if word.startswith("Z")]
    assert zs == ["Z49.", "Z-3.", "Z0."] and "G91 G28 Z0." in right and "X30. Y10." in right
    report = verified(HELD_UNDER_LENGTH, right, "fanuc", "fanuc", "translate 0,0,-1", setup=setup)
    assert report.ok and report.max_deviation == 0.0
    # the return's intermediate point moved 5 mm up, against the way home: a different path, seen
    wrong = right.replace("G91 G28 Z0.", "G91 G28 Z5.")
    assert not verified(HELD_UNDER_LENGTH, wrong, "fanuc", "fanuc", "translate 0,0,-1", setup=setup).ok
