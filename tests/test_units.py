"""``--units mm|inch`` (issue #27 item 3): every length converted by hand (1 in = 25.4 mm exactly), the unit
code written or added in each dialect's spelling, what stays (dwells, inverse-time feeds, repeat counts,
G16 angles), the located refusals, and random programs whose conversion cuts the same path (``verify``)."""

from __future__ import annotations

import io
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.verify import verify_lines


def run(text: str, source: str, target: str, units: str, **kw: Any) -> str:
    out = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target, units=units, **kw)
    return out.getvalue()


def same_path(text: str, out: str, source: str, target: str) -> None:
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="t.nc",
                          file_out="o.nc", source=source, target=target, tolerance=1e-4)
    assert report.ok, report.summary()


INCH = """G20 G17 G90 G94
G10 L2 P1 X1. Y2. Z0.
G10 L10 P3 R5.
G10 L12 P3 R0.25
G00 X0. Y0. Z1. S1000 M03
G01 Z-0.1 F10.
G02 X1. Y0. I0.5 J0.
G03 X0. Y0. R0.5
G91 G01 X0.5 Y-0.25
G90 G04 P500
G99 G82 X1. Y1. Z-0.5 R0.1 P250 F5.
G98 G83 X2. Y1. Z-0.5 R0.1 Q0.2 F5.
G80
G95 G01 X0. F0.004
G94
M30
"""


def test_inch_to_mm_by_hand() -> None:
    """Each length times 25.4: work offset and tool data (G10), absolute and incremental moves, arc
    centre and radius, feeds per minute and per revolution, cycle R, Z, Q and positions; the dwells (G4
    P500, the G82 P250 milliseconds) stay."""
    out = run(INCH, "fanuc", "fanuc", "mm")
    for line in ("G17 G21 G90 G94", "G10 L2 P1 X25.4 Y50.8 Z0.", "G10 L10 P3 R127.", "G10 L12 P3 R6.35",
                 "G00 X0. Y0. Z25.4 S1000 M03", "G01 Z-2.54 F254.", "G02 X25.4 Y0. I12.7 J0.", "G03 X0. Y0. R12.7",
                 "G91 G01 X12.7 Y-6.35", "G90 G04 P500", "G99 G82 X25.4 Y25.4 Z-12.7 R2.54 P250 F127.",
                 "G98 G83 X50.8 Y25.4 Z-12.7 R2.54 Q5.08 F127.", "G95 G01 X0. F0.1016"):
        assert line in out.splitlines(), line
    assert "G20" not in out
    same_path(INCH, out, "fanuc", "fanuc")


def test_a_program_without_units_gets_them() -> None:
    """Millimetres (the reading default) to inches: G20 before the first block that does anything."""
    text = "%\nO0001 (PART)\nG0 X25.4 Y-12.7\nG1 X50.8 F254.\nM30\n%\n"
    out = run(text, "fanuc", "fanuc", "inch")
    assert out.splitlines()[:5] == ["%", "O0001 (PART)", "G20", "G00 X1. Y-0.5", "G01 X2. F10."]
    same_path(text, out, "fanuc", "fanuc")


def test_each_dialect_spells_its_own_unit_code() -> None:
    """ISG's inch code is G70 ([K] DIALECTS.md: G70/G71), LinuxCNC's G20."""
    assert run("G71\nG01 X25.4 Y0 F254\nM30\n", "isg", "isg", "inch").splitlines()[:2] == ["G70", "G01 X1. Y0. F10."]
    out = run("G1 X25.4 F254.\nM2\n", "linuxcnc", "linuxcnc", "inch")
    assert out.splitlines()[:2] == ["G20", "G1 X1. F10."]


def test_a_unit_change_inside_the_program() -> None:
    """An inch part and a millimetre part both end in inches: only the mm values change."""
    text = "G20 G90 G0 X1. Y1.\nG21 G0 X50.8 Y0.\nG1 X25.4 F254.\nM30\n"
    out = run(text, "fanuc", "fanuc", "inch")
    assert out.splitlines()[:3] == ["G20 G90 G0 X1. Y1.", "G20 G00 X2. Y0.", "G01 X1. F10."]  # the first copied as written
    same_path(text, out, "fanuc", "fanuc")


def test_blending_tolerance_and_inverse_time() -> None:
    """G64 P is a length (converted); a G93 feed is 1/minutes (kept)."""
    text = "G21 G90 G64 P0.254\nG93 G01 X25.4 F2.\nG94 G01 X0 F254\nM2\n"
    out = run(text, "linuxcnc", "linuxcnc", "inch")
    assert out.splitlines()[:3] == ["G64 P0.01 G20 G90", "G93 G1 X1. F2.", "G94 G1 X0. F10."]


def test_polar_angles_stay() -> None:
    """Under G16 the second axis word is an angle: X (the radius) converts, Y (degrees) does not."""
    text = "G21 G17 G90 G00 X0. Y0. Z5.\nG16\nG01 X25.4 Y45. F100.\nG15\nM30\n"
    out = run(text, "fanuc", "fanuc", "inch")
    assert "G01 X1. Y45. F3.93700787" in out
    same_path(text, out, "fanuc", "fanuc")


def test_a_macro_program_is_flattened_where_it_can_be() -> None:
    text = "G21 G90 G00 X0. Y0. Z1.\n#1=25.4\nG01 X#1 F100.\nM30\n"
    out = run(text, "fanuc", "linuxcnc", "inch")
    assert "G1 X1. F3.93700787" in out and "#" not in out
    same_path(text, out, "fanuc", "linuxcnc")


@pytest.mark.parametrize("text, source, message", [
    ("G21 G90 G00 X0. Y0. Z1.\n#1=#5221\nG01 X[#1+1.] F100.\nM30\n", "fanuc",
     "t.nc:2:1: error: #5221 (work offset) is known only to the machine"),
])
def test_refused_at_the_line(text: str, source: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        run(text, source, source, "inch")
    assert any(str(e).startswith(message) for e in info.value.errors), info.value.errors


def test_a_dynamic_tool_length_is_converted() -> None:
    """LinuxCNC's G43.1 is the neutral dynamic offset (it was kept as written and refused here): 2.54 mm is
    0.1 in (hand-derived), and the path is the source's."""
    text = "G21 G90\nG0 X0 Y0 Z5.08\nG43.1 Z2.54\nG1 Z0 F100\nM2\n"
    out = run(text, "linuxcnc", "linuxcnc", "inch")
    assert "G43.1 Z0.1" in out.splitlines(), out
    same_path(text, out, "linuxcnc", "linuxcnc")


def test_a_lathe_program_is_converted() -> None:
    """X20 (a diameter) is 0.7874 in, Z1 0.0394 in (more in tests/test_frames_lathe_units.py)."""
    text = "G21 G0 X20. Z1.\nM30\n"
    out = run(text, "gsk", "gsk", "inch")
    assert "G20" in out and "X0.787401" in out and "Z0.03937" in out, out
    same_path(text, out, "gsk", "gsk")


# -- random programs ----------------------------------------------------------------------------------
_value = st.integers(-2000, 2000).map(lambda n: n / 40.0)


@st.composite
def programs(draw: st.DrawFn) -> str:
    """Straight moves and quarter arcs in either unit, absolute and incremental, feeds per minute."""
    lines = [draw(st.sampled_from(["G20", "G21", ""])) + " G17 G90 G94 G00 X0. Y0. Z1."]
    for _ in range(draw(st.integers(1, 12))):
        kind = draw(st.sampled_from(["move", "move", "arc", "units", "distance"]))
        if kind == "units":
            lines.append(draw(st.sampled_from(["G20", "G21"])))
        elif kind == "distance":
            lines.append(draw(st.sampled_from(["G90", "G91"])))
        elif kind == "move":
            lines.append(f"G01 X{draw(_value)} Y{draw(_value)} Z{draw(_value)} F{draw(st.integers(1, 500))}.")
        else:
            r = draw(st.integers(1, 200)) / 20.0
            lines.append(f"G91 G0{draw(st.sampled_from('23'))} X{r} Y{r} I{r} J0. F50.\nG90")
    lines.append("M30")
    return "\n".join(lines) + "\n"


@settings(max_examples=40, deadline=None)
@given(programs(), st.sampled_from(["mm", "inch"]), st.sampled_from(["fanuc", "linuxcnc", "grbl"]))
def test_random_programs_cut_the_same_path(text: str, units: str, target: str) -> None:
    out = run(text, "fanuc", target, units)
    same_path(text, out, "fanuc", target)


def test_a_program_in_the_units_asked_for_is_written_as_it_was() -> None:
    text = "%\nO0002\nG21 G90 G17\nG0 X0 Y0 Z10.\nG99 G81 X10. Y5. Z-3. R2. F100.\nX20.\nG80\nM30\n%\n"
    assert run(text, "fanuc", "fanuc", "mm") == text


# -- rs274 as the oracle ------------------------------------------------------------------------------
@pytest.mark.skipif(not __import__("tests.support.rs274", fromlist=["available"]).available(),
                    reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_converted_program_along_the_same_path() -> None:
    """Random LinuxCNC programs (moves, incremental moves, full circles, helices, R arcs, drilling and peck
    cycles) and their inch conversions run in rs274: the same moves in mm, within rs274's printed places
    (4 decimals of an inch: 1.3e-3 mm)."""
    from tests.support.rs274 import canonical_moves, run_rs274
    from tests.test_transforms_verify import _batch, _segments, program
    texts = [program(seed, "linuxcnc") for seed in range(20)]
    outs = [run(text, "linuxcnc", "linuxcnc", "inch") for text in texts]
    assert all("G20" in out for out in outs)
    sources = _segments(run_rs274(_batch(texts), timeout=120), len(texts))
    results = _segments(run_rs274(_batch(outs), timeout=120), len(texts))
    for text, out, theirs, ours in zip(texts, outs, sources, results):
        want = [e for e in canonical_moves(theirs) if "move" in e]
        got = [e for e in canonical_moves(ours) if "move" in e]
        assert len(got) == len(want), f"{text}\n---\n{out}"
        for a, b in zip(want, got):
            assert a["move"] == b["move"]
            for key in ("x", "y", "z", "cx", "cy", "cz"):
                if key in a:
                    assert abs(a[key] - b[key]) <= 1.5e-3, f"{key}\n{a}\n{b}\n{text}\n---\n{out}"


def test_a_macro_program_already_in_the_units_asked_for_stays_symbolic() -> None:
    text = "G21 G90 G00 X0. Y0. Z1.\n#1=25.4\nG01 X#1 F100.\nM30\n"
    assert run(text, "fanuc", "fanuc", "mm") == text
    assert "#1" in run(text, "fanuc", "linuxcnc", "mm")
