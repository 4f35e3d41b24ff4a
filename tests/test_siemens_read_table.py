"""The SINUMERIK spelling of each construct read, and what Fanuc and LinuxCNC get for it (a ``validate_all``-style
table, the other direction of ``test_siemens.WRITE_TABLE``).

The expected lines are the targets' spellings of the meaning the 840D manuals give the SINUMERIK one (sources
in ``dialects/siemens/codes.py`` and ``expressions.py``): Fanuc ``G04 X`` and LinuxCNC ``G4 P`` take seconds;
SINUMERIK ``G505``/``G506`` are settable offsets 5 and 6, Fanuc's and LinuxCNC's ``G58``/``G59``; ``G60`` is
exact stop, ``G61``; ``G70``/``G700`` inch and ``G71``/``G710`` mm; ``CR=`` is the R form (negative over 180
degrees on all three); trigonometry in degrees on all three (LinuxCNC ``ATAN[y]/[x]``); ``POT`` squares.
Each translation also verifies (toolpath equivalence) where it moves.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines

ZERO_TOOLS = Path(__file__).resolve().parent / "support" / "zero_tools.xml"

HEAD = "G710 G90 G0 X0 Y0 Z0\n"

READ_TABLE = [
    # (SINUMERIK block after HEAD, what Fanuc gets, what LinuxCNC gets)
    ("G17", "G17", "G17"), ("G18", "G18", "G18"), ("G19", "G19", "G19"),
    ("G54", "G54", "G54"), ("G57", "G57", "G57"), ("G505", "G58", "G58"), ("G506", "G59", "G59"),
    ("G60", "G61", "G61"), ("G64", "G64", "G64"), ("G91", "G91", "G91"), ("G94", "G94", "G94"),
    ("G700", "G20", "G20"), ("G70", "G20", "G20"), ("G71", "G21", "G21"),
    ("S100 M3", "S100 M03", "S100 M3"), ("S100 M4", "S100 M04", "S100 M4"), ("M5", "M05", "M5"),
    ("M8", "M08", "M8"), ("M9", "M09", "M9"), ("M0", "M00", "M0"), ("M1", "M01", "M1"),
    ("G4 F1.5", "G04 X1.5", "G4 P1.5"), ("/G1 X1 F10", "/ G01 X1. F10.", "/ G1 X1. F10."),
    ("G2 X10 Y0 CR=5 F10", "G02 X10. Y0. R5. F10.", "G2 X10. Y0. R5. F10."),
    ("G2 X10 Y0 CR=-5 F10", "G02 X10. Y0. R-5. F10.", "G2 X10. Y0. R-5. F10."),
    ("D0", "G49", "G49"), ("G40", "G40", "G40"),
    ("R1=2.5", "#501=2.5", "#501=2.5"), ("R1=1.5EX1", "#501=15.", "#501=15."),
    ("G1 X=SIN(30) F10", "G01 X[SIN[30.]] F10.", "G1 XSIN[30.] F10."),
    ("G1 X=POT(3) F10", "G01 X9. F10.", "G1 X9. F10."),
    ("G1 X=ATAN2(1,1) F10", "G01 X45. F10.", "G1 XATAN[1.]/[1.] F10."),
    ("G1 F100\nG0\nMCALL CYCLE81(0, 0, 0, -5)\nX5\nMCALL", "G01 F100.|G00|G99 G81 Z-5. R0. K0|X5.|G80", None),
    ("G1 F100\nG0\nMCALL CYCLE83(0, 0, 0, -8, , -4, , 0, 0, 0, 1, 1, , , , , 0.5)\nX5\nMCALL",
     "G01 F100.|G00|G99 G83 Z-8. R0. Q4. K0|X5.|G80", None),
    # a floating tap (CYCLE840, ENC 1) is G84 under G99; a rigid one (CYCLE84) Fanuc's M29 and G84 at each hole,
    # LinuxCNC's G33.1 (the pitch K 1.5)
    ("S500 M3\nG1 F100\nG0\nMCALL CYCLE840(0, 0, 0, -5, , , 4, 3, 1)\nX5\nMCALL",
     "S500 M03|G01 F100.|G00|G99 G84 Z-5. R0. K0|X5.|G80", None),
    ("S500 M3\nG0\nCYCLE84(0, 0, 0, -5, , , 3, , 1.5, 0, 500, 500)",
     "S500 M03|G00|G99|S500 M29|G99 G84 Z-5. R0. F750.|G80|G00",
     "S500 M3|G0|G99|(tap from line 4: R0.0 Z-5.0)|G33.1 Z-5. K1.5|G0"),
]
"""LinuxCNC None: the cycle is not compared by its text (checked by ``verify``)."""


def _out(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target,
              setup=load_setup(str(ZERO_TOOLS)), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("siemens, fanuc, linuxcnc", READ_TABLE, ids=[row[0] for row in READ_TABLE])
def test_a_siemens_construct_gets_each_targets_spelling_and_verifies(siemens: str, fanuc: str,
                                                                     linuxcnc: str | None) -> None:
    text = f"{HEAD}{siemens}\nM30\n"
    for target, expected in (("fanuc", fanuc), ("linuxcnc", linuxcnc)):
        out = _out(text, target)
        if expected is not None:
            assert "|".join(out.splitlines()[1:-1]) == expected, out
        report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                              target=target, setup=load_setup(str(ZERO_TOOLS)), tolerance=0.0)
        assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


@pytest.mark.parametrize("siemens, refusal", [
    ("G599", "cannot express work offset 99"),
    ("G1 X=IC(2) F10", "X=IC(..) (a per-address distance mode"),
    ("G58 X5", "G58 (axial programmable offset)"),
    ("CYCLE84(10, 0, 2, -20, , 0, 3, , 1.25, 0, 400, 400)", "CYCLE84 with SST 400 other than the S in force"),
    ("G0 X1 TURN=2", "TURN= counts the full circles of a helix"),
])
def test_a_siemens_construct_without_a_spelling_is_refused_by_name(siemens: str, refusal: str) -> None:
    for target in ("fanuc", "linuxcnc"):
        with pytest.raises(ErrorList) as caught:
            _out(f"{HEAD}{siemens}\nM30\n", target)
        assert any(refusal in str(e) for e in caught.value.errors), [str(e) for e in caught.value.errors]
