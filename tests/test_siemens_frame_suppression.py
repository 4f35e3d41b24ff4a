"""SINUMERIK ``G53``/``G153``/``SUPA`` (``dialects/siemens/frame_suppression.py``): read as a rapid move in
machine coordinates where the tool offsets cannot matter (no length, no radius compensation: whether they stay
is machine data), kept verbatim and refused elsewhere by name otherwise.

Expected points are worked out by hand: ``TRANS X2 Y3`` moves the programmable frame, which a suppressed block
does not apply (the set-up has no work offset: machine and work positions are the same numbers; the toolpath
takes work offsets as settings, not as positions).
"""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

TOOLS = '<Tool number="1" length="0.0" radius="0.0"/><Tool number="2" length="75.0" radius="4.0"/>'
START = "G710 G17 G90 G54 G0 X5 Y5 Z5\nTRANS X2 Y3\n"


def _setup(tmp_path: Path) -> MachineSetup:
    path = tmp_path / "machine.xml"
    path.write_text(f'<MachineSetup name="t"><Tools>{TOOLS}</Tools></MachineSetup>')
    return load_setup(path)


def _translate(text: str, target: str, setup: MachineSetup) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _moves(text: str, setup: MachineSetup) -> list[tuple[str, float, float, float]]:
    return [(e["move"], float(e["x"]), float(e["y"]), float(e["z"]))
            for e in toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens", setup=setup) if "move" in e]


@pytest.mark.parametrize("line", ["G53 G0 X20 Y20", "G153 X20 Y20", "SUPA G0 X20 Y20", "G0 SUPA X20 Y20",
                                  "G0 G53 X20 Y20"])
def test_a_block_without_frames_goes_to_the_machine_position(line: str, tmp_path: Path) -> None:
    """X20 Y20 without TRANS X2 Y3 (with it: X22 Y23); Z stays; the frame applies again to the next block
    (G0 X1: X 1 + 2 = 3)."""
    setup = _setup(tmp_path)
    moves = _moves(START + line + "\nG0 X1\nM30\n", setup)
    assert moves[1:] == [("rapid", 20, 20, 5), ("rapid", 3, 20, 5)]


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_a_block_without_frames_translates_exactly(target: str, tmp_path: Path) -> None:
    setup = _setup(tmp_path)
    text = START + "T1 D1 M6\nG53 G0 Z0\nSUPA X20 Y20\nG0 X1 Y1\nM30\n"
    out = _translate(text, target, setup)
    assert "G53" in out, out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target=target, setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


@pytest.mark.parametrize("lines, why", [
    ("G1 F100\nG53 X0", "G53 (frame suppression) in G1"),
    ("G53 G1 X0 F100", "G53 (frame suppression) in G1"),
    ("G91 G53 Z-2", "G53 (frame suppression) in G91"),
    ("G53 G0 X1 I2", "G53 (frame suppression) with interpolation parameters I, J, K"),
    ("T2 D2 M6\nG53 G0 Z0", "G53 (frame suppression) with the length of D2 in force"),
    ("G53 G0 Z0 D1", "G53 (frame suppression) selecting tool data"),
    ("G1 G41 X10 F100\nG0\nG153 X0", "G153 (frame suppression) under radius compensation"),
])
def test_a_block_without_frames_whose_meaning_is_machine_data_is_kept_verbatim(lines: str, why: str,
                                                                            tmp_path: Path) -> None:
    setup = _setup(tmp_path)
    text = START + lines + "\nM30\n"
    assert _translate(text, "siemens", load_setup_plain()) == text
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc", setup)
    assert any(why in str(e) for e in caught.value.errors), [str(e) for e in caught.value.errors]


def load_setup_plain() -> MachineSetup:
    """A set-up with no travel or tools to check: SINUMERIK to SINUMERIK copies the verbatim block."""
    return load_setup(str(Path(__file__).resolve().parent / "support" / "zero_tools.xml"))


# -- Fanuc G53 written as SUPA ---------------------------------------------------------------------------------

def _from_fanuc(text: str, setup: MachineSetup) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target="siemens", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def test_fanuc_g53_is_supa_where_no_tool_offset_is_in_force_and_reads_back(tmp_path: Path) -> None:
    """SUPA leaves out every frame and offset (the neutral machine coordinates); G49 is D0 (no length), and tool
    1 is 0 long, so D1 brings none either."""
    setup = _setup(tmp_path)
    text = ("G21 G90 G17 G0 X5. Y5. Z5.\nG52 X2. Y3.\nG53 G0 Z0.\nG53 X20. Y20.\nG0 X1.\nT1 M6\nG43 H1 Z10.\n"
            "G53 Z0.\nT2 M6\nG43 H2 Z10.\nG49 G0 Z20.\nG53 Z0.\nM30\n")
    out = _from_fanuc(text, setup)
    assert [line for line in out.splitlines() if "SUPA" in line] == ["SUPA G0 Z0.", "SUPA G0 X20. Y20.",
                                                                      "SUPA G0 Z0.", "SUPA G0 Z0."], out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="siemens", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out
    back = _translate(out, "fanuc", setup)
    assert back.count("G53 G00") == 4, back


def test_fanuc_g53_in_g1_is_at_rapid_so_supa_is_written_with_g0(tmp_path: Path) -> None:
    """Fanuc's G53 positions at rapid whatever the modal motion; the G1 in force is taken up again after it."""
    setup = _setup(tmp_path)
    text = "G21 G90 G17 G0 X5. Y5. Z5.\nG1 F100.\nG53 X0.\nX3.\nM30\n"
    out = _from_fanuc(text, setup)
    assert "SUPA G0 X0.\nG1 X3.\n" in out, out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="siemens", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


def test_fanuc_g53_under_a_tool_length_takes_it_out_with_d0_and_selects_it_again(tmp_path: Path) -> None:
    """Exact whatever ``$MN_G53_TOOLCORR`` says: ``D0`` before the SUPA block (no length left to suppress), the D
    again after it (Fanuc's G43 stays in force after G53). By hand: tool 2 is 75 mm long and the set-up has no
    work offset, so G53 Z0 puts the spindle (the controlled point) at Z0: under D0 the point programmed is the
    spindle's; G0 Z10. after it puts the tip at Z10, the spindle at 85; ``G53 G49 Z0.`` cancels the length in
    its own block: D0 alone, and Z5. after it is the spindle's."""
    setup = _setup(tmp_path)
    text = ("G21 G90 G17 G0 X5. Y5. Z5.\nT2 M6\nG43 H2 Z10.\nG53 Z0.\nG53 X20. Y20.\nG0 Z10.\n"
            "G53 G49 Z0. M5\nG0 Z5.\nM30\n")
    out = _from_fanuc(text, setup)
    assert out.splitlines()[1:12] == ["T2 M6", "D02 G0 Z10.", "D0", "SUPA G0 Z0.", "D02", "D0", "SUPA G0 X20. Y20.",
                                      "D02", "G0 Z10.", "D0", "SUPA G0 Z0. M5"], out
    moves = [(e["x"], e["y"], e["z"], e.get("controlled", {}).get("z"))
             for e in toolpath_events(io.StringIO(out), file="o.mpf", dialect="siemens", setup=setup) if "move" in e]
    assert moves[1:] == [(5, 5, 10, 85), (5, 5, 0, None), (20, 20, 0, None), (20, 20, 10, 85), (20, 20, 0, None),
                         (20, 20, 5, None)], out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="siemens", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


def test_a_block_skip_goes_on_the_d0_and_d_blocks_too(tmp_path: Path) -> None:
    """Skipped, none of the three runs: the length stays in force, as on Fanuc where the skipped G53 does not
    run; not skipped, the three run as above."""
    setup = _setup(tmp_path)
    out = _from_fanuc("G21 G90 G17 G0 X5. Y5. Z5.\nT2 M6\nG43 H2 Z10.\n/G53 Z0. M9\nM30\n", setup)
    assert out.splitlines()[3:6] == ["/ D0", "/ SUPA G0 Z0. M9", "/ D02"], out


@pytest.mark.parametrize("lines", ["G41 D2 G1 X10. F100.\nG0\nG53 Z0."])
def test_fanuc_g53_with_a_tool_offset_in_force_is_refused(lines: str, tmp_path: Path) -> None:
    """Radius compensation in force (the source cannot run it either)."""
    with pytest.raises(ErrorList) as caught:
        _from_fanuc(f"G21 G90 G17 G0 X5. Y5. Z5.\n{lines}\nM30\n", _setup(tmp_path))
    assert any("machine coordinates" in str(e) for e in caught.value.errors), [str(e) for e in caught.value.errors]


# -- under a tool length, as the set-up's $MN_G53_TOOLCORR says --------------------------------------------------

def _setup_corr(tmp_path: Path, corr: str) -> MachineSetup:
    path = tmp_path / f"machine{corr}.xml"
    path.write_text(f'<MachineSetup name="t"><Controller g53ToolCorr="{corr}"/><Tools>{TOOLS}</Tools></MachineSetup>')
    return load_setup(path)


UNDER_LENGTH = START + "T2 D2 M6\nG0 Z10\nSUPA G0 Z-100\nG0 X1\nM30\n"
"""D2 is 75 long: G0 Z10 puts the spindle at 85. ``SUPA Z-100`` with ``$MN_G53_TOOLCORR`` 1 suppresses the length
too: the spindle goes to machine -100 (the tool tip to -175); with 0 the length stays: the tool tip goes to -100,
the spindle to -25 [V: 802D sl/840D ISO Milling 04.07, 3.1.1]. The next block has the frame again: X 1 + 2."""


@pytest.mark.parametrize("corr, spindle", [("1", -100.0), ("0", -25.0)])
def test_a_block_without_frames_under_a_length_moves_as_the_machine_data_says(corr: str, spindle: float,
                                                                               tmp_path: Path) -> None:
    setup = _setup_corr(tmp_path, corr)
    events = [e for e in toolpath_events(io.StringIO(UNDER_LENGTH), file="in.mpf", dialect="siemens", setup=setup)
              if "move" in e]
    assert [(e["x"], e["controlled"]["z"]) for e in events[1:]] == [(5, 85), (5, spindle), (3, spindle)]
    for target in ("fanuc", "linuxcnc"):
        out = _translate(UNDER_LENGTH, target, setup)
        report = verify_lines(io.StringIO(UNDER_LENGTH), io.StringIO(out), file_in="a", file_out="b",
                              source="siemens", target=target, setup=setup, tolerance=0.0)
        assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out
        assert re.search(rf"^(G53 G0?0|G0?0 G53) Z{spindle:g}\.$", out, re.M), out


def test_without_the_machine_data_the_refusal_names_the_attribute(tmp_path: Path) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(UNDER_LENGTH, "fanuc", _setup(tmp_path))
    assert 'in.mpf:5:1: error: SUPA (frame suppression) with the length of D2 in force (whether it stays is machine ' \
           'data $MN_G53_TOOLCORR: the set-up\'s <Controller g53ToolCorr="0"/> or "1" says' in str(caught.value.errors[0])


def test_a_machine_move_under_g91_is_refused_towards_siemens() -> None:
    """Found by tests/test_fuzz_all_dialects.py (grbl -> siemens): ``G53 G91 X10.`` was written ``SUPA G91 G0 X10.``,
    which the SINUMERIK reader then refused (it reads SUPA in G90 only). Machine positions are absolute: a located
    error now, and under G90 it is written as before."""
    with pytest.raises(ErrorList) as caught:
        out = io.StringIO()
        translate(io.StringIO("G21 G90 G0 X0. Y0. Z10.\nG53 G91 X10.\n"), out, file="in.mpf", source="grbl",
                  target="siemens", setup=MachineSetup(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert "in.mpf:2:1: error: the siemens dialect cannot express a move in machine coordinates under G91" in \
        str(caught.value.errors[0])


ROTARY = ('<MachineSetup name="t"><Machine axes="XYZA"/><Tools><Tool number="1" length="0.0" radius="0.0"/></Tools>'
          '<WorkOffsets><Offset number="1" x="-100" y="-50" z="-200" a="30"/></WorkOffsets></MachineSetup>')
"""G54 shifts Y by -50 and A by 30 degrees: a machine position is the work position plus those."""


def _rotary(tmp_path: Path) -> MachineSetup:
    path = tmp_path / "rotary.xml"
    path.write_text(ROTARY)
    return load_setup(path)


@pytest.mark.parametrize("line", ["SUPA G0 Y0 A20", "G53 G0 Y0 A20", "G153 Y0 A20"])
def test_a_block_without_frames_puts_a_rotary_axis_at_its_machine_position(line: str, tmp_path: Path) -> None:
    """A frame carries offsets of the special axes too (issue 26, haasfacts; ``frame_suppression``): the block
    goes to machine Y0 A20, which in G54 (Y -50, A +30) is work Y 0 + 50 = 50 and A 20 - 30 = -10 (worked out
    by hand); the next block is in G54 again (A2 is work A 2)."""
    text = "G710 G17 G90 G54 G0 X5 Y5 Z5 A0\nG0 A1\n" + line + "\nG0 A2\nM30\n"
    moves = [(e["move"], float(e["y"]), float(e["a"]))
             for e in toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens", setup=_rotary(tmp_path))
             if "move" in e]
    assert moves == [("rapid", 5, 0), ("rapid", 5, 1), ("rapid", 50, -10), ("rapid", 50, 2)]


def test_fanuc_g53_of_a_rotary_axis_is_supa_and_reads_back(tmp_path: Path) -> None:
    """``G53 Y0. A0.`` (a Haas program's end, issue 26 audit26) was refused for SINUMERIK (the reading kept a
    SUPA block with A verbatim); SUPA suppresses the frames of every axis (``frame_suppression``): written
    ``SUPA G0 Y0. A0.`` and verified point for point against the Fanuc source (machine A0 is work A -30)."""
    setup = _rotary(tmp_path)
    text = "G21 G90 G17 G54 G0 X5. Y5. Z5. A10.\nG53 Y0. A0.\nG0 A5.\nM30\n"
    out = _from_fanuc(text, setup)
    assert "SUPA G0 Y0. A0.\n" in out, out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="siemens", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out
    moves = [(float(e["y"]), float(e["a"])) for e in toolpath_events(io.StringIO(out), file="out.mpf",
                                                                         dialect="siemens", setup=setup)
             if "move" in e]
    assert moves == [(5, 10), (50, -30), (50, 5)], moves
