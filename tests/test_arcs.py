"""``translate --arcs`` and ``verify --arcs``: hand-derived rewrites, chord geometry as a property, located
refusals. The LinuxCNC interpreter's view of the same rewrites is in ``test_arcs_rs274.py``."""

from __future__ import annotations

import io
import math
import re

import pytest
from hypothesis import given, settings, strategies as st

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.lowering.arc_geometry import Arc, chord_count, chord_points, r_centre_error, signed_radius, split
from postproc.lowering.arcs import ArcOption, parse_arc_option
from postproc.simulate.verify import verify_lines


def _translate(text: str, arcs: str, source: str = "linuxcnc", target: str = "linuxcnc") -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.ngc", source=source, target=target, arcs=parse_arc_option(arcs))
    return out.getvalue()


MOVE = re.compile(r"(G[0-3]|[XYZ][-.\d])")
ARC = re.compile(r"\bG0?[23]\b")


def _moves(text: str) -> list[str]:
    """The lines that start with a move (G0-G3, or an axis word under a modal one)."""
    return [line for line in text.splitlines() if MOVE.match(line) and not line.startswith(("G17", "G18", "G19", "G2"
                                                                                            "0", "G21"))]


# -- the option ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("text, expected", [
    ("lines:0.01", ArcOption("lines", 0.01)), ("LINES:0.5", ArcOption("lines", 0.5)),
    ("ijk", ArcOption("ijk")), ("r", ArcOption("r")),
])
def test_the_option_reads(text: str, expected: ArcOption) -> None:
    assert parse_arc_option(text) == expected


@pytest.mark.parametrize("args, fragment", [
    (["--arcs", "lines"], "chord tolerance"), (["--arcs", "lines:0"], "at least 0.0001"),
    (["--arcs", "lines:nan"], "finite"), (["--arcs", "ijk:1"], "lines:TOL, ijk or r"),
    (["--arcs", "spline"], "lines:TOL, ijk or r"),
])
def test_wrong_arcs_option_is_usage(cli, tmp_path, args, fragment) -> None:
    program = tmp_path / "a.ngc"
    program.write_text("G0 X0\nM2\n")
    result = cli("translate", program, "--from", "linuxcnc", "--to", "grbl", *args)
    assert result.status == 2 and fragment in result.err


def test_arcs_reaches_every_file_of_a_batch(cli, tmp_path) -> None:
    """A batch rewrites each file's arcs as the single-file command does (``tests/test_batch.py`` verifies a
    batch with --arcs lines against its sources)."""
    for name in ("a.ngc", "b.ngc"):
        (tmp_path / name).write_text("G0 X0 Y0\nG2 X10 Y0 R5 F100\nM2\n")
    result = cli("translate", tmp_path / "a.ngc", tmp_path / "b.ngc", "-o", tmp_path / "out", "--from", "linuxcnc",
                 "--to", "grbl", "--arcs", "ijk")
    assert result.status == 0, result.err
    for name in ("a.ngc", "b.ngc"):
        assert "G2 X10. Y0. I5. J0. F100." in (tmp_path / "out" / name).read_text().splitlines()


# -- geometry, by hand --------------------------------------------------------------------------------

def test_chord_count_of_a_quarter_circle() -> None:
    # r = 10, tol = 0.01: a chord may span 2 acos(1 - 0.001) = 0.089450 rad; pi/2 / 0.089450 = 17.56 -> 18
    arc = Arc((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), False, {})
    assert chord_count(arc, 0.01) == 18


def test_semicircle_in_two_chords() -> None:
    # r = 5: two chords of 90 degrees lie 5 (1 - cos 45) = 1.4645 inside; one would lie 5 inside
    arc = Arc((0.0, 0.0), (10.0, 0.0), (5.0, 0.0), True, {"Z": (0.0, -2.0)})
    points = list(chord_points(arc, 1.5, 1e-6))
    assert points == [((5.0, 5.0), {"Z": -1.0}), ((10.0, 0.0), {"Z": -2.0})]


def test_signed_radius_is_negative_over_half_a_turn() -> None:
    quarter = Arc((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), False, {})
    three_quarters = Arc((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), True, {})
    assert signed_radius(quarter) == 10.0 and signed_radius(three_quarters) == -10.0


def test_r_cannot_place_a_full_circle_or_a_semicircle() -> None:
    full = Arc((0.0, 0.0), (0.0, 0.0), (5.0, 0.0), True, {})
    half = Arc((0.0, 0.0), (10.0, 0.0), (5.0, 0.0), True, {})
    assert r_centre_error(full, 1e-6) == math.inf
    # R written 1e-6 long: the centre moves sqrt(5^2 - ... ) = sqrt(2 * 5 * 1e-6) off the chord = 0.0032
    assert r_centre_error(half, 1e-6) == pytest.approx(math.sqrt((5 + 1e-6) ** 2 - 25), rel=1e-6)
    # a 120 degree piece: the centre moves at most R / d = 2 times the slack
    assert r_centre_error(split(full, 3, 1e-6)[0], 1e-6) < 3e-6


# -- hypothesis: random arcs --------------------------------------------------------------------------

@st.composite
def arcs(draw: st.DrawFn) -> tuple[Arc, float]:
    cx, cy = draw(st.floats(-500, 500)), draw(st.floats(-500, 500))
    r = draw(st.floats(0.05, 2000))
    a0 = draw(st.floats(-math.pi, math.pi))
    sweep = draw(st.floats(0.001, 2 * math.pi))
    clockwise = draw(st.booleans())
    full = draw(st.booleans()) and sweep > 6
    a1 = a0 if full else a0 + (-sweep if clockwise else sweep)
    start = (round(cx + r * math.cos(a0), 6), round(cy + r * math.sin(a0), 6))
    end = start if full else (round(cx + r * math.cos(a1), 6), round(cy + r * math.sin(a1), 6))
    helix = {"Z": (0.0, draw(st.floats(-50, 50)))} if draw(st.booleans()) else {}
    tolerance = draw(st.floats(0.0001, 1.0))
    return Arc(start, end, (cx, cy), clockwise, helix), tolerance


@settings(max_examples=150, deadline=None)
@given(arcs())
def test_every_chord_lies_within_the_tolerance_and_ends_exactly(case: tuple[Arc, float]) -> None:
    arc, tolerance = case
    try:
        points = list(chord_points(arc, tolerance, 1e-6))
    except ValueError:
        assert chord_count.__doc__  # too many chords: refused (checked in the count below)
        r = max(arc.radii)
        assert arc.sweep / (2 * math.acos(1 - tolerance / r)) > 100_000
        return
    c, (r0, r1) = arc.centre, arc.radii
    sweep = arc.sweep
    assert points[-1] == (arc.end, {a: e for a, (_, e) in arc.along.items()})  # exactly the end
    previous, swept = arc.start, 0.0
    turn = -1 if arc.clockwise else 1
    for k, ((x, y), others) in enumerate(points, 1):
        step = (turn * (math.atan2(y - c[1], x - c[0]) - math.atan2(previous[1] - c[1], previous[0] - c[0]))) \
            % (2 * math.pi)
        swept += step if step > 1e-12 else 2 * math.pi  # a full circle's last chord closes the turn
        t = swept / sweep
        radius = r0 + (r1 - r0) * t
        assert abs(math.hypot(x - c[0], y - c[1]) - radius) <= 2e-6  # on the arc (rounded to 1e-6)
        mx, my = (previous[0] + x) / 2, (previous[1] + y) / 2
        assert radius - math.hypot(mx - c[0], my - c[1]) <= tolerance + 2e-6  # the chord's middle
        for axis, (s, e) in arc.along.items():  # the angle read back from rounded points: 2e-6 / r off
            assert others[axis] == pytest.approx(s + (e - s) * t, abs=2e-6 + 4 * abs(e - s) * 2e-6 / r0 / sweep)
        previous = (x, y)
    assert swept == pytest.approx(sweep, abs=1e-6)
    n = len(points)  # the fewest: one chord fewer would leave the tolerance
    if n > 1:  # (no chord spans over half a turn)
        assert sweep / (n - 1) > math.pi or max(r0, r1) * (1 - math.cos(sweep / (2 * (n - 1)))) > tolerance


# -- translations, by hand ------------------------------------------------------------------------------

SEMICIRCLE = "G21 G90 G17 F100\nG0 X0 Y0 Z1\nG2 X10 Y0 Z-1 R5\nM2\n"


def test_lines_of_a_helical_semicircle() -> None:
    # centre (5, 0); 1.5 mm allows two chords (1.4645 inside), Z halfway at the middle point
    assert _moves(_translate(SEMICIRCLE, "lines:1.5")) == ["G0 X0 Y0 Z1", "G1 X5. Y5. Z0.", "G1 X10. Y0. Z-1."]


def test_ijk_of_an_r_arc_and_r_of_an_ijk_arc() -> None:
    ijk = _translate("G21 G90 G17 F100\nG0 X0 Y0\nG3 X10 Y10 R10\nG2 X20 Y0 R-10\nM2\n", "ijk")
    # ccw quarter from (0,0) to (10,10), R10: centre on the left of the chord, (0, 10); the cw one, R-10
    # (the long way) from (10,10) to (20,0): centre on the right of the chord, (20, 10): 270 degrees
    assert _moves(ijk)[1:] == ["G3 X10. Y10. I0. J10.", "G2 X20. Y0. I10. J0."]
    r = _translate("G21 G90 G17 F100\nG0 X0 Y0\nG3 X10 Y10 I0 J10\nG2 X20 Y0 I10 J0\nM2\n", "r")
    assert _moves(r)[1:] == ["G3 X10. Y10. R10.", "G2 X20. Y0. R-10."]


def test_r_splits_a_full_circle_in_three() -> None:
    # start (0,0), centre (5,0), clockwise: 120 degrees on, at angles 60 and -60 about the centre
    r = _translate("G21 G90 G17 F100\nG0 X0 Y0\nG2 I5 J0\nM2\n", "r")
    assert _moves(r)[1:] == ["G2 X7.5 Y4.330127 R5.", "G2 X7.5 Y-4.330127 R5.", "G2 X0. Y0. R5."]


def test_other_planes() -> None:
    # G18 (ZX): Z is the first axis, X the second; Z0 X10 is at 90 degrees about the origin, ccw turns
    # towards Z-10 X0 (180). tol 1: two chords of 45 degrees (10 (1 - cos 22.5) = 0.761; one: 2.93)
    zx = _translate("G21 G90 G18 F100\nG0 X10 Y0 Z0\nG3 X0 Z-10 I-10 K0\nM2\n", "lines:1")
    assert _moves(zx)[1:] == ["G1 X7.071068 Z-7.071068", "G1 X0. Z-10."]
    # G19 (YZ): Y the first axis; a cw half turn from Y0 Z0 to Y0 Z10 about (0, 5) passes Y5 Z5... -Y side
    yz = _translate("G21 G90 G19 F100\nG0 X0 Y0 Z0\nG2 Y0 Z10 J0 K5\nM2\n", "lines:5")
    # cw in YZ from angle -90 (Y0 Z0 seen about Y0 Z5) turns towards -Y: the middle point is Y-5 Z5
    assert _moves(yz)[1:] == ["G1 Y-5. Z5.", "G1 Y0. Z10."]


def test_incremental_chords_sum_to_the_programmed_move() -> None:
    out = _translate("G21 G91 G17 F100\nG2 X10 Y0 I5 J0\nM2\n", "lines:0.01")
    total = [0.0, 0.0]
    for line in _moves(out):
        for word in line.split()[1:]:
            total["XY".index(word[0])] += float(word[1:])
    assert total == pytest.approx([10.0, 0.0], abs=1e-12)
    assert all(line.startswith("G1") for line in _moves(out))


def test_inch_program_takes_the_tolerance_in_mm() -> None:
    # r = 1 inch = 25.4 mm, tolerance 3 mm: cos(a/2) >= 1 - 3/25.4, a <= 0.9676 rad: a semicircle in 4
    out = _translate("G20 G90 G17 F10\nG0 X0 Y0\nG2 X2 Y0 I1 J0\nM2\n", "lines:3")
    assert len(_moves(out)) == 1 + 4


def test_the_arc_block_keeps_its_words_before_and_after_the_motion() -> None:
    out = _translate("G21 G90 G17\nG0 X0 Y0\nN5 F200 M3 S1000 G2 X10 Y0 R5 M9 M0\nM2\n", "lines:1.5")
    lines = out.splitlines()
    first = next(k for k, line in enumerate(lines) if "X5." in line)
    # M9 acts before the motion on LinuxCNC (the RS274/NGC order of execution), M0 after it
    assert "F200" in lines[first] and "M3" in lines[first] and "M9" in lines[first] and "M0" not in lines[first]
    assert "M0" in lines[first + 1] and "X10." in lines[first + 1]


def test_a_modal_arc_after_lines_gets_its_g_code_back() -> None:
    out = _translate("G21 G90 G17 F100\nG0 X0 Y0\nG2 X10 Y0 R5\nX20 R5\nM2\n", "r")
    assert _moves(out)[-1] == "X20 R5"  # nothing changed: the modal G2 stands
    out = _translate("G21 G90 G17 F100\nG0 X0 Y0\nG2 X10 Y0 R5\nX20 Y0 R5\nG1 X30\nX40\nM2\n", "lines:1.5")
    assert _moves(out)[-2:] == ["G1 X30.", "X40"]


def test_verify_accepts_the_chords_and_refuses_them_without_the_option(tmp_path) -> None:
    source = "G21 G90 G17 F100\nG0 X0 Y0 Z1\nG2 X10 Y0 Z-1 I5 J0\nG3 X0 Y0 R5\nG2 I5\nM2\n"
    out = _translate(source, "lines:0.01", target="grbl")
    report = verify_lines(io.StringIO(source), io.StringIO(out), file_in="a", file_out="b", source="linuxcnc",
                          target="grbl", chord_tolerance=0.01)
    assert report.ok and 0.009 < report.chord_deviation <= 0.01
    plain = verify_lines(io.StringIO(source), io.StringIO(out), file_in="a", file_out="b", source="linuxcnc",
                         target="grbl")
    assert not plain.ok and plain.mismatch is not None
    finer = verify_lines(io.StringIO(source), io.StringIO(out), file_in="a", file_out="b", source="linuxcnc",
                         target="grbl", chord_tolerance=0.005)
    assert not finer.ok and finer.mismatch is None


def test_verify_finds_a_chord_off_its_arc() -> None:
    source = "G21 G90 G17 F100\nG0 X0 Y0\nG2 X10 Y0 R5\nM2\n"
    out = _translate(source, "lines:1.5")
    bad = out.replace("G1 X5. Y5.", "G1 X5. Y4.6")  # the chords' middles (2.5, 2.3), (7.5, 2.3): 1.603 inside;
    # nearer still where the chord from (0, 0) to (5, 4.6) passes nearest the centre (5, 0): |5 * 4.6| / |(5, 4.6)|
    # = 3.385 from it (by hand: the foot of the perpendicular, at 0.54 of the chord), 1.615 inside the arc
    report = verify_lines(io.StringIO(source), io.StringIO(bad), file_in="a", file_out="b", source="linuxcnc",
                          target="linuxcnc", chord_tolerance=1.5)
    assert not report.ok and report.chord_deviation == pytest.approx(5 - 5 * 4.6 / math.hypot(5, 4.6), abs=1e-6)
    short = out.replace("G1 X10. Y0.", "G1 X9. Y0.")
    report = verify_lines(io.StringIO(source), io.StringIO(short), file_in="a", file_out="b", source="linuxcnc",
                          target="linuxcnc", chord_tolerance=1.5)
    assert not report.ok


def test_pattern_arcs_become_lines_and_verify(root) -> None:
    source = (root / "examples/fagor/bolt_circle_arcs.nc").read_text()
    out = _translate(source, "lines:0.01", source="fagor", target="linuxcnc")
    assert not ARC.search(out)
    report = verify_lines(io.StringIO(source), io.StringIO(out), file_in="a", file_out="b", source="fagor",
                          target="linuxcnc", chord_tolerance=0.01)
    assert report.ok, report.summary()


def test_compensated_arcs_become_lines_after_the_compensation() -> None:
    source = ("G21 G90 G17 F100\nT1 M6\nG0 X-10 Y0\nG41 D1 G1 X0 Y0\nG2 X10 Y0 R5\nG1 X20\nG40 G1 X30 Y-10\nM2\n")
    from postproc.setup.machine_setup import MachineSetup
    from postproc.setup.machine import ToolData
    setup = MachineSetup()
    setup.tools["1"] = ToolData(number=1, radius=1.0)
    out = io.StringIO()
    translate(io.StringIO(source), out, file="t.ngc", source="linuxcnc", target="grbl", setup=setup,
              arcs=parse_arc_option("lines:0.01"))
    assert not ARC.search(out.getvalue()) and "G41" not in out.getvalue()
    report = verify_lines(io.StringIO(source), io.StringIO(out.getvalue()), file_in="a", file_out="b",
                          source="linuxcnc", target="grbl", setup=setup, chord_tolerance=0.01)
    assert report.ok, report.summary()


# -- refusals --------------------------------------------------------------------------------------------

def _error(text: str, arcs: str, target: str = "linuxcnc") -> str:
    with pytest.raises(ErrorList) as info:
        _translate(text, arcs, target=target)
    return str(info.value.errors[0])


def test_an_arc_whose_start_is_not_known_is_refused_at_its_line() -> None:
    message = _error("G21 G90 G17 F100\nG0 X0 Y0\nG55\nG2 X10 Y0 R5\nM2\n", "ijk")
    assert message.startswith("t.ngc:4:") and "start point of this arc is not known" in message


def test_an_incremental_arc_needs_no_known_start() -> None:
    out = _translate("G21 G90 G17 F100\nG55\nG91 G2 X10 Y0 R5\nM2\n", "ijk")
    assert "G2 X10. Y0. I5. J0." in out


def test_lines_under_cutter_compensation_kept_by_the_target_is_refused() -> None:
    text = "G21 G90 G17 F100\nT1 M6\nG0 X-10 Y0\nG41 D1 G1 X0 Y0\nG2 X10 Y0 R5\nG40 G1 X20\nM2\n"
    message = _error(text, "lines:0.01")
    assert message.startswith("t.ngc:5:") and "cutter compensation" in message
    assert "G2 X10. Y0. I5. J0." in _translate(text, "ijk")  # the same arc in centre form is fine


def test_lines_under_inverse_time_is_refused() -> None:
    message = _error("G21 G90 G17\nG0 X0 Y0\nG93 G2 X10 Y0 R5 F2\nG94\nM2\n", "lines:0.01")
    assert message.startswith("t.ngc:3:") and "inverse-time" in message


def test_too_fine_a_tolerance_for_a_huge_arc_is_refused() -> None:
    message = _error("G21 G90 G17 F100\nG0 X0 Y0\nG2 X0 Y0 I900000 J0\nM2\n", "lines:0.0001")
    assert message.startswith("t.ngc:3:") and "chords would be needed" in message


def test_under_warn_a_refused_arc_is_written_as_it_was() -> None:
    text = "G21 G90 G17 F100\nT1 M6\nG0 X-10 Y0\nG41 D1 G1 X0 Y0\nG2 X10 Y0 R5\nG40 G1 X20\nM2\n"
    warnings = io.StringIO()
    from postproc.errors import Diagnostics
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.ngc", source="linuxcnc", target="linuxcnc", on_unsupported="warn",
              diagnostics=Diagnostics(warn_stream=warnings), arcs=parse_arc_option("lines:0.01"))
    assert "G2 X10 Y0 R5" in out.getvalue()
    assert "t.ngc:5:" in warnings.getvalue() and "written as it was" in warnings.getvalue()


@st.composite
def s_curves(draw: st.DrawFn) -> str:
    """A line, then incremental (G91) arcs turning one way then the other, each tangent to the move before
    (an S), then a line tangent to the last: a chord at either end of an arc and the move next to it are
    nearly in line."""
    inch = draw(st.booleans())
    heading = draw(st.floats(0.0, 2.0 * math.pi))
    x, y = (round(draw(st.floats(0.05, 5.0)) * f(heading), 4) for f in (math.cos, math.sin))
    lines = ["G20" if inch else "G21", "G90 G17 G94 G0 X0 Y0 Z0", f"G91 G1 X{x:.4f} Y{y:.4f} F100"]
    ccw = draw(st.booleans())
    for _ in range(draw(st.integers(2, 3))):
        r = draw(st.floats(0.5, 8.0))
        sweep = draw(st.floats(0.3, 1.5 * math.pi))
        side = heading + (math.pi / 2.0 if ccw else -math.pi / 2.0)  # towards the centre
        cx, cy = x + r * math.cos(side), y + r * math.sin(side)
        a = math.atan2(y - cy, x - cx) + (sweep if ccw else -sweep)
        ex, ey = cx + r * math.cos(a), cy + r * math.sin(a)
        i, j, dx, dy = (round(v, 4) for v in (cx - x, cy - y, ex - x, ey - y))
        lines.append(f"G{3 if ccw else 2} X{dx:.4f} Y{dy:.4f} I{i:.4f} J{j:.4f}")
        x, y = x + dx, y + dy
        heading += sweep if ccw else -sweep
        ccw = not ccw
    length = draw(st.floats(0.05, 5.0))
    lines += [f"G1 X{length * math.cos(heading):.4f} Y{length * math.sin(heading):.4f}", "G90 M2"]
    return "\n".join(lines) + "\n"


@settings(max_examples=40, deadline=None)
@given(s_curves(), st.sampled_from(["lines:0.001", "lines:0.0005", "lines:0.0001"]),
       st.sampled_from(["grbl", "fanuc", "linuxcnc"]))
def test_verify_follows_chords_merged_across_an_arcs_end(program: str, arcs: str, target: str) -> None:
    """verify merges straight moves within half its tolerance of one line: at an S's turn (or into a tangent
    line) the last chord of an arc and the next move merge into one run, and so do a line and the first
    chord of the arc it runs into; verify's chord check cuts the run at the arc's (the line's) end again.
    Before, it reported "OUT's straight moves run past the end of IN's arc" (the fuzz's known defect, put
    down to the increments' rounding, which it was not) or the line's end a chord's length off."""
    out = _translate(program, arcs, target=target)
    tolerance = float(arcs.partition(":")[2])
    for verify_tolerance in (0.001, 0.002, 0.005):
        report = verify_lines(io.StringIO(program), io.StringIO(out), file_in="a", file_out="b", source="linuxcnc",
                              target=target, tolerance=verify_tolerance, chord_tolerance=tolerance)
        assert report.ok, f"{report.summary()}\n{program}"


def test_the_fuzz_case_of_chords_past_an_arcs_end() -> None:
    """The program options fuzz's case (Fanuc to grbl): a long G3 R arc, then a long G2 R arc, tangent at the
    turn; the last chord of the first (OUT:177) merged with the first of the second (OUT:179)."""
    program = ("G21 G17 G90 G94\nG0 X0. Y0. Z10.\nG91 G3 X11. Y11. R-11. F90.\nG90\nG91 G2 X7.75 Y7.75 R-7.75\n"
               "G90\nM30\n")
    out = _translate(program, "lines:0.001", source="fanuc", target="grbl")
    report = verify_lines(io.StringIO(program), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="grbl", tolerance=0.002, chord_tolerance=0.001)
    assert report.ok and report.mismatch is None, report.summary()


def test_a_run_that_ends_within_the_tolerance_of_the_line_is_not_cut() -> None:
    """A line's end, rotated by the transform, lies 1.5e-7 mm before where OUT writes it: not a run past the
    line's end to cut (a first version of the cut paired the nanometre left over with the circle after it)."""
    from postproc.transforms.spec import parse_transform
    program = ("G21 G17 G90 G94\nG0 X0. Y0. Z10.\nG1 X13.75 Y-40. Z8. F200.\nG91 G3 X0. I-6.5 J13.75 F100.\n"
               "G90 G0 Z10.\nM30\n")
    transform = parse_transform("rotate 12.5 about 10,5")
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.ngc", source="linuxcnc", target="fanuc", transform=transform,
              arcs=parse_arc_option("lines:0.001"))
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a", file_out="b",
                          source="linuxcnc", target="fanuc", tolerance=0.002, transform=transform,
                          chord_tolerance=0.001)
    assert report.ok, report.summary()


def test_the_arc_pass_is_left_out_exactly_where_the_settle_pass_has_nothing_to_do() -> None:
    """``postproc.api`` decides before importing ``postproc.lowering.arcs`` whether a translation has arcs to settle
    (``ArcEndRule.settles_for``): for every pair of installed dialects, with their set-up's rule and with each other
    path an arc can take, it leaves the pass out exactly where the pass's own ``start`` would do nothing."""
    from dataclasses import replace

    from postproc.api import _arc_pass
    from postproc.errors import Diagnostics
    from postproc.geometry.arc_end import RUNS
    from postproc.lowering.arcs import RewriteArcs, SettleArcEnds, settle_arc_ends
    from postproc.plugins import default_registry
    from postproc.setup.machine_setup import MachineSetup

    dialects = list(default_registry().dialects.values())
    kept = left = 0
    for src in dialects:
        ctx = src.context("t.nc", MachineSetup(), Diagnostics())
        for rule in {ctx.arc_end, *(replace(ctx.arc_end, runs=runs, of_centre_shift=False) for runs in RUNS)}:
            ctx.arc_end = rule
            for dst in dialects:
                chosen = _arc_pass(None, ctx, dst)
                assert (chosen is None) == (settle_arc_ends.start(ctx, dst) is None), (src.NAME, rule, dst.NAME)
                assert chosen is None or isinstance(chosen, SettleArcEnds)
                kept, left = kept + (chosen is not None), left + (chosen is None)
                assert isinstance(_arc_pass(parse_arc_option("ijk"), ctx, dst), RewriteArcs)  # --arcs: always
    assert kept and left  # (both sides met)
