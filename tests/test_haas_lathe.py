"""Haas and shop lathe programs: the safe-start line ``G00 G18 G20 G40 G80 G99``, one-block G71/G76, gear
ranges, and GSK's G18.

The program under ``lathe_programs/`` is written for these tests in the shape of public Haas lathe programs
(enier290188/cnc ``src/lathe/*.nc``, a student's Haas ST programs; that repository states no licence, so
none of its text is copied here): safe start, ``G50`` clamp with ``G96``, one-block ``G71 P Q U W D F``
with ``G70``, one-block ``G76 X Z K D F``. It round-trips byte for byte, and translates to GSK (two-block
forms) and LinuxCNC (expanded, G33 passes), each verified against the source; the LinuxCNC output runs in
rs274 with the same moves.

Gear ranges declared in the shipped lathe set-ups (``<MachineCodes>``, kept verbatim within a family and
refused elsewhere): Fanuc T M41-M44, the machine builder's [K: the Fanuc family defaults,
``dialects/fanuc/machine_codes.py``]; GSK 980TDc M41-M44 automatic spindle gear shift [K: the 980TDc user
manual's M-code list; the public copy could not be read past its preface]; Haas lathes M41 low gear, M42
high gear [K: Haas lathe operator's manual M-code list], M43/M44 as the family's defaults. The Haas set-up's
``threadMinDepth`` 0.0254 mm (0.001 in) stands for a machine setting [?].
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import read_program, translate
from postproc.errors import ErrorList
from postproc.ir import CycleCancel
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.test_lathe_rs274 import INCH_TOLERANCE, difference, ours, theirs

ROOT = Path(__file__).resolve().parents[1]
HAAS = load_setup(str(ROOT / "examples" / "setups" / "haas_st10_lathe.xml"))
GSK = load_setup(str(ROOT / "examples" / "setups" / "gsk_980tdc.xml"))
PLUG = (ROOT / "tests" / "lathe_programs" / "haas_style_plug.nc").read_text()


def write(text: str, source: str, target: str, setup=HAAS) -> str:  # type: ignore[no-untyped-def]
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target, setup=setup)
    return out.getvalue()


def test_the_safe_start_line_reads_g80_as_the_cycle_cancel() -> None:
    blocks = read_program(io.StringIO(PLUG), file="in.nc", dialect="fanuc", setup=HAAS)
    first = next(b for b in blocks if b.text and b.text.startswith("G00 G18"))
    assert isinstance(first.sections.get("CycleCancel"), CycleCancel)
    assert write(PLUG, "fanuc", "fanuc") == PLUG


def test_g80_while_a_single_cycle_is_in_force_is_refused() -> None:
    program = "G99 G97 S500 M03\nG00 X50. Z2.\nG90 X40. Z-20. F0.2\nG80\nX30.\n"
    with pytest.raises(ErrorList) as caught:
        read_program(io.StringIO(program), file="in.nc", dialect="fanuc", setup=HAAS)
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:4:1: error: G80 while the single cycle G90 is in force: whether it ends it differs between "
        "controls (Haas: it does [K], Fanuc T: only a motion code does [K]); program G00 or G01 instead"]


def test_the_haas_program_translates_to_gsk() -> None:
    gsk = write(PLUG, "fanuc", "gsk")
    assert "G71 P10 Q20 U0.02 W0.01 F0.008" in gsk.splitlines()  # one block becomes two
    assert "G76 X0.92 Z-0.9 P450 Q120 F0.0625" in gsk.splitlines()
    assert not any("G80" in line for line in gsk.splitlines())  # nothing to cancel on the 980TDc
    report = verify_lines(io.StringIO(PLUG), io.StringIO(gsk), file_in="in.nc", file_out="out.nc", source="fanuc",
                          target="gsk", setup=HAAS, tolerance=1e-5)  # GSK's inch data parameters round at 1e-8 in
    assert report.ok, report.summary()


def test_the_haas_program_translates_to_linuxcnc_and_runs_in_rs274() -> None:
    ngc = write(PLUG, "fanuc", "linuxcnc")
    assert "G96 D2500 S600 M3" in ngc.splitlines() and any(line.startswith("G33 ") for line in ngc.splitlines())
    report = verify_lines(io.StringIO(PLUG), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc", source="fanuc",
                          target="linuxcnc", setup=HAAS, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    if available():
        assert difference(ours(PLUG, "fanuc", HAAS), theirs(ngc), INCH_TOLERANCE) is None  # rs274 prints inches


def test_gear_ranges_are_declared_in_the_shipped_lathe_set_ups() -> None:
    program = "G00 X50. Z2.\nM42\nM30\n"
    for dialect, setup in (("fanuc", HAAS), ("gsk", GSK)):
        events = list(toolpath_events(io.StringIO(program), file="in.nc", dialect=dialect, setup=setup))
        assert {"line": 2, "event": "machine", "action": "gear", "code": "M42",
                "name": "spindle high gear" if dialect == "fanuc" else "spindle gear range 2"} in events
    with pytest.raises(ErrorList):  # another family's gear code has no LinuxCNC meaning: refused, not dropped
        write(program, "fanuc", "linuxcnc")


def test_gsk_reads_and_writes_g18_only() -> None:
    program = "G18 G00 X50. Z2.\nM30\n"
    assert write(program, "gsk", "gsk", GSK) == program
    assert write("G00 X50. Z2.\nG18\nM30\n", "fanuc", "gsk", GSK).splitlines()[1] == "G18"
    with pytest.raises(ErrorList) as caught:
        read_program(io.StringIO("G17\n"), file="in.nc", dialect="gsk", setup=GSK)
    assert [str(e) for e in caught.value.errors] == ["in.nc:1:1: error: unknown G code G17"]


HAAS_TNC_ROUGHING = """G00 G18 G20 G40 G80 G99
T0101
G50 S2500
G97 S2000 M03
G00 G54 X1.6 Z0.1
G71 P10 Q20 U0.01 W0.005 D0.05 F0.010
N10 G00 G42 X0.3 Z0.1
G01 Z0.
X0.48 Z-0.09
Z-0.85
G02 X0.58 Z-0.9 R0.05
G01 X1.3
N20 G00 G40 X1.6
G70 P10 Q20
M30
"""
"""The shape of public Haas lathe programs (enier290188/cnc ``src/lathe/lathe_hp/*.nc``: one-block G71 with
``G42`` in its first profile block and ``G40`` in its last, then G70 on the same profile), written here."""


def test_a_haas_roughing_cycle_that_compensates_inside_its_profile_needs_the_nose_radius() -> None:
    """The Haas form (G42 in the P block, G40 in the Q block) roughs to the nose's path
    (tests/test_haas_lathe_nose.py): without the offset's nose radius in the set-up it is refused, naming
    the element that gives it; on a Fanuc T set-up, whose controller alarms on G40-G42 inside ns..nf [K],
    the profile block is refused by name."""
    with pytest.raises(ErrorList) as caught:
        write(HAAS_TNC_ROUGHING, "fanuc", "gsk")
    assert str(caught.value.errors[0]) == (
        "in.nc:6:1: error: the set-up gives tool radius register 1 no value: add <Tool number=\"1\" radius=\"..\"/> "
        "to its <Tools>, or write the register in the program")
    fanuc_t = load_setup(str(ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"))
    with pytest.raises(ErrorList) as caught:
        two_blocks = HAAS_TNC_ROUGHING.replace("G71 P10 Q20 U0.01 W0.005 D0.05 F0.010",
                                               "G71 U0.05 R0.01\nG71 P10 Q20 U0.01 W0.005 F0.010")
        read_program(io.StringIO(two_blocks), file="in.nc", dialect="fanuc", setup=fanuc_t)
    assert str(caught.value.errors[0]).startswith(
        "in.nc:8:1: error: G71: the profile block at line 8 turns tool nose radius compensation on or off: this "
        "controller's rules for compensation inside the cycle are not in our sources")
