"""SINUMERIK drilling cycles (``dialects/siemens/cycles.py``): called once and under ``MCALL``.

Every expected toolpath is worked out by hand from the manual's description of the cycle (PGZ 11/2006 2.1.2-2.1.10:
rapid from where the tool stands to RFP+SDIS, the work in the hole, back to RTP), never from the code: the
comments beside each give the arithmetic. Translations are checked by ``verify`` (toolpath equivalence) and,
for LinuxCNC, by its own interpreter (``examples/siemens/cycles.mpf`` runs in ``test_siemens_oracle``).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

ROOT = Path(__file__).resolve().parents[1]
START = "G710 G17 G90 G0 X5 Y5 Z50\nS800 M3\nG1 F100\nG0\n"
"""The tool at (5, 5, 50), the spindle turning clockwise, F100 in force, G0 in force."""


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, target: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, target)
    return [str(e) for e in caught.value.errors]


def _events(text: str) -> list[tuple[object, ...]]:
    """(move, x, y, z) of each motion, ("dwell", s), ("spindle", dir) and ("stop",) of each event."""
    out: list[tuple[object, ...]] = []
    for e in toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens"):
        if "move" in e:
            out.append((e["move"], e["x"], e["y"], e["z"]))
        elif e.get("event") == "dwell":
            out.append(("dwell", e["seconds"]))
        elif e.get("event") == "spindle":
            out.append(("spindle", e["dir"]))
        elif e.get("event") == "stop":
            out.append(("stop",))
    return out


def _after_start(text: str) -> list[tuple[object, ...]]:
    events = _events(START + text)
    assert events[:2] == [("rapid", 5, 5, 50), ("spindle", "cw")]
    return events[2:]


def _verify(text: str, target: str) -> None:
    out = _translate(text, target)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target=target, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out


# -- called once: every read cycle, hand-derived ------------------------------------------------------------

ONCE = [
    # CYCLE81: G0 to RFP+SDIS = 0+2, G1 to DP -5, G0 to RTP 10
    ("CYCLE81(10, 0, 2, -5)", [("rapid", 5, 5, 2), ("feed", 5, 5, -5), ("rapid", 5, 5, 10)]),
    # DPR: the depth is RFP - DPR = 1 - 4 = -3; RFP+SDIS = 1+3 = 4; RTP 4 is the R level
    ("CYCLE81(4, 1, 3, , 4)", [("rapid", 5, 5, 4), ("feed", 5, 5, -3), ("rapid", 5, 5, 4)]),
    # CYCLE82: as CYCLE81 with DTB 1.5 s at the depth
    ("CYCLE82(10, 0, 2, -5, , 1.5)", [("rapid", 5, 5, 2), ("feed", 5, 5, -5), ("dwell", 1.5), ("rapid", 5, 5, 10)]),
    # CYCLE82 with an empty DTB: no dwell
    ("CYCLE82(10, 0, 2, -5)", [("rapid", 5, 5, 2), ("feed", 5, 5, -5), ("rapid", 5, 5, 10)]),
    # CYCLE85: G1 in at FFR 100, G1 out at RFF 100 to RFP+SDIS 2, G0 to RTP 12
    ("CYCLE85(12, 0, 2, -6, , , 100, 100)", [("rapid", 5, 5, 2), ("feed", 5, 5, -6), ("feed", 5, 5, 2),
                                             ("rapid", 5, 5, 12)]),
    # CYCLE85 with DTB 0.5 s at the depth
    ("CYCLE85(12, 0, 2, -6, , 0.5, 100, 100)", [("rapid", 5, 5, 2), ("feed", 5, 5, -6), ("dwell", 0.5),
                                                ("feed", 5, 5, 2), ("rapid", 5, 5, 12)]),
    # CYCLE89: G1 to -6, dwell 0.25 s, G1 out to 2 at the same F, G0 to RTP 30
    ("CYCLE89(30, 0, 2, -6, , 0.25)", [("rapid", 5, 5, 2), ("feed", 5, 5, -6), ("dwell", 0.25), ("feed", 5, 5, 2),
                                       ("rapid", 5, 5, 30)]),
    # CYCLE87: G1 to -8, M5, M0, G0 to RTP 20, spindle in SDIR 3 (M3)
    ("CYCLE87(20, 0, 2, -8, , 3)", [("rapid", 5, 5, 2), ("feed", 5, 5, -8), ("spindle", "stop"), ("stop",),
                                    ("rapid", 5, 5, 20), ("spindle", "cw")]),
    # CYCLE88: as CYCLE87 with DTB 2 s before M5
    ("CYCLE88(20, 0, 2, -8, , 2, 3)", [("rapid", 5, 5, 2), ("feed", 5, 5, -8), ("dwell", 2), ("spindle", "stop"),
                                       ("stop",), ("rapid", 5, 5, 20), ("spindle", "cw")]),
]


@pytest.mark.parametrize("call, moves", ONCE, ids=[c for c, _ in ONCE])
def test_a_cycle_called_once_drills_where_the_tool_stands_and_ends(call: str, moves: list[tuple[object, ...]]) -> None:
    # after the cycle no cycle is active: X30 is a plain G0 move at the level the cycle left
    end_z = [m for m in moves if m[0] in ("rapid", "feed")][-1][3]
    assert _after_start(f"{call}\nX30\nM30\n") == [*moves, ("rapid", 30, 5, end_z)]


@pytest.mark.parametrize("call", [c for c, _ in ONCE])
@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_a_cycle_called_once_translates_exactly_and_reads_back(call: str, target: str) -> None:
    text = f"{START}{call}\nX30\nG1 X40\nM30\n"
    assert _translate(text, "siemens") == text
    _verify(text, target)


def test_a_cycle_called_once_is_expanded_for_fanuc_and_cancels_nothing_after_it() -> None:
    out = _translate(f"{START}CYCLE81(10, 0, 2, -5)\nX30\nM30\n", "fanuc")
    assert "G81" not in out and "G80" not in out
    assert "\nX30.\n" in out or "\nG00 X30.\n" in out


def test_the_motion_mode_before_a_cycle_is_in_force_after_it() -> None:
    # G1 is in force: the cycle positions at rapid itself, and X30 after it feeds
    events = _after_start("G1 X10\nCYCLE81(10, 0, 2, -5)\nX30\nM30\n")
    assert events == [("feed", 10, 5, 50), ("rapid", 10, 5, 2), ("feed", 10, 5, -5), ("rapid", 10, 5, 10),
                      ("feed", 30, 5, 10)]


# -- MCALL: every read cycle, hand-derived -----------------------------------------------------------------

MODAL = (START
         + "MCALL CYCLE85(50, 0, 3, , 10, , 100, 100)\nX10 Y10\nX20\nMCALL\n"
         + "MCALL CYCLE89(3, 0, 3, -10, , 0.75)\nX30\nMCALL\n"
         + "MCALL CYCLE88(3, 0, 3, -12, , 2, 3)\nX40\nMCALL\n"
         + "G0 Z20\nMCALL CYCLE87(20, 0, 3, -12, , 3)\nX50\nMCALL\nM30\n")


def test_mcall_cycles_drill_at_each_position_as_the_manual_describes() -> None:
    assert _after_start(MODAL[len(START):]) == [
        # CYCLE85, RTP 50 = the Z at MCALL: R = 0+3, depth 0-10 = -10, feed in and out, G0 to 50
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 3), ("feed", 10, 10, -10), ("feed", 10, 10, 3), ("rapid", 10, 10, 50),
        ("rapid", 20, 10, 50), ("rapid", 20, 10, 3), ("feed", 20, 10, -10), ("feed", 20, 10, 3), ("rapid", 20, 10, 50),
        # CYCLE89 from Z50, RTP 3 = RFP+SDIS: G0 down to 3 after the position, dwell, feed out to 3
        ("rapid", 30, 10, 50), ("rapid", 30, 10, 3), ("feed", 30, 10, -10), ("dwell", 0.75), ("feed", 30, 10, 3),
        # CYCLE88 (RTP 3): at Z3, to -12, dwell 2, M5, M0, G0 to 3, M3
        ("rapid", 40, 10, 3), ("feed", 40, 10, -12), ("dwell", 2), ("spindle", "stop"), ("stop",),
        ("rapid", 40, 10, 3), ("spindle", "cw"),
        ("rapid", 40, 10, 20),
        # CYCLE87 (RTP 20 = the Z at MCALL)
        ("rapid", 50, 10, 20), ("rapid", 50, 10, 3), ("feed", 50, 10, -12), ("spindle", "stop"), ("stop",),
        ("rapid", 50, 10, 20), ("spindle", "cw")]


def test_mcall_cycles_are_fanuc_cycles_natively() -> None:
    # R = RFP+SDIS, Z = the depth, P = DTB in ms; G98 where RTP is the Z at MCALL, G99 where it is R
    out = _translate(MODAL, "fanuc")
    assert "G98 G85 Z-10. R3. K0\nX10. Y10.\nX20.\nG80\n" in out
    assert "G99 G89 Z-10. R3. P750 K0\nX30.\nG80\n" in out
    assert "G99 G88 Z-12. R3. P2000 K0\nX40.\nG80\n" in out
    assert "G98 G88 Z-12. R3. K0\nX50.\nG80\n" in out


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "siemens"])
def test_mcall_cycles_translate_exactly(target: str) -> None:
    if target == "siemens":
        assert _translate(MODAL, target) == MODAL
    else:
        _verify(MODAL, target)


# -- what is kept verbatim, and what is refused -------------------------------------------------------------

@pytest.mark.parametrize("line, name", [
    ("CYCLE83(10, 0, 0, -20, , -5, , 2, 0, 0, 1, 1, , , , , 0.5)", "CYCLE83 with DAM"),
    ("CYCLE84(10, 0, 2, -20, , 0, 3, , 1.25, 0, 400, 400)", "CYCLE84 with SST 400 other than the S in force"),
    ("CYCLE840(10, 0, 2, -20, , 0, 0, 3, 1, , 1.25)", "CYCLE840 with a lead MPIT/PIT"),
    ("CYCLE86(10, 0, 2, -20, , 0, 3, 0.1, 0, 0, 0)", "CYCLE86 (its lift-off RPA/RPO/RPAP"),
    ("MCALL CYCLE83(10, 0, 2, -20, , -5, , 0, 0, 0, 1, 1, , , , , 0.5)", "MCALL CYCLE83 with SDIS other than 0"),
    ("CYCLE87(20, 0, 2, -8, , 4)", "CYCLE87 with SDIR 4"),
    ("CYCLE88(20, 0, 2, -8, , 2)", "CYCLE88 with SDIR empty"),
    ("CYCLE85(12, 0, 2, -6, , , 100, 200)", "CYCLE85 with RFF other than FFR"),
    ("CYCLE85(12, 0, 2, -6, , , 300, 300)", "CYCLE85 with FFR 300 other than the F in force"),
    ("CYCLE81(R1, 0, 2, -5)", "CYCLE81 with computed parameters"),
    ("CYCLE81(10, 0, 2, -5, , 0, 1, 0)", "CYCLE81 with parameters after DPR"),
])
def test_an_unconfirmed_cycle_is_kept_verbatim_and_refused_elsewhere_by_name(line: str, name: str) -> None:
    text = f"{START}R1=10\n{line}\nM30\n"
    assert _translate(text, "siemens") == text
    for target in ("fanuc", "linuxcnc"):
        assert name in _errors(text, target)[0]


def test_a_cycle_called_once_under_mcall_is_kept_verbatim() -> None:
    text = f"{START}MCALL CYCLE81(50, 0, 2, -5)\nX10\nCYCLE82(50, 0, 2, -5, , 1)\nMCALL\nM30\n"
    assert _translate(text, "siemens") == text
    assert "CYCLE82 called once under MCALL" in _errors(text, "fanuc")[0]


@pytest.mark.parametrize("line, message", [
    ("CYCLE81(10, 0, 2, -5) X5", "5:23: error: CYCLE81(..) is alone in its block"),
    ("CYCLE81(10, 0, 2, -5", "5:21: error: ',' or ')' expected in CYCLE81(..)"),
    ("CYCLE81(10, 0, , -5)", "5:1: error: CYCLE81: SDIS is empty"),
    ("CYCLE81(10, 0, 2)", "5:1: error: CYCLE81: give exactly one of DP and DPR"),
    ("CYCLE81(10, 0, 2, -5, 5)", "give exactly one of DP and DPR"),
    ("CYCLE81(10, 0, -2, -5)", "SDIS and DPR have no sign"),
    ("CYCLE81(10, 0, 2, 5)", "the final depth 5 is above RFP+SDIS (2)"),
    ("CYCLE82(10, 0, 2, -5, , 0.0004)", "DTB is a dwell of whole milliseconds here, not 0.0004"),
    ("CYCLE85(12, 0, 2, -6)", "CYCLE85 needs its feeds FFR (in) and RFF (out)"),
    ("CYCLE81(" + ",".join(["1"] * 100) + ")", "CYCLE81(..) has more than 64 parameters"),
    ("CYCLE81(" + "(" * 400 + "1" + ")" * 400 + ", 0, 2, -5)", "nested deeper than"),
    ("G91\nCYCLE81(10, 0, 2, -5)", "CYCLE81 is read in G17 and G90 only"),
    ("G18\nCYCLE81(10, 0, 2, -5)", "CYCLE81 is read in G17 and G90 only"),
])
def test_bad_cycle_calls_are_located_errors(line: str, message: str) -> None:
    errors = _errors(f"{START}{line}\nM30\n", "linuxcnc")
    assert any(message in e for e in errors), errors


# -- properties --------------------------------------------------------------------------------------------

_LEVEL = st.integers(-50, 50).map(lambda n: n / 4)
_POSITIVE = st.integers(0, 40).map(lambda n: n / 4)


@settings(max_examples=40, deadline=None)
@given(rfp=_LEVEL, sdis=_POSITIVE, depth=st.integers(1, 80).map(lambda n: n / 4), above=_POSITIVE,
       dtb=st.one_of(st.none(), st.integers(0, 3000)), relative=st.booleans())
def test_any_drilling_call_once_moves_to_r_cuts_to_the_depth_and_rises_to_rtp(
        rfp: float, sdis: float, depth: float, above: float, dtb: int | None, relative: bool) -> None:
    rtp = rfp + sdis + above
    dp = f", {depth}" if relative else f"{rfp - depth}, "  # DP and an empty DPR, or an empty DP and DPR
    call = (f"CYCLE81({rtp}, {rfp}, {sdis}, {dp})" if dtb is None
            else f"CYCLE82({rtp}, {rfp}, {sdis}, {dp}, {dtb / 1000})")
    text = f"G710 G17 G90 G0 X1 Y2 Z60\nG1 F80\n{call}\nM30\n"
    assert _translate(text, "siemens") == text
    expected: list[tuple[object, ...]] = [("rapid", 1, 2, 60)]
    if rfp + sdis != 60:
        expected.append(("rapid", 1, 2, rfp + sdis))
    expected.append(("feed", 1, 2, rfp - depth))
    if dtb:  # DTB 0 (or empty) dwells not at all
        expected.append(("dwell", dtb / 1000))
    expected.append(("rapid", 1, 2, rtp))
    _close(_events(text), expected)


def _close(ours: list[tuple[object, ...]], expected: list[tuple[object, ...]]) -> None:
    """The same events, coordinates within 1e-6 (the toolpath writes 6 decimals)."""
    assert len(ours) == len(expected), (ours, expected)
    for a, b in zip(ours, expected):
        assert a[0] == b[0], (ours, expected)
        assert all(abs(float(str(x)) - float(str(y))) < 1e-6 for x, y in zip(a[1:], b[1:])), (ours, expected)


# -- HOLES1 / HOLES2 under MCALL ---------------------------------------------------------------------------

HOLES = (START + "MCALL CYCLE81(50, 0, 2, -5)\nHOLES1(10, 10, 30, 4, 6, 3)\nHOLES2(60, 40, 10, 90, 0, 4)\n"
         "HOLES2(60, 40, 10, 0, -45, 2)\nMCALL\nM30\n")


def _drill(x: float, y: float) -> list[tuple[object, ...]]:
    """CYCLE81(50, 0, 2, -5) at (x, y) from Z50: over the hole, G0 to 2, G1 to -5, G0 to 50."""
    return [("rapid", x, y, 50), ("rapid", x, y, 2), ("feed", x, y, -5), ("rapid", x, y, 50)]


def test_holes1_and_holes2_run_the_modal_cycle_at_hand_derived_points() -> None:
    c30, s30 = 3 ** 0.5 / 2, 0.5
    h = 0.5 ** 0.5 * 10
    expected = (
        # HOLES1: from (10, 10) at 30 degrees, 4 to the first hole, 6 between: distances 4, 10, 16
        _drill(10 + 4 * c30, 10 + 4 * s30) + _drill(10 + 10 * c30, 10 + 10 * s30) + _drill(10 + 16 * c30, 10 + 16 * s30)
        # HOLES2: centre (60, 40), radius 10, from 90 degrees, INDA 0: 4 holes 90 degrees apart (counter-clockwise)
        + _drill(60, 50) + _drill(50, 40) + _drill(60, 30) + _drill(70, 40)
        # INDA -45: from 0 degrees clockwise; the first hole is where the tool stands (no move over it)
        + _drill(70, 40)[1:] + _drill(60 + h, 40 - h))
    _close(_after_start(HOLES[len(START):]), expected)


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "siemens"])
def test_hole_patterns_translate_exactly(target: str) -> None:
    if target == "siemens":
        assert _translate(HOLES, target) == HOLES
    else:
        _verify(HOLES, target)


@pytest.mark.parametrize("lines, name", [
    ("HOLES1(10, 10, 0, 5, 10, 3)", "HOLES1 without an active MCALL cycle"),
    ("MCALL CYCLE81(50, 0, 2, -5)\nHOLES1(-40, 5, 0, 5, 10, 3)", "HOLES1 with the tool not nearer its first hole"),
    ("MCALL CYCLE83(50, 0, 2, -20, , -5, , 2, 0, 0, 1, 1)\nHOLES2(60, 40, 10, 90, 0, 4)",
     "MCALL CYCLE83 with SDIS other than 0"),
])
def test_a_pattern_that_is_not_read_is_kept_verbatim(lines: str, name: str) -> None:
    text = f"{START}{lines}\nMCALL\nM30\n"
    assert _translate(text, "siemens") == text
    assert name in _errors(text, "linuxcnc")[0]


@pytest.mark.parametrize("line, message", [
    ("HOLES1(10, 10, 0, 5, 10)", "6:1: error: HOLES1 takes its 6 parameters, each given"),
    ("HOLES1(10, 10, 0, , 10, 3)", "HOLES1 takes its 6 parameters, each given"),
    ("HOLES1(10, 10, 0, 5, 10, 2.5)", "NUM is a whole number of holes from 1 to 10000, not 2.5"),
    ("HOLES2(60, 40, 10, 0, 0, 0)", "NUM is a whole number of holes from 1 to 10000, not 0"),
    ("HOLES2(60, 40, 10, 0, 0, 1EX9)", "NUM is a whole number of holes from 1 to 10000"),
    ("HOLES1(10, 10, 0, -5, 10, 3)", "HOLES1: FDIS and DBH have no sign"),
    ("HOLES2(60, 40, 0, 0, 0, 3)", "HOLES2: the radius RAD is positive"),
])
def test_a_bad_pattern_call_is_a_located_error(line: str, message: str) -> None:
    errors = _errors(f"{START}MCALL CYCLE81(50, 0, 2, -5)\n{line}\nMCALL\nM30\n", "linuxcnc")
    assert any(message in e for e in errors), errors


def test_the_moves_of_a_pattern_are_bounded_by_the_set_up(tmp_path: Path) -> None:
    from postproc.setup.machine_setup import load_setup
    path = tmp_path / "limits.xml"
    path.write_text('<MachineSetup><Limits movesPerBlock="100"/></MachineSetup>')
    text = f"{START}MCALL CYCLE81(50, 0, 2, -5)\nHOLES2(60, 40, 10, 0, 0, 30)\nMCALL\nM30\n"
    out = io.StringIO()
    with pytest.raises(ErrorList) as caught:  # 30 holes of 4 moves: 120 moves
        translate(io.StringIO(text), out, file="in.mpf", source="siemens", target="linuxcnc",
                  setup=load_setup(str(path)), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert "6:1: error: HOLES2: 30 holes make more than 100 moves in one block" in str(caught.value.errors[0])


def test_the_siemens_cycle_sections_are_xml_serialisable_through_the_registry() -> None:
    from postproc.plugins import default_registry
    from postproc.xmlio import DEFAULT

    from dialects.siemens.cycles import CycleLevels, SiemensCycleEnd
    from dialects.siemens.holes import SiemensHoles
    default_registry()
    for node in (CycleLevels(10.0, 2.0, True, 100.0, "CYCLE85"), SiemensHoles("HOLES2", 1.0, 2.0, 3.0, 4.0, 5.0, 6),
                 SiemensCycleEnd()):
        assert DEFAULT.create(node.make_xml_source()) == node
