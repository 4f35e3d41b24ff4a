"""SINUMERIK ``CYCLE84`` (rigid tapping, ``dialects/siemens/tapping.py``) both ways.

Read: a rigid tap at the pitch PIT, where the call moves as Fanuc's rigid ``G84``/``G74`` (PGZ 11/2006 2.1.5:
G0 to RFP+SDIS, tap to the depth in step with the spindle, dwell DTB, tap back out to RFP+SDIS with the
direction reversed, G0 to RTP; the direction after it SDAC, the speed the one before the call). Expected toolpaths
are worked out by hand from that sequence (the comments give the arithmetic). Written: Fanuc ``M29 S..`` then a
rigid ``G84``/``G74`` as ``MCALL CYCLE84`` with the parameter mapping of USERS-AND-SIEMENS.md 3.2 (RTP the
return level, RFP = R, SDIS 0, DP = Z, SDAC the tap's direction, PIT signed by the hand, SST = SST1 = the S in
force), read back to the same toolpath on seeded random programs. grbl cannot synchronise its spindle: a tap is
refused there by name. LinuxCNC's interpreter runs ``examples/siemens/tapping.mpf``'s translation to the same
moves (``test_siemens_oracle``).
"""

from __future__ import annotations

import io
import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

START = "G710 G17 G90 G94 G0 X5 Y5 Z20\nS500 M3\n"
"""The tool at (5, 5, 20), the spindle turning clockwise at 500 rev/min, G0 in force, no F programmed."""


def _translate(text: str, target: str, source: str = "siemens", **options: object) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()), **options)  # type: ignore[arg-type]
    return out.getvalue()


def _errors(text: str, target: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, target)
    return [str(e) for e in caught.value.errors]


def _events(text: str, dialect: str = "siemens") -> list[tuple[object, ...]]:
    """(move, x, y, z) of each motion with the pitch of a tap, ("dwell", s) and ("spindle", dir)."""
    out: list[tuple[object, ...]] = []
    for e in toolpath_events(io.StringIO(text), file="in", dialect=dialect):
        if e.get("move") == "tap":
            out.append(("tap", e["x"], e["y"], e["z"], e["f"]))
        elif "move" in e:
            out.append((e["move"], e["x"], e["y"], e["z"]))
        elif e.get("event") == "dwell":
            out.append(("dwell", e["seconds"]))
        elif e.get("event") == "spindle":
            out.append(("spindle", e["dir"]))
    return out


def _verify(text: str, out: str, source: str, target: str, **options: object) -> None:
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source=source,
                          target=target, tolerance=0.0, **options)  # type: ignore[arg-type]
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


MODAL = START + "MCALL CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 500, 500)\nX20\nX30 Y20\nMCALL\nG0 X0 Y0\nM30\n"
ONCE_LEFT = START + "G0 X0 Y0 Z20\nCYCLE84(20, 0, 2, -8, , 0.5, 4, , -1, , 500, )\nM30\n"


def test_mcall_cycle84_taps_each_hole_in_step_with_the_spindle() -> None:
    """RTP 20 is the tool's Z at the call (Fanuc's initial level); RFP+SDIS = 0+2; DP -10; PIT 1.5 (right-hand,
    SDAC 3 = M3, the direction in force): at each hole G0 to X, Y at Z20, G0 to Z2, a tap to -10 and back to 2
    at 1.5 mm a revolution, G0 to RTP 20."""
    assert _events(MODAL) == [
        ("rapid", 5, 5, 20), ("spindle", "cw"),
        ("rapid", 20, 5, 20), ("rapid", 20, 5, 2), ("tap", 20, 5, -10, 1.5), ("tap", 20, 5, 2, 1.5),
        ("rapid", 20, 5, 20),
        ("rapid", 30, 20, 20), ("rapid", 30, 20, 2), ("tap", 30, 20, -10, 1.5), ("tap", 30, 20, 2, 1.5),
        ("rapid", 30, 20, 20),
        ("rapid", 0, 0, 20)]


def test_a_left_hand_cycle84_called_once_turns_the_spindle_counter_clockwise_and_dwells_at_the_depth() -> None:
    """PIT -1: a left-hand thread, tapped counter-clockwise (SDAC 4 = M4 after it); DTB 0.5 s at the depth
    -8; SST1 empty; G0 to RFP+SDIS 2 first, G0 back to RTP 20 last."""
    assert _events(ONCE_LEFT)[2:] == [
        ("rapid", 0, 0, 20), ("rapid", 0, 0, 2), ("spindle", "ccw"), ("tap", 0, 0, -8, 1.0), ("dwell", 0.5),
        ("tap", 0, 0, 2, 1.0), ("rapid", 0, 0, 20)]


def test_a_siemens_tap_is_fanucs_rigid_tap_cycle_at_each_hole() -> None:
    """Fanuc's tap cycle is rigid only after M29 S..: each hole is the positioning moves, M29 with the S in
    force, a G99 G84 at the spot from R 2 (F = 1.5 x 500 = 750 in G94), G80, and the rapid to RTP."""
    out = _translate(MODAL, "fanuc")
    assert "\n".join(line for line in out.splitlines() if not line.startswith("(")).count(
        "G00 Z2.\nS500 M29\nG99 G84 Z-10. R2. F750.\nG98 G80\n") == 2, out
    _verify(MODAL, out, "siemens", "fanuc")
    left = _translate(ONCE_LEFT.replace(", 0.5, 4", ", , 4"), "fanuc")
    assert "S500 M29\nG99 G74 Z-8. R2. F500.\nG98 G80\n" in left, left
    _verify(ONCE_LEFT.replace(", 0.5, 4", ", , 4"), left, "siemens", "fanuc")


def test_a_siemens_tap_is_linuxcnc_g33_1_and_refused_by_grbl_by_name() -> None:
    out = _translate(MODAL, "linuxcnc")
    assert out.count("G33.1 Z-10. K1.5") == 2, out
    _verify(MODAL, out, "siemens", "linuxcnc")
    assert all("rigid (spindle-synchronised) tap" in e for e in _errors(MODAL, "grbl")), _errors(MODAL, "grbl")


def test_a_siemens_tap_with_a_dwell_is_refused_where_the_synchronised_tap_has_none() -> None:
    """LinuxCNC's G33.1 reverses at once, and Fanuc's tap cycle written for a synchronised tap has no dwell."""
    assert any("dwell at the bottom" in e for e in _errors(ONCE_LEFT, "linuxcnc"))
    assert any("a rigid tap with a dwell" in e for e in _errors(ONCE_LEFT, "fanuc"))


def test_a_siemens_tap_reads_back_from_siemens_under_units_inch() -> None:
    out = _translate(MODAL, "siemens", units="inch")
    assert "MCALL CYCLE84(0.78740157, 0.07874016, 0, -0.39370079, , , 3, , 0.05905512, 0, 500, 500)" in out, out
    _verify(MODAL, out, "siemens", "siemens")  # toolpaths compare in mm


@pytest.mark.parametrize("call, name", [
    ("CYCLE84(20, 0, 2, -10, , , 5, , 1.5, 0, 500, 500)", "CYCLE84 with SDAC 5"),
    ("CYCLE84(20, 0, 2, -10, , , 4, , 1.5, 0, 500, 500)", "CYCLE84 with SDAC 4"),
    ("CYCLE84(20, 0, 2, -10, , , 3, 10, , 0, 500, 500)", "CYCLE84 with MPIT"),
    ("CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 30, 500, 500)", "CYCLE84 with POSS other than 0"),
    ("CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 500, 800)", "CYCLE84 with SST1 other than SST"),
    ("CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 400, 400)", "CYCLE84 with SST 400 other than the S in force"),
    ("CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 500, 500, , , , 1, 3, 1)", "CYCLE84 with _VARI other than 0"),
    ("CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 500, 500, , 2)", "CYCLE84 with _PTAB other than 0"),
    ("CYCLE84(20, 0, 2, -10, , , 3, , , 0, 500, 500)", "CYCLE84 without its pitch PIT"),
    ("CYCLE840(20, 0, 2, -10, , , 4, 3, 1, , 1.5)", "CYCLE840 with a lead MPIT/PIT"),
])
def test_an_unconfirmed_tap_is_kept_verbatim_and_refused_elsewhere_by_name(call: str, name: str) -> None:
    text = START + call + "\nM30\n"
    assert _translate(text, "siemens") == text
    for target in ("fanuc", "linuxcnc", "grbl"):
        assert any(name in e for e in _errors(text, target)), (target, _errors(text, target))


def test_another_speed_under_mcall_cycle84_is_a_located_error() -> None:
    """SINUMERIK taps every hole at SST and restores the S in force after it; Fanuc's tap runs at the S in force."""
    text = START + "MCALL CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 500, 500)\nX20 S800\nMCALL\nM30\n"
    errors = _errors(text, "fanuc")
    assert any(e.startswith("in.mpf:4:5: error: S 800") and "SST 500" in e for e in errors), errors


# -- Fanuc rigid taps written as CYCLE84 ---------------------------------------------------------------------

FANUC = ("G21 G90 G17 G94\nG0 X0. Y0. Z20.\nS800 M3\nM29 S500\nG98 G84 X10. Y5. Z-10. R2. F750.\nX20.\nG80\n"
         "M29 S400\nG99 G74 X5. Y5. Z-8. R3. P300 F400.\nY15.\nG80\nG0 Z20.\nM30\n")


def test_fanuc_rigid_taps_are_mcall_cycle84() -> None:
    """G98 G84: RTP the initial level 20, RFP = R 2, SDIS 0, DP -10, SDAC 3, PIT = F/S = 750/500 = 1.5, SST =
    SST1 = 500; G99 G74: RTP = R 3, DTB 0.3 s, SDAC 4, PIT -(400/400) = -1. M29 goes (CYCLE84 is rigid by itself),
    its S stays."""
    out = _translate(FANUC, "siemens", source="fanuc")
    assert out.splitlines() == [
        "G17 G710 G90 G94", "G0 X0. Y0. Z20.", "S800 M3",
        "S500 ;M29 (rigid tapping): the taps after it are written spindle-synchronised", "F750.", "G0",
        "MCALL CYCLE84(20., 2., 0, -10., , , 3, , 1.5, 0, 500, 500)", "X10. Y5.", "X20.", "MCALL",
        "S400 ;M29 (rigid tapping): the taps after it are written spindle-synchronised", "F400.", "G0",
        "MCALL CYCLE84(3., 3., 0, -8., , 0.3, 4, , -1., 0, 400, 400)", "X5. Y5.", "Y15.", "MCALL", "G0 Z20.", "M30"]
    _verify(FANUC, out, "fanuc", "siemens")


def test_a_rigid_tap_where_the_tool_stands_is_cycle84_called_once() -> None:
    """The hole at the tool's own X, Y: no position block runs the modal call there [?], so the call once."""
    text = "G21 G90 G17 G94\nG0 X10. Y5. Z20.\nS600 M3\nM29 S600\nG99 G84 X10. Y5. Z-6. R1. F600.\nX20.\nG80\nM30\n"
    out = _translate(text, "siemens", source="fanuc")
    assert "CYCLE84(1., 1., 0, -6., , , 3, , 1., 0, 600, 600)\nG0\nMCALL CYCLE84(1., 1., 0, -6., , , 3, , 1., 0, " \
           "600, 600)\nX20.\nMCALL\n" in out, out
    _verify(text, out, "fanuc", "siemens")


def test_a_floating_g99_tap_is_mcall_cycle840_and_a_g98_one_its_moves() -> None:
    """G84 without M29 feeds at F with the spindle reversed at the bottom: CYCLE840 with ENC 1 (G63 at the F in
    force), SDR 4 (out counter-clockwise), SDAC 3, RTP = RFP = R 2, DTB 0.2 s. Under G98 the spindle's turning back
    before or after the rise to RTP is not confirmed: the moves."""
    text = "G21 G90 G17 G94\nG0 X0. Y0. Z20.\nS500 M3\nG99 G84 X10. Y5. Z-10. R2. P200 F750.\nG80\nM30\n"
    out = _translate(text, "siemens", source="fanuc")
    assert "G0\nMCALL CYCLE840(2., 2., 0, -10., , 0.2, 4, 3, 1)\nX10. Y5.\nMCALL\n" in out, out
    _verify(text, out, "fanuc", "siemens")
    g98 = text.replace("G99", "G98")
    out = _translate(g98, "siemens", source="fanuc")
    assert "CYCLE84" not in out and "M4" in out, out
    _verify(g98, out, "fanuc", "siemens")


FLOATING = START + "G1 F450\nG0 X10 Y10 Z2\nMCALL CYCLE840(2, 0, 2, -10, , 0.2, 4, 3, 1)\nX20\nMCALL\nM4\n" \
    "CYCLE840(2, 0, 2, , 8, , 3, 4, 1)\nM30\n"


def test_cycle840_without_encoder_is_a_floating_tap() -> None:
    """G0 to RFP+SDIS 2, G63 to -10 at the F in force 450, dwell 0.2 s, out reversed (SDR 4) at 450, the spindle
    back in SDAC 3; the left-hand call once from (10, 10... no: where the tool stands, X20 Y10) in the direction
    in force M4, out in SDR 3, M4 again; DPR 8 below RFP 0 is -8."""
    assert _events(FLOATING)[3:] == [
        ("rapid", 20, 10, 2), ("feed", 20, 10, -10), ("dwell", 0.2), ("spindle", "ccw"), ("feed", 20, 10, 2),
        ("spindle", "cw"), ("spindle", "ccw"), ("feed", 20, 10, -8), ("spindle", "cw"), ("feed", 20, 10, 2),
        ("spindle", "ccw")]
    out = _translate(FLOATING, "fanuc")
    assert "G99 G84 Z-10. R2. P200 K0\n" in out and "M29" not in out, out
    _verify(FLOATING, out, "siemens", "fanuc")
    for target in ("linuxcnc", "grbl"):
        _verify(FLOATING, _translate(FLOATING, target), "siemens", target)


@pytest.mark.parametrize("call, name", [
    ("CYCLE840(2, 0, 2, -10, , , 4, 3, 0)", "CYCLE840 with ENC other than 1"),
    ("CYCLE840(2, 0, 2, -10, , , 0, 3, 1)", "CYCLE840 with SDR 0 and SDAC 3"),
    ("CYCLE840(2, 0, 2, -10, , , 4, 3, 1, 10)", "CYCLE840 with a lead MPIT/PIT"),
    ("CYCLE840(20, 0, 2, -10, , , 4, 3, 1)", "CYCLE840 with RTP other than RFP+SDIS"),
    ("CYCLE840(2, 0, 2, -10, , , 3, 4, 1)", "CYCLE840 with the spindle cw, not SDAC's ccw"),
    ("G95\nCYCLE840(2, 0, 2, -10, , , 4, 3, 1)", "CYCLE840 outside G94"),
])
def test_an_unconfirmed_cycle840_is_kept_verbatim_and_refused_elsewhere_by_name(call: str, name: str) -> None:
    text = START + "G1 F450\nG0\n" + call + "\nM30\n"
    assert _translate(text, "siemens") == text
    for target in ("fanuc", "linuxcnc"):
        assert any(name in e for e in _errors(text, target)), (target, _errors(text, target))


def test_a_spindle_code_under_a_modal_tap_is_a_located_error() -> None:
    text = START + "MCALL CYCLE84(20, 0, 2, -10, , , 3, , 1.5, 0, 500, 500)\nX20 M4\nMCALL\nM30\n"
    assert any(e.startswith("in.mpf:4:1: error: a spindle code under MCALL CYCLE84/CYCLE840")
               for e in _errors(text, "fanuc"))


def _random_taps(seed: int) -> str:
    rng = random.Random(seed)
    per_rev = rng.random() < 0.4
    lines = ["G21 G90 G17 " + ("G95" if per_rev else "G94"), "G0 X0. Y0. Z30.", "S1000 M3"]
    for _ in range(rng.randint(1, 3)):
        rpm = rng.randrange(200, 1300, 100)
        pitch = rng.choice([0.5, 0.7, 0.8, 1.0, 1.25, 1.5, 1.75, 2.0])
        feed = pitch if per_rev else pitch * rpm
        code = rng.choice(["G84", "G74"])
        level = rng.choice(["G98", "G99"])
        r = rng.choice([1.0, 2.0, 3.0])
        dwell = f" P{rng.choice([100, 250, 500])}" if rng.random() < 0.3 else ""
        rigid = rng.random() < 0.7
        if rigid:
            lines.append(f"M29 S{rpm}")
        else:  # a floating tap: the spindle turning its direction, G99 (CYCLE840), or G98 (its moves)
            lines.append(f"S{rpm} {'M3' if code == 'G84' else 'M4'}")
        lines.append(f"{level} {code} X{rng.randint(-30, 30)}. Y{rng.randint(-30, 30)}. Z{-rng.randint(3, 15)}. "
                     f"R{r}{dwell} F{feed:.4f}")
        lines += [f"X{rng.randint(-30, 30)}. Y{rng.randint(-30, 30)}." for _ in range(rng.randint(0, 3))]
        lines += ["G80", "G0 Z30."] + ([] if rigid else ["M3"])
    lines.append("M30")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("seed", range(12))
def test_random_fanuc_taps_read_back_from_siemens_to_the_same_toolpath(seed: int) -> None:
    text = _random_taps(seed)
    out = _translate(text, "siemens", source="fanuc")
    assert "M29" not in out.replace(";M29", ""), out
    if "M29" in text or "G94" in text and "G99" in text:  # a rigid tap, or a floating one under G94 and G99
        assert "CYCLE84" in out, out
    _verify(text, out, "fanuc", "siemens")
    taps_in = [e for e in _events(text, "fanuc") if e[0] == "tap"]
    taps_out = [e for e in _events(out) if e[0] == "tap"]
    assert taps_in == taps_out and bool(taps_in) == ("M29" in text), (taps_in, taps_out)


def test_the_tapping_example_is_fanucs_rigid_tap_cycles_and_refused_by_grbl() -> None:
    path = Path(__file__).resolve().parents[1] / "examples" / "siemens" / "tapping.mpf"
    text = path.read_text(encoding="utf-8")
    setup = load_setup(str(path.parents[1] / "setups" / "siemens_840d_mill.xml"))
    out = _translate(text, "fanuc", setup=setup)
    assert out.count("S400 M29\nG99 G84 Z-12. R3. F600.\nG98 G80\n") == 3, out  # F = 1.5 x 400
    assert out.count("S300 M29\nG99 G74 Z-10. R3. F375.\nG80\n") == 1, out  # F = 1.25 x 300 (G99 in force)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target="fanuc", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0 and report.moves >= 20, report.summary()
    with pytest.raises(ErrorList) as caught:
        _translate(text, "grbl", setup=setup)
    assert [str(e).split(": error: ")[0] for e in caught.value.errors] == [f"in.mpf:{n}:1" for n in (13, 14, 15, 20)]
    assert all("rigid (spindle-synchronised) tap" in str(e) for e in caught.value.errors)


def test_the_floating_tap_example_is_fanucs_g84_and_the_moves_elsewhere() -> None:
    path = Path(__file__).resolve().parents[1] / "examples" / "siemens" / "floating_tap.mpf"
    text = path.read_text(encoding="utf-8")
    setup = load_setup(str(path.parents[1] / "setups" / "siemens_840d_mill.xml"))
    out = _translate(text, "fanuc", setup=setup)
    assert "N80 G99 G84 Z-14. R3. P300 K0\nN90 X35.\nN100 X35. Y35.\nN110 X15. Y35.\nN120 G80\n" in out, out
    for target in ("fanuc", "linuxcnc", "grbl"):
        made = out if target == "fanuc" else _translate(text, target, setup=setup)
        report = verify_lines(io.StringIO(text), io.StringIO(made), file_in="a", file_out="b", source="siemens",
                              target=target, setup=setup, tolerance=0.0)
        assert report.ok and report.max_deviation == 0 and report.moves >= 12, report.summary() + "\n" + made


_PARAMETER = st.one_of(st.none(), st.sampled_from([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, -1.5, 1.25, 500.0, 20.0, -10.0]))


@settings(max_examples=40, deadline=None)
@given(name=st.sampled_from(["CYCLE84", "CYCLE840"]), params=st.lists(_PARAMETER, min_size=4, max_size=14),
       modal=st.booleans())
def test_any_tap_call_is_copied_and_either_translates_exactly_or_is_refused_on_its_line(
        name: str, params: list[float | None], modal: bool) -> None:
    """Whatever its parameters: SINUMERIK gets the program back byte for byte (or the located error of a call
    that cannot run, an empty RTP...); Fanuc gets a translation that verifies at zero deviation, or located errors
    (never a traceback, never a silent change)."""
    call = f"{name}({', '.join('' if p is None else f'{p:g}' for p in params)})"
    text = START + "G1 F450\nG0\n" + (f"MCALL {call}\nX20\nMCALL\n" if modal else f"{call}\n") + "M30\n"
    try:
        assert _translate(text, "siemens") == text
    except ErrorList as err:
        assert all(str(e).startswith("in.mpf:") for e in err.errors), err.errors
    try:
        out = _translate(text, "fanuc")
    except ErrorList as err:
        assert all(str(e).startswith("in.mpf:") for e in err.errors), err.errors
        return
    _verify(text, out, "siemens", "fanuc")


LINUXCNC = "G21 G90 G17 G94\nG0 X10 Y10 Z5\nS400 M3\nG33.1 Z-10 K1.5\nG0 X20\nM4\nG33.1 Z-6 K1\nG0 Z20\nM30\n"


def test_linuxcnc_g33_1_is_cycle84_called_once_from_where_the_tool_stands() -> None:
    """G33.1 taps from the tool's Z 5 to Z and back at K a revolution, the spindle reversed at the bottom and again
    at the top: CYCLE84 once with RTP = RFP = 5, SDIS 0, SDAC the direction in force (M4: 4, a left-hand thread,
    PIT -1), SST = SST1 = S 400."""
    out = _translate(LINUXCNC, "siemens", source="linuxcnc")
    assert out.splitlines()[3:7] == ["CYCLE84(5., 5., 0, -10., , , 3, , 1.5, 0, 400, 400)", "G0 X20.", "M4",
                                     "CYCLE84(5., 5., 0, -6., , , 4, , -1., 0, 400, 400)"], out
    _verify(LINUXCNC, out, "linuxcnc", "siemens")
    with pytest.raises(ErrorList) as caught:
        _translate(LINUXCNC.replace("K1.5", "K1.5 I2"), "siemens", source="linuxcnc")
    assert "in.mpf:4:1: error: a rigid tap with a computed word or a faster way out" in str(caught.value.errors[0])
