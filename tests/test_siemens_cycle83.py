"""SINUMERIK ``CYCLE83`` (deep-hole drilling, ``dialects/siemens/deep_hole.py``) both ways.

Expected toolpaths are worked out by hand from the manual's sequence for swarf removal (PGZ 11/2006 2.1.4: G0 to
RFP+SDIS, G1 to the first depth, G0 back to RFP+SDIS, G0 to the depth reached less the anticipation distance
_DIS1, G1 to the next depth, ..., G0 to RTP); the comments beside each give the arithmetic. Fanuc's G83 is read
back from SINUMERIK and checked by ``verify`` (toolpath equivalence) on seeded random programs; LinuxCNC runs the
example ``examples/siemens/deep_hole.mpf`` in ``test_siemens_oracle``.
"""

from __future__ import annotations

import io
import random
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

ROOT = Path(__file__).resolve().parents[1]
ZERO_TOOLS = ROOT / "tests" / "support" / "zero_tools.xml"
START = "G710 G17 G90 G0 X5 Y5 Z50\nS800 M3\nG1 F100\nG0\n"
"""The tool at (5, 5, 50), F100 in force, G0 in force (the set-up's G83 clearance d is the default 0.5 mm)."""
DEEP = "MCALL CYCLE83(50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1, , , , , 0.5)\nX10 Y10\nX20\nMCALL\nM30\n"


def _setup(tmp: Path | None = None, clearance: float | None = None) -> MachineSetup:
    if clearance is None or tmp is None:
        return load_setup(str(ZERO_TOOLS))
    path = tmp / "setup.xml"
    path.write_text(f'<MachineSetup name="t" extends="{ZERO_TOOLS}"><Cycles peckClearance="{clearance}"/>'
                    '</MachineSetup>')
    return load_setup(str(path))


def _translate(text: str, source: str, target: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source=source, target=target,
              setup=setup or _setup(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, target: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, "siemens", target)
    return [str(e) for e in caught.value.errors]


def _verify(text: str, source: str, target: str, setup: MachineSetup | None = None) -> str:
    out = _translate(text, source, target, setup)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source=source,
                          target=target, setup=setup or _setup(), tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out
    return out


def _moves(text: str, dialect: str = "siemens") -> list[tuple[str, float, float, float]]:
    return [(e["move"], float(e["x"]), float(e["y"]), float(e["z"]))
            for e in toolpath_events(io.StringIO(text), file="in", dialect=dialect, setup=_setup()) if "move" in e]


def _hole(x: float, y: float) -> list[tuple[str, float, float, float]]:
    """CYCLE83(50, 0, 0, -12, , -4, ...) at (x, y) from Z50: strokes of 4 from RFP 0 (FDEP -4), d 0.5."""
    return [("rapid", x, y, 50), ("rapid", x, y, 0),
            ("feed", x, y, -4), ("rapid", x, y, 0), ("rapid", x, y, -3.5),  # -4 + 0.5
            ("feed", x, y, -8), ("rapid", x, y, 0), ("rapid", x, y, -7.5),  # -8 + 0.5
            ("feed", x, y, -12), ("rapid", x, y, 50)]                       # the final depth, G0 to RTP 50


def test_mcall_cycle83_drills_in_strokes_with_swarf_removal_as_the_manual_describes() -> None:
    assert _moves(START + DEEP)[1:] == _hole(10, 10) + _hole(20, 10)


def test_cycle83_called_once_with_fdpr_drills_where_the_tool_stands() -> None:
    # RFP 2, DPR 9: the depth is 2 - 9 = -7; FDPR 3: the first depth is -1, strokes of 3; RTP 10
    moves = _moves(START + "CYCLE83(10, 2, 0, , 9, , 3, 0, 0, 0, 1, 1, , , , 0, 0.5)\nM30\n")
    assert moves[1:] == [("rapid", 5, 5, 2), ("feed", 5, 5, -1), ("rapid", 5, 5, 2), ("rapid", 5, 5, -0.5),
                         ("feed", 5, 5, -4), ("rapid", 5, 5, 2), ("rapid", 5, 5, -3.5), ("feed", 5, 5, -7),
                         ("rapid", 5, 5, 10)]


def test_mcall_cycle83_is_fanucs_g83_natively() -> None:
    # RTP 50 is the Z at MCALL: G98; R = RFP+SDIS = 0; Z = DP; Q = the stroke 4
    assert "G98 G83 Z-12. R0. Q4. K0\nX10. Y10.\nX20.\nG80\n" in _translate(START + DEEP, "siemens", "fanuc")


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "siemens"])
def test_mcall_cycle83_translates_exactly(target: str) -> None:
    if target == "siemens":
        assert _translate(START + DEEP, "siemens", target) == START + DEEP
    else:
        _verify(START + DEEP, "siemens", target)


def test_an_anticipation_distance_other_than_the_set_ups_is_each_holes_own(tmp_path: Path) -> None:
    """_DIS1 is the cycle's d. Fanuc's G83 takes the set-up's (a machine parameter): where _DIS1 is another,
    every other dialect gets the holes' exact moves with it (here d = 0.3: back down to -4 + 0.3 = -3.7)."""
    text = START + DEEP.replace(", 0.5)", ", 0.3)")
    assert _translate(text, "siemens", "siemens") == text
    assert _moves(text)[1:4] == [("rapid", 10, 10, 50), ("rapid", 10, 10, 0), ("feed", 10, 10, -4)]
    assert _moves(text)[5] == ("rapid", 10, 10, -3.7)
    out = _verify(text, "siemens", "fanuc")
    assert "G83" not in out and "G00 Z-3.7" in out, out
    out = _verify(text, "siemens", "fanuc", _setup(tmp_path, 0.3))
    assert "G98 G83 Z-12. R0. Q4. K0" in out


def test_a_g83_with_another_clearance_than_the_set_ups_is_written_with_it(tmp_path: Path) -> None:
    """A Fanuc-family source whose G83 clearance is its own (grblHAL's fixed 0.1 mm) towards a set-up whose
    SINUMERIK takes 0.5: the lowering expands it (the clearances differ)."""
    text = "G21 G90 G17\nG0 X0. Y0. Z20.\nG99 G83 X10. Y5. Z-10. R2. Q4. F120.\nX20.\nG80\nM30\n"
    out = _verify(text, "grblhal", "siemens")
    assert "CYCLE83" not in out, out


@pytest.mark.parametrize("params, name", [
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, 0, , , 1, , 0.5", "CYCLE83 with VARI 0"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, , , , , , 0.5", "CYCLE83 with VARI empty"),
    ("50, 0, 2, -12, , -4, , 0, 0, 0, 1, 1, , , , , 0.5", "CYCLE83 with SDIS other than 0"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 0.5, 1, , , , , 0.5", "CYCLE83 with FRF other than 1"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, , 1, , , , , 0.5", "CYCLE83 with FRF other than 1"),
    ("50, 0, 0, -12, , -4, , 1, 0, 0, 1, 1, , , , , 0.5", "CYCLE83 with DAM"),
    ("50, 0, 0, -12, , -4, , 0, 0.5, 0, 1, 1, , , , , 0.5", "CYCLE83 with DTB"),
    ("50, 0, 0, -12, , -4, , 0, 0, 1, 1, 1, , , , , 0.5", "CYCLE83 with DTS"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1, , , , 2, 0.5", "CYCLE83 with _DTD"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1, 1, , , , 0.5", "CYCLE83 with _AXN other than 3"),
    ("50, 0, 0, -12, , -4, 4, 0, 0, 0, 1, 1, , , , , 0.5", "CYCLE83 without exactly one of FDEP and FDPR"),
    ("50, 0, 0, -12, , , , 0, 0, 0, 1, 1, , , , , 0.5", "CYCLE83 without exactly one of FDEP and FDPR"),
    ("50, 0, 0, -12, , -5, , 0, 0, 0, 1, 1, , , , , 0.5", "CYCLE83 whose depth 12 is not a whole number"),
    ("50, 0, 0, -12, , -14, , 0, 0, 0, 1, 1, , , , , 0.5", "CYCLE83 whose first depth is not between"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1, , 5, , , 0.5", "CYCLE83 with _MDEP above its stroke"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1, , , , , 0", "CYCLE83 with _DIS1 empty or 0"),
    ("50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1", "CYCLE83 with _DIS1 empty or 0"),
])
def test_an_unconfirmed_cycle83_is_kept_verbatim_and_refused_elsewhere_by_name(params: str, name: str) -> None:
    for once in (True, False):
        text = START + ("" if once else "MCALL ") + f"CYCLE83({params})\n" + ("" if once else "X10\nMCALL\n") + "M30\n"
        assert _translate(text, "siemens", "siemens") == text
        for target in ("fanuc", "linuxcnc"):
            errors = _errors(text, target)
            assert ("" if once else "MCALL ") + name in errors[0], errors


def test_cycle83_with_more_parameters_than_its_seventeen_is_kept_verbatim() -> None:
    text = START + "CYCLE83(50, 0, 0, -12, , -4, , 0, 0, 0, 1, 1, , , , , 0.5, 0, 0, 1001110)\nM30\n"
    assert _translate(text, "siemens", "siemens") == text
    assert "CYCLE83 with parameters after _DIS1" in _errors(text, "fanuc")[0]


# -- Fanuc G83 written as MCALL CYCLE83 --------------------------------------------------------------------

G83_ROW = "G21 G90 G17\nG0 X0. Y0. Z20.\nG99 G83 X10. Y5. Z-10. R2. Q4. F120.\nX20.\nG80\nG0 Z20.\nM30\n"


def test_g83_is_mcall_cycle83_with_the_first_stroke_and_the_set_ups_clearance() -> None:
    # RTP = R = 2 (G99), RFP 2, SDIS 0, DP -10, FDEP = R - Q = -2, DAM/DTB/DTS 0, FRF 1, VARI 1, _DTD 0, _DIS1 0.5
    out = _translate(G83_ROW, "fanuc", "siemens")
    assert out.splitlines()[3:7] == ["G0", "MCALL CYCLE83(2., 2., 0, -10., , -2., , 0, 0, 0, 1, 1, , , , 0, 0.5)",
                                     "X10. Y5.", "X20."], out
    back = _verify(out, "siemens", "fanuc")
    assert "G99 G83 Z-10. R2. Q4. K0" in back
    _verify(G83_ROW, "fanuc", "siemens")


def test_g83_whose_depth_is_no_whole_number_of_pecks_is_expanded() -> None:
    text = G83_ROW.replace("Q4.", "Q5.")  # 12 deep
    out = _verify(text, "fanuc", "siemens")
    assert "CYCLE83" not in out and " from line " in out, out


def test_a_g83_peck_deeper_than_the_hole_is_one_stroke() -> None:
    text = G83_ROW.replace("Q4.", "Q30.")
    out = _verify(text, "fanuc", "siemens")
    assert "MCALL CYCLE83(2., 2., 0, -10., , -10., , 0, 0, 0, 1, 1, , , , 0, 0.5)" in out, out


def test_a_g83_hole_where_the_tool_stands_is_written_as_its_pecks() -> None:
    """Fanuc's G83 at X0 Y0 from there: rapid to R 2, feed -2, rapid 2, rapid -1.5, feed -6, ..., rapid to 20."""
    text = "G21 G90 G17\nG0 X0. Y0. Z20.\nG98 G83 Z-10. R2. Q4. F100.\nX5.\nG80\nM30\n"
    out = _verify(text, "fanuc", "siemens")
    assert "G0 Z2.\nG1 Z-2.\nG0 Z2.\nG0 Z-1.5\nG1 Z-6.\nG0 Z2.\nG0 Z-5.5\nG1 Z-10.\nG0 Z20.\n" in out, out
    assert "MCALL CYCLE83(20., 2., 0, -10., , -2., , 0, 0, 0, 1, 1, , , , 0, 0.5)\nX5.\nMCALL\n" in out, out


def test_a_linuxcnc_g83_keeps_its_own_clearance_by_expanding() -> None:
    """LinuxCNC's d is fixed (0.254 mm), the set-up's SINUMERIK one 0.5: no CYCLE83 can say LinuxCNC's."""
    text = "G21 G90 G17\nG0 X0. Y0. Z20.\nG99 G83 X10. Y5. Z-10. R2. Q4. F120.\nX20.\nG80\nM30\n"
    out = _verify(text, "linuxcnc", "siemens")
    assert "CYCLE83" not in out, out


def _random_pecks(rng: random.Random) -> tuple[str, int]:
    lines, native = ["G21 G90 G17", f"G0 X0. Y0. Z{rng.randint(10, 40)}."], 0
    for _ in range(rng.randint(1, 3)):
        r, q = rng.randint(0, 5), rng.choice([1.5, 2., 2.5, 4.])
        whole = rng.random() < 0.7
        count = rng.randint(1, 6)
        z = r - q * count - (0 if whole else 0.75)
        x, y = rng.randint(-50, 50), rng.randint(-50, 50)
        lines.append(f"{rng.choice(['G98', 'G99'])} G83 X{x}. Y{y}. Z{z:.3f} R{r}. Q{q:.3f} F{rng.randint(50, 400)}.")
        for _ in range(rng.randint(1, 4)):
            x, y = x + rng.randint(1, 30), y + rng.choice([0, rng.randint(-20, 20)])
            lines.append(f"X{x}. Y{y}.")
        lines += ["G80", f"G0 Z{rng.randint(10, 40)}."]
        native += whole
    return "\n".join(lines + ["M30"]) + "\n", native


def test_random_g83_programs_read_back_from_siemens_to_the_same_toolpath() -> None:
    rng = random.Random(2883)
    for _ in range(25):
        text, native = _random_pecks(rng)
        out = _verify(text, "fanuc", "siemens")
        assert out.count("MCALL CYCLE83(") == native, (text, out)
        _verify(out, "siemens", "fanuc")


def test_a_stroke_so_small_the_pecks_pass_the_set_ups_bound_is_a_located_error() -> None:
    text = START + "MCALL CYCLE83(50, 0, 0, -10, , -0.0001, , 0, 0, 0, 1, 1, , , , , 0.5)\nX10\nMCALL\nM30\n"
    errors = _errors(text, "linuxcnc")
    assert errors[0].startswith("in.mpf:6:1: error: CYCLE83: the expansion makes more than 100000 moves in one block"), \
        errors


def test_an_inch_g83_reads_back_with_its_clearance_written_to_8_decimals(tmp_path: Path) -> None:
    """0.3 mm is 0.011811023... inch, written 0.01181102: read back as the set-up's clearance."""
    setup = _setup(tmp_path, 0.3)
    text = "G20 G90 G17\nG0 X0. Y0. Z1.\nG99 G83 X1. Y0.5 Z-0.4 R0.1 Q0.25 F10.\nX2.\nG80\nM30\n"
    out = _verify(text, "fanuc", "siemens", setup)
    assert "MCALL CYCLE83(0.1, 0.1, 0, -0.4, , -0.15, , 0, 0, 0, 1, 1, , , , 0, 0.01181102)" in out, out
    assert "G99 G83 Z-0.4 R0.1 Q0.25 K0" in _verify(out, "siemens", "fanuc", setup)
