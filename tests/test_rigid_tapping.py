"""Rigid (spindle-synchronised) tapping across families, with LinuxCNC's interpreter as the oracle.

* LinuxCNC ``G33.1`` programs (seeded): postproc's toolpath gives the moves rs274 gives (two ``tap`` moves per
  G33.1, to the end point and back, at the K pitch; rs274: ``START_SPEED_FEED_SYNC(K)``, ``RIGID_TAP``).
* Fanuc rigid taps (``M29 S..`` + ``G84``/``G74``, seeded: G98/G99, feed per minute or per revolution, metric
  or inch, rows of holes): translated to LinuxCNC they run in rs274 as the Fanuc program is simulated, pitch
  included (F/S per minute [V: Fanuc 0i connection manual B-63833EN-1/02, rigid tapping], F per revolution),
  and ``verify`` passes; written as plain feeds they fail ``verify``.
* Hand-derived points, and the refusals: a target without synchronised motion (grbl) even with
  ``--on-unsupported warn``, a dwell at the bottom towards G33.1, M29 before a cycle that is not a tap.
"""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274

TOLERANCE_MM = 3e-3
"""rs274 prints 4 decimals in program units: 1e-4 in = 0.00254 mm."""
PROGRAMS = 24


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def events(text: str, dialect: str) -> list[dict[str, Any]]:
    return list(toolpath_events(_lines(text), file="t.nc", dialect=dialect, setup=MachineSetup()))[1:]


def to(target: str, text: str, mode: str = "error") -> str:
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.nc", source="fanuc", target=target, setup=MachineSetup(),
              on_unsupported=mode, diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def moves(evs: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [e for e in evs if "move" in e]


def same_moves(ours: list[dict[str, Any]], theirs: list[dict[str, Any]]) -> None:
    """Move by move: the kind, the end point, and the pitch of a tap."""
    assert [e["move"] for e in ours] == [e["move"] for e in theirs], (ours, theirs)
    for a, b in zip(ours, theirs):
        assert max(abs(float(a[k]) - float(b[k])) for k in "xyz") <= TOLERANCE_MM, (a, b)
        if a["move"] == "tap":
            assert abs(float(a["f"]) - float(b["f"])) <= 1e-4 * max(1.0, float(b["f"])), (a, b)


def oracle(ngc: str) -> list[dict[str, Any]]:
    return moves(rs274.canonical_moves(rs274.run_rs274(ngc), start=(0.0, 0.0, 0.0), feeds=True))


needs_rs274 = pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")


# -- hand-derived ------------------------------------------------------------------------------------

def test_g33_1_taps_in_and_back_at_its_pitch() -> None:
    # G91 Z-15 from Z5: in to Z-10 and back to Z5 at 1.25 mm/rev; the point does not change (the G0 after it
    # starts at X1 Z5)
    got = moves(events("G21 G90 S500 M3\nG0 X1 Z5\nG91 G33.1 Z-15 K1.25\nG90 G0 X3\nM2\n", "linuxcnc"))
    assert got == [
        {"line": 2, "move": "rapid", "x": 1, "y": 0, "z": 5},
        {"line": 3, "move": "tap", "x": 1, "y": 0, "z": -10, "f": 1.25, "feed_mode": "per_rev"},
        {"line": 3, "move": "tap", "x": 1, "y": 0, "z": 5, "f": 1.25, "feed_mode": "per_rev"},
        {"line": 4, "move": "rapid", "x": 3, "y": 0, "z": 5}]


def test_fanuc_rigid_tap_per_minute_and_per_revolution() -> None:
    # G95 F1.5: the pitch is F; G94 F300 S200: F/S = 1.5; G74 taps counter-clockwise: the spindle is set
    for feed in ("G95 F1.5", "G94 F300."):
        got = events(f"G21 G90 G0 X0 Y0 Z10. S200 M3\nM29 S200\nG98 G74 X5. Y6. Z-4. R2. {feed}\nG80\nM30\n", "fanuc")
        assert [(e.get("move") or e["dir"], e.get("z"), e.get("f")) for e in got if e["line"] == 3] == [
            ("rapid", 10, None), ("rapid", 2, None), ("ccw", None, None), ("tap", -4, 1.5), ("tap", 2, 1.5),
            ("rapid", 10, None)]


def test_rigid_mode_ends_with_the_cycle_cancel() -> None:
    # after G80 the next G84 without M29 is a floating tap again: feed moves, the spindle reversed
    got = events("G21 G90 G0 X0 Y0 Z10. S200 M3\nM29 S200\nG84 X0 Y0 Z-4. R2. F300.\nG80\n"
                 "G84 X5. Y0 Z-4. R2. F300.\nG80\nM30\n", "fanuc")
    assert [e["move"] for e in got if e["line"] == 3 and "move" in e] == ["rapid", "tap", "tap", "rapid"]
    assert [e["move"] for e in got if e["line"] == 5 and "move" in e] == ["rapid", "rapid", "feed", "feed", "rapid"]


def test_m29_before_a_cycle_that_is_not_a_tap_is_refused() -> None:
    with pytest.raises(ErrorList) as info:
        events("G21 G90 G0 X0 Y0 Z10. S200 M3\nM29 S200\nG81 X0 Y0 Z-4. R2. F300.\nM30\n", "fanuc")
    assert [str(e) for e in info.value.errors] == [
        "t.nc:3:1: error: G81 while rigid tapping mode (M29) is on: only a tap cycle may follow it (cancel the "
        "mode with the cycle cancel first)"]


def test_peck_rigid_tapping_is_refused_not_tapped_in_one_go() -> None:
    with pytest.raises(ErrorList) as info:
        events("G21 G90 G0 X0 Y0 Z10. S200 M3\nM29 S200\nG84 X0 Y0 Z-4. R2. Q1. F300.\nG80\nM30\n", "fanuc")
    assert [str(e) for e in info.value.errors] == [
        "t.nc:3:20: error: peck rigid tapping (M29 then G84 with Q) is not modelled: its return per peck is a machine "
        "parameter"]


def test_an_axis_move_between_m29_and_its_tap_is_refused() -> None:
    with pytest.raises(ErrorList) as info:
        events("G21 G90 G0 X0 Y0 Z10. S200 M3\nM29 S200\nG0 X5.\nG84 Z-4. R2. F300.\nG80\nM30\n", "fanuc")
    assert [str(e) for e in info.value.errors][:1] == [
        "t.nc:3:1: error: an axis move between M29 (rigid tapping) and its tap cycle: the control refuses it (Fanuc "
        "alarm PS0204); position the tool before the rigid tapping code"]


@pytest.mark.parametrize("mode", ["error", "warn"])
def test_a_dwell_at_the_bottom_has_no_g33_1_spelling(mode: str) -> None:
    with pytest.raises(ErrorList) as info:
        to("linuxcnc", "G21 G90 G0 X0 Y0 Z10. S200 M3\nM29 S200\nG84 X0 Y0 Z-4. R2. P500 F300.\nG80\nM30\n", mode)
    assert [str(e) for e in info.value.errors] == [
        "t.nc:3:1: error: a rigid tap with a dwell at the bottom (P): linuxcnc's synchronised tap reverses at once "
        "and has no dwell there: refused, even with --on-unsupported warn"]


def test_g33_1_with_the_spindle_stopped_is_refused() -> None:
    with pytest.raises(ErrorList) as info:
        events("G21 G90 S500\nG0 Z5\nG33.1 Z-10 K1\nM2\n", "linuxcnc")
    assert [str(e) for e in info.value.errors] == [
        "t.nc:3:1: error: a rigid tap with the spindle stopped cannot be run (start it first)"]


def test_g33_1_round_trips_and_its_mode_is_modal() -> None:
    text = "G21 G90\nS500 M3\nG0 X1 Z5\nG33.1 Z-10 K1.25 I2\nZ-5 K1\nG0 X3\nM2\n"
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="linuxcnc", setup=MachineSetup())
    assert out.getvalue() == text
    assert [e["z"] for e in moves(events(text, "linuxcnc")) if e["move"] == "tap"] == [-10, 5, -5, 5]


@pytest.mark.parametrize("mode", ["error", "warn"])
def test_g33_1_towards_a_target_without_it_is_refused(mode: str) -> None:
    out = io.StringIO(newline="")
    with pytest.raises(ErrorList) as info:
        translate(_lines("G21 G90\nS500 M3\nG0 X1 Z5\nG33.1 Z-10 K1.25\nM2\n"), out, file="t.ngc", source="linuxcnc",
                  target="grbl", setup=MachineSetup(), on_unsupported=mode,
                  diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert [e.location.line for e in info.value.errors if e.location] == [4]


# -- against rs274 ---------------------------------------------------------------------------------------

def _g33_1_program(rng: random.Random) -> str:
    inch = rng.random() < 0.25
    lines = ["G20" if inch else "G21", "G90 G17", f"S{rng.randint(100, 900)} M{rng.choice((3, 4))}"]
    z0 = rng.uniform(1, 10)
    lines.append(f"G0 X{rng.uniform(-50, 50):.4f} Y{rng.uniform(-50, 50):.4f} Z{z0:.4f}")
    for _ in range(rng.randint(1, 4)):
        pitch = rng.choice((0.5, 0.7, 1.0, 1.25, 1.5, 2.0, 0.05))
        if rng.random() < 0.3:
            lines.append(f"G91 G33.1 Z{-rng.uniform(1, 20):.4f} K{pitch}")
            lines.append("G90")
        else:
            extra = f" X{rng.uniform(-50, 50):.4f}" if rng.random() < 0.2 else ""
            speedup = f" I{rng.choice((1, 1.5, 2))}" if rng.random() < 0.3 else ""
            lines.append(f"G33.1{extra} Z{-rng.uniform(1, 20):.4f} K{pitch}{speedup}")
        lines.append(f"G0 X{rng.uniform(-50, 50):.4f} Y{rng.uniform(-50, 50):.4f}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_g33_1_moves_as_rs274_moves(seed: int) -> None:
    text = _g33_1_program(random.Random(seed))
    same_moves(moves(events(text, "linuxcnc")), oracle(text))


def _fanuc_rigid_program(rng: random.Random) -> str:
    inch = rng.random() < 0.25
    unit = 25.4 if inch else 1.0
    per_rev = rng.random() < 0.3
    left = rng.random() < 0.3
    rpm = rng.choice((200, 300, 450, 600, 800))
    pitch = rng.choice((0.5, 1.0, 1.25, 1.5, 2.0)) / unit
    feed = f"F{pitch:.4f}" if per_rev else f"F{pitch * rpm:.4f}"
    z0, r = rng.uniform(8, 20) / unit, rng.uniform(1, 5) / unit
    lines = ["G20" if inch else "G21", "G90 G17 G95" if per_rev else "G90 G17 G94",
             f"G0 X0. Y0. Z{z0:.4f} S{rpm} M{4 if left and rng.random() < 0.5 else 3}", f"M29 S{rpm}"]
    holes = [(rng.uniform(-40, 40) / unit, rng.uniform(-40, 40) / unit) for _ in range(rng.randint(1, 4))]
    code = "G74" if left else "G84"
    lines.append(f"{rng.choice(('G98', 'G99'))} {code} X{holes[0][0]:.4f} Y{holes[0][1]:.4f} "
                 f"Z{-rng.uniform(3, 15) / unit:.4f} R{r:.4f} {feed}")
    lines.extend(f"X{x:.4f} Y{y:.4f}" for x, y in holes[1:])
    lines += ["G80", "M30"]
    return "\n".join(lines) + "\n"


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_a_fanuc_rigid_tap_runs_in_linuxcnc_as_the_source_moves(seed: int) -> None:
    text = _fanuc_rigid_program(random.Random(1000 + seed))
    ngc = to("linuxcnc", text)
    assert "G33.1" in ngc and "M29" not in ngc.replace("(M29", "")
    same_moves(moves(events(text, "fanuc")), oracle(ngc))
    report = verify_lines(_lines(text), _lines(ngc), file_in="t.nc", file_out="t.ngc", source="fanuc",
                          target="linuxcnc", setup=MachineSetup())
    assert report.ok and report.max_deviation < 1e-6, report.summary()


@pytest.mark.parametrize("mode", ["error", "warn"])
def test_a_fanuc_rigid_tap_is_never_fed_to_grbl(mode: str) -> None:
    text = _fanuc_rigid_program(random.Random(7))  # M29 at line 4, the taps at lines 5 and 6 (and G95 at 2)
    with pytest.raises(ErrorList) as info:
        to("grbl", text, mode)
    assert sorted(e.location.line for e in info.value.errors if e.location and "tap" in str(e)) == [4, 5, 6]


def _linuxcnc_taps(rng: random.Random) -> str:
    """G33.1 along Z only (what a tap cycle can say), absolute or incremental, either spindle direction."""
    inch = rng.random() < 0.25
    lines = ["G20" if inch else "G21", "G90 G17 G94 F50", f"S{rng.randint(100, 900)} M{rng.choice((3, 4))}"]
    for _ in range(rng.randint(1, 3)):
        lines.append(f"G0 X{rng.uniform(-50, 50):.4f} Y{rng.uniform(-50, 50):.4f} Z{rng.uniform(1, 10):.4f}")
        pitch = rng.choice((0.5, 0.7, 1.0, 1.25, 1.5, 2.0))
        if rng.random() < 0.3:
            lines += [f"G91 G33.1 Z{-rng.uniform(2, 20):.4f} K{pitch}", "G90"]
        else:
            lines.append(f"G33.1 Z{-rng.uniform(1, 20):.4f} K{pitch}")
    lines += ["G1 X0 Y0", "M2"]
    return "\n".join(lines) + "\n"


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS // 2))
def test_g33_1_reaches_fanuc_as_m29_and_a_tap_cycle(seed: int) -> None:
    text = _linuxcnc_taps(random.Random(2000 + seed))
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=MachineSetup())
    nc = out.getvalue()
    assert nc.count("M29") == text.count("G33.1") and "G33" not in nc, nc
    same_moves(moves(events(nc, "fanuc")), oracle(text))
    report = verify_lines(_lines(text), _lines(nc), file_in="t.ngc", file_out="t.nc", source="linuxcnc",
                          target="fanuc", setup=MachineSetup())
    assert report.ok and report.max_deviation < 1e-6, report.summary()


def test_g33_1_to_fanuc_hand_derived() -> None:
    text = "G21 G90 G17\nS500 M4\nG0 X1 Y2 Z5 F200\nG91 G33.1 Z-8 K1\nM2\n"
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=MachineSetup())
    # M4: a left-hand tap (G74); R at the start Z5, the bottom 8 below it; F = 1 x 500; back to G91 and F200
    assert out.getvalue() == ("G17 G21 G90\nS500 M04\nG00 X1. Y2. Z5. F200.\nS500 M29\nG90 G99 G74 Z-3. R5. F500.\n"
                              "G91 G80 F200.\nM02\n")


@pytest.mark.parametrize("mode", ["error", "warn"])
def test_an_oblique_g33_1_has_no_tap_cycle(mode: str) -> None:
    out = io.StringIO(newline="")
    with pytest.raises(ErrorList) as info:
        translate(_lines("G21 G90\nS500 M3\nG0 X1 Z5\nG33.1 X2 Z-10 K1.25\nM2\n"), out, file="t.ngc",
                  source="linuxcnc", target="fanuc", setup=MachineSetup(), on_unsupported=mode,
                  diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert [str(e) for e in info.value.errors] == [
        "t.ngc:4:1: error: a rigid tap that moves X (an oblique tap): fanuc's tap cycle taps along Z only"]
