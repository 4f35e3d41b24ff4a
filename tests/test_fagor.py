"""The Fagor 8070 dialect: lossless reading, the spelling of every construct (a ``validate_all`` table),
the collisions with Fanuc's numbers in both directions, the drilling words by role, and what the
reference leaves uncertain (kept verbatim, refused elsewhere).

Expected texts and toolpaths are written by hand from DIALECTS.md 1.4, 2.3 and 3.4 (Fagor) and 2.1
(Fanuc); LinuxCNC translations are checked by rs274 through the conftest hook and ``test_fagor_oracle``.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.isg_family.expressions import BINARY, FUNCTIONS, P_BASE, spell_expr, spell_word_value
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.verify import verify_lines

from tests.support.paths import assert_verifies_exactly, moves_and_dwells

from dialects.fagor import Fagor
from dialects.fagor.reader import FagorReader

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples" / "fagor").glob("*.nc"))
HUNDREDTHS = MachineSetup(cycles=CycleSettings(fagor_dwell_unit="hundredths"))


def _translate(text: str, source: str, target: str, setup: MachineSetup | None = None,
               warn: bool = False) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target, setup=setup,
              on_unsupported="warn" if warn else "error", diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, source: str, target: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, source, target, setup)
    return [str(e) for e in caught.value.errors]


# -- lossless ------------------------------------------------------------------------------------------

LEXICAL = [
    "%part_7\nG71 G90 G17 G54\nM30\n",
    "%1001\nN10 G00 X10 Y20 ; a comment runs to the end ; even this\nN20 G01 X10.5 F100\nM30\n",
    "G01X10Y20F100\n",
    "#COMMENT BEGIN\nanything ( at all $IF\n#COMMENT END\nG00 X1\n",
    "P1=2 P2=P1*3\nG01 X[P1+2] YP2 Z-P1 F100\n",
    "G00 X[SIN[30]*P1] Y[2 ** 3]\n",
    "G159=3\nG159 = 12\nG54\n",
    "G70\nG00 X1.5\nG71\n",
    "$IF P1 == 2\nG01 X1 F100\n$ELSE\nG01 X2 F100\n$ENDIF\n",
    "$FOR P1 = 1, 3, 1\n$ENDFOR\n$WHILE P1 < 3\nP1=P1+1\n$ENDWHILE\n",
    "[START] G00 X1\nN100: G00 X2\n$GOTO [START]\n",
    "/ G01 X1 F100\n/3 G01 X2\n",
    "LL SUB1\nL sub2.nc\n#CALL SUB2\n#PCALL SUB3 A1 B2\n#MCALL SUB4\n#MDOFF\n#RET\n",
    "%L SUB1\nG01 X1 F100\nM17\n%main\nLL SUB1\nM30\n",
    "#MSG [\"done :)\"]\nG00 X1 (a comment on the 8070) Y2\nG00 X2 (to the end of the block Y3\nG00 (a (nested) one) X3\n",
    "G00 X0 Y0 Z20\nG81 G99 Z2 I-10 K0.5 F100\nG82 Z2 I-10 B3 C1 D1 H1 J1 K1 L1 R1\nG83 Z2 I-2 J5\nG84 Z2 I-10 K1 R1\n"
    "G85 Z2 I-10 K1\nG86 Z2 I-10 K1\nG87 Z2 I-10 J10 K5 B1 C1 D1 H1 L1 V1\nG88 Z2 I-10 J5 B1 C1 D1 H1 L1\n"
    "G89 Z2 I-10 K1\nG80\n",
    "G00 X10\r\nG01 Y5 F100\r\n",
]


@pytest.mark.parametrize("text", LEXICAL)
def test_fagor_lexical_forms_round_trip_byte_for_byte(text: str) -> None:
    assert _translate(text, "fagor", "fagor") == text


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_fagor_example_reads_and_writes_back_byte_for_byte(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert _translate(text, "fagor", "fagor") == text


# -- validate_all: one construct, its reading and its writing in each dialect ---------------------------
# (source dialect, source text) -> {target: expected text | the start of the error message}

PRO = {"fanuc": "G21 G17 G90\nG00 X0. Y0. Z20.\n", "fagor": "G71 G17 G90\nG00 X0 Y0 Z20\n",
       "linuxcnc": "G21 G17 G90\nG0 X0. Y0. Z20.\n", "isg": "G71 G17 G90\nG00 X0 Y0 Z20\n"}
VALIDATE_ALL = [
    # units: Fagor G70/G71 are Fanuc G20/G21 (and Fanuc's G70/G71 are no mill codes)
    (("fagor", "G70\nG00 X1.\n"), {"fanuc": "G20\nG00 X1.\n", "linuxcnc": "G20\nG0 X1.\n", "isg": "G70\nG00 X1.\n"}),
    (("fanuc", "G20\nG00 X1.\n"), {"fagor": "G70\nG00 X1.\n"}),
    (("isg", "G71\nG00 X1\n"), {"fagor": "G71\nG00 X1.\n"}),
    # zero offsets: G159=1..6 are G54..G59, above is kept for Fagor only
    (("fagor", "G159=2\n"), {"fanuc": "G55\n", "linuxcnc": "G55\n", "isg": "G55\n"}),
    (("fagor", "G159=9\n"), {"fanuc": "error: G159=9 (zero offset 9) from fagor has no equivalent in fanuc",
                             "linuxcnc": "error: G159=9 (zero offset 9) from fagor has no equivalent in linuxcnc"}),
    (("fanuc", "G59\n"), {"fagor": "G59\n"}),
    # return levels: the same meaning in both (ISG's G98/G99 are software limits: never written there)
    # (a G81 without K drills with no dwell, K0 [V: Fagor 8055-M programming manual p.162]: Fanuc's G81)
    (("fagor", "M03 S1000\nG98 G81 X5. Y5. Z2. I-5. F100.\n"),
     {"fanuc": "S1000 M03\nG98 G81 X5. Y5. Z-5. R2. F100.\n"}),
    (("fanuc", "M03 S1000\nG99 G81 X5. Y5. Z-5. R2. F100.\n"),
     {"fagor": "S1000 M03\nG99 G81 X5. Y5. Z2. I-5. F100.\n"}),
    # Fagor's pockets never reach another dialect; Fanuc's G87/G88 never reach Fagor as G87/G88
    (("fagor", "G87 G99 Z2 I-10 J10 K5 D1\n"),
     {"fanuc": "error: G87 (rectangular pocket) from fagor has no equivalent in fanuc",
      "isg": "error: G87 (rectangular pocket) from fagor has no equivalent in isg"}),
    (("fagor", "G88 G99 Z2 I-10 J5 D1\n"),
     {"linuxcnc": "error: G88 (circular pocket) from fagor has no equivalent in linuxcnc"}),
    (("fanuc", "M03 S1000\nG98 G88 X5. Y5. Z-5. R2. P100 F100.\n"),
     {"fagor": "S1000 M03\nG98 F100.\n;bore_manual from line 4: G98 G88 X5. Y5. Z-5. R2. P100 F100.\n"
               "G00 X5. Y5. Z20.\nG00 Z2.\nG01 Z-5.\nG04 K0.1\nM05\nM00\nG00 X5. Y5. Z20.\nM03\n"}),
    # the uncertain: kept verbatim for Fagor, refused with its name elsewhere
    (("fagor", "$IF P1 == 2\n$ENDIF\n"), {"fanuc": "error: $IF (control flow [?]: If) from fagor has no equivalent"}),
    (("fagor", "LL SUB1\n"), {"fanuc": "error: LL SUB1 (subroutine call [?]) from fagor has no equivalent"}),
    (("fagor", "#MCALL SUB1\n"), {"isg": "error: #MCALL (modal subroutine call [?]) from fagor has no equivalent"}),
    (("fagor", "/ G00 X1\n"), {"fanuc": "error: block skip /1 [?] from fagor has no equivalent"}),
    # ( ) is a block comment (Fagor's table of programming commands, dialects/fagor/reader.py)
    (("fagor", "G00 X1 (note) Y2\n"), {"fanuc": "G00 X1. Y2. (note)\n", "isg": "G00 X1. Y2. (note)\n"}),
    (("fanuc", "/G00 X1.\n"), {"fagor": "error: the fagor dialect cannot express a block skip"}),
    # comments and parameters
    (("fagor", "G00 X1 ; go\n"), {"fanuc": "G00 X1. ( go)\n", "isg": "G00 X1. ( go)\n"}),
    (("fanuc", "G00 X1. (go)\n"), {"fagor": "G00 X1. ;go\n"}),
    # P parameters are the family's neutral #501-#999: kept symbolically where the target has variables
    (("fagor", "P1=2\nG00 X[P1*3]\n"), {"fanuc": "#501=2.\nG00 X[#501*3.]\n", "isg": "P1=2\nG00 X[P1*3]\n"}),
    # dwell: G04 K in the set-up's unit (seconds by default)
    (("fanuc", "G04 X1.5\n"), {"fagor": "G04 K1.5\n"}),
    (("fagor", "G04 K0.25\n"), {"fanuc": "G04 X0.25\n", "linuxcnc": "G4 P0.25\n"}),
]


@pytest.mark.parametrize("source_text, writes", VALIDATE_ALL,
                         ids=lambda v: repr(v)[:60] if isinstance(v, tuple) else "")
def test_validate_all(source_text: tuple[str, str], writes: dict[str, str]) -> None:
    source, text = source_text
    for target, expected in writes.items():
        program = PRO[source] + text + "M30\n"
        if expected.startswith("error: "):
            errors = _errors(program, source, target)
            assert any(expected[len("error: "):] in e for e in errors), errors
            assert all(e.startswith("in.nc:") for e in errors)
        else:
            out = _translate(program, source, target)
            body = out.splitlines(keepends=True)[2:-1]
            assert "".join(body) == expected, out


# -- collisions pinned both ways -----------------------------------------------------------------------

def test_fanuc_cycles_fagor_numbers_other_things_reach_fagor_expanded() -> None:
    """Fanuc G73, G74, G76, G83, G84, G86, G87, G88 are never written as the Fagor code of that number."""
    program = ("G21 G17 G90\nG00 X0. Y0. Z20.\nS500 M03\nG98 G73 X1. Y1. Z-4. R2. Q1. F100.\nG80\n"
               "M04\nG74 X2. Z-4. R2. F100.\nG80\nM03\nG83 X3. Z-4. R2. Q1.5\nG84 X4. Z-4. R2. P100\n"
               "G86 X5. Z-4. R2.\nG87 X6. Z-8. R-4. Q1.\nG88 X7. Z-4. R2. P100\nG76 X8. Z-4. R2. Q1.\nG80\nM30\n")
    setup = MachineSetup(cycles=CycleSettings(orientation="m19"))
    out = _translate(program, "fanuc", "fagor", setup)
    codes = [w for line in out.splitlines() if not line.startswith(";") for w in line.split() if w.startswith("G")]
    assert not set(codes) & {"G73", "G74", "G76", "G82", "G83", "G84", "G85", "G86", "G87", "G88"}, out
    for kind in ("peck_chip", "tap_left", "peck_deep", "tap", "bore_stop", "back_bore", "bore_manual", "fine_bore"):
        assert f";{kind} from line" in out
    assert_verifies_exactly(program, out, "fanuc", "fagor", setup)


def test_fanuc_back_boring_needs_an_orientation_fagor_cannot_make() -> None:
    program = PRO["fanuc"] + "S500 M03\nG98 G87 X6. Z-8. R-4. Q1. F100.\nG80\nM30\n"
    assert _errors(program, "fanuc", "fagor") == [
        "in.nc:4:1: error: G87 needs an oriented spindle stop, which the fagor dialect cannot make (set "
        "<Cycles orientation=\"stop\"/> or \"m19\")"]


def test_fagor_m19_only_on_a_machine_the_set_up_says_has_it() -> None:
    assert _errors("M19\n", "fagor", "fagor")[0].startswith(
        "in.nc:1:1: error: M19: an oriented spindle stop is not confirmed on the 8070")
    setup = MachineSetup(cycles=CycleSettings(orientation="m19"))
    assert _translate("M19\n", "fagor", "fanuc", setup) == "G21 M19\n"  # G21: the units the program was read in (tests/test_units_at_start.py)


@pytest.mark.parametrize("code, error", [
    ("G160", "5:10: error: G160 takes no Y word (its words: A X I K P Q R S T U V)"),
    ("G161", "5:1: error: G161 needs exactly two of X (length), I (step) and K (number of points), not 1"),
    ("G162", "5:1: error: G162 needs exactly two of X (length), I (step) and K (number of points), not 1"),
    ("G163", "5:1: error: G163 needs the angular step I or the number of points K"),
    ("G164", "5:1: error: G164 needs B, the angle of the arc"),
])
def test_multiple_machining_goes_to_its_reader_and_is_never_dropped(code: str, error: str) -> None:
    # the words of one pattern are wrong for another: each block is refused where it is, never dropped
    # (tests/test_fagor_multiple_machining.py reads every pattern's words)
    program = f"G71 G90\nG00 X0 Y0 Z20\nM03 S500\nG81 Z2 I-5 F100\n{code} X10 Y0\nG80\nM30\n"
    for target in ("fagor", "fanuc"):
        assert _errors(program, "fagor", target) == [f"in.nc:{error}"]


def test_fagor_cycles_outside_the_xy_plane_are_refused() -> None:
    assert _errors("G71 G90 G18\nG00 X0 Y0 Z20\nG81 Z2 I-5 F100\n", "fagor", "fagor") == [
        "in.nc:3:1: error: G81: Fagor hole cycles are read in the XY plane (G17) only (which axis Z names in "
        "G18/G19 is not confirmed)"]


@pytest.mark.parametrize("text, message", [
    ("%\nM30\n", "in.nc:1:1: error: a program header is %<name> (a lone % is not a Fagor header)"),
    ("G159\n", "in.nc:1:1: error: G159 needs a value: G159=<n>"),
    ("G159=2.5\n", "in.nc:1:6: error: G159= takes a whole number"),
    ("G159=100\n", "in.nc:1:1: error: unknown G code G159=100"),
    ("$ENDIF\n", "in.nc:1:1: error: $ENDIF does not close an open $IF"),
    ("$IF P1 == 1\nM30\n", "in.nc:1:1: error: $IF is never closed"),
    ("#COMMENT BEGIN\nG00 X1\n", "in.nc:1:1: error: #COMMENT BEGIN is never ended (#COMMENT END missing)"),
    ("G00 X1 ) Y2\n", "in.nc:1:8: error: ')' without an opening '('"),
    ("G00 X1 #CALL A\n", "in.nc:1:8: error: a # command must be alone in its block (only N may come before it)"),
    ("P0=1\n", "in.nc:1:1: error: P0: P parameters P1 to P499 are read"),
    ("G04\n", "in.nc:1:1: error: G04 needs a dwell time K"),
    ("G71 G90 G00 X0 Y0 Z20\nG81 Z2 F100\n", "in.nc:2:1: error: G81 needs a hole bottom I"),
    ("G71 G90 G00 X0 Y0 Z20\nG81 I-5 F100\n", "in.nc:2:1: error: G81 needs an R level Z"),
    ("G71 G90 G00 X0 Y0 Z20\nG81 Z2 I5 F100\n", "in.nc:2:8: error: G81 hole bottom I is above the R level"),
    ("G71 G90 G00 X0 Y0 Z20\nG81 Z2 I-5 K-1 F100\n", "in.nc:2:12: error: G81 dwell time K cannot be negative"),
])
def test_hostile_fagor_input_gives_located_errors(text: str, message: str) -> None:
    errors = _errors(text, "fagor", "fagor")
    assert errors[0].startswith(message), errors


def test_a_parenthesised_comment_is_simulated_as_one() -> None:
    """The words after ``( .. )`` move the tool; an unclosed ``(`` hides the rest of its block only."""
    text = "%demo\nG71 G90\nG00 X1 (note) Y2\nG01 F100 X3 (the rest Y9\nG00 Z5\nM30\n"
    assert moves_and_dwells(text, "fagor") == [("rapid", 1, 2, 0), ("feed", 3, 2, 0), ("rapid", 3, 2, 5)]


# -- drilling words: hand-derived toolpaths ------------------------------------------------------------

def test_fagor_g81_absolute_moves_as_derived_by_hand() -> None:
    """From Z20: rapid over the hole, rapid to the reference plane Z2, feed to I-10, dwell K, rapid back to
    Z2 (G99); the next hole from Z2 (already at the plane: no Z move); the third rises to its plane Z3 and
    G98 returns to the initial level 20 (the cycle stayed active, so the initial level is still 20)."""
    program = ("G71 G90 G17\nG00 X0 Y0 Z20\nM03 S800\nG81 G99 X10 Y10 Z2 I-10 K0.5 F200\nX20\n"
               "G98 G81 X30 Y10 Z3 I-4\nG80\nM30\n")
    assert moves_and_dwells(program, "fagor") == [
        ("rapid", 0.0, 0.0, 20.0),
        ("rapid", 10.0, 10.0, 20.0), ("rapid", 10.0, 10.0, 2.0), ("feed", 10.0, 10.0, -10.0), ("dwell", 0.5),
        ("rapid", 10.0, 10.0, 2.0),
        ("rapid", 20.0, 10.0, 2.0), ("feed", 20.0, 10.0, -10.0), ("dwell", 0.5),
        ("rapid", 20.0, 10.0, 2.0),
        ("rapid", 30.0, 10.0, 2.0), ("rapid", 30.0, 10.0, 3.0), ("feed", 30.0, 10.0, -4.0), ("dwell", 0.5),
        ("rapid", 30.0, 10.0, 20.0),
    ]


def test_fagor_g91_reference_plane_from_the_start_and_depth_from_the_plane() -> None:
    """G91 from Z20: Z-18 puts the reference plane at 2, I-12 the bottom at 2 - 12 = -10; X/Y are steps."""
    program = "G71 G90 G17\nG00 X0 Y0 Z20\nM03 S800\nG91 G98 G81 X10 Y5 Z-18 I-12 F100\nX5\nG80\nM30\n"
    assert moves_and_dwells(program, "fagor") == [
        ("rapid", 0.0, 0.0, 20.0),
        ("rapid", 10.0, 5.0, 20.0), ("rapid", 10.0, 5.0, 2.0), ("feed", 10.0, 5.0, -10.0), ("rapid", 10.0, 5.0, 20.0),
        ("rapid", 15.0, 5.0, 20.0), ("rapid", 15.0, 5.0, 2.0), ("feed", 15.0, 5.0, -10.0), ("rapid", 15.0, 5.0, 20.0),
    ]


def test_fagor_g89_dwells_and_feeds_out() -> None:
    program = "G71 G90\nG00 X0 Y0 Z20\nM03 S800\nG99 G89 X5 Y5 Z2 I-6 K1 F50\nG80\nM30\n"
    assert moves_and_dwells(program, "fagor")[1:] == [
        ("rapid", 5.0, 5.0, 20.0), ("rapid", 5.0, 5.0, 2.0), ("feed", 5.0, 5.0, -6.0), ("dwell", 1.0),
        ("feed", 5.0, 5.0, 2.0)]


@pytest.mark.parametrize("setup, k, seconds", [(None, "K0.5", 0.5), (HUNDREDTHS, "K50", 0.5), (HUNDREDTHS, "K5", 0.05)])
def test_the_dwell_unit_comes_from_the_set_up(setup: MachineSetup | None, k: str, seconds: float) -> None:
    program = f"G71 G90\nG00 X0 Y0 Z20\nM03 S800\nG81 X5 Y5 Z2 I-6 {k} F50\nG04 {k}\nG80\nM30\n"
    assert [m for m in moves_and_dwells(program, "fagor", setup) if m[0] == "dwell"] == [("dwell", seconds)] * 2
    fanuc = _translate(program, "fagor", "fanuc", setup)
    assert f"G82 X5. Y5. Z-6. R2. P{round(seconds * 1000)} F50." in fanuc
    assert f"G04 X{seconds:g}" in fanuc
    back = k if "." in k else k + "."  # written with its point
    assert f"{back} F50." in _translate(fanuc, "fanuc", "fagor", setup)


def test_a_dwell_fanuc_cannot_hold_in_whole_milliseconds_is_refused() -> None:
    program = PRO["fagor"] + "M03 S800\nG81 X5 Y5 Z2 I-6 K0.0005 F50\nG80\nM30\n"
    assert _errors(program, "fagor", "fanuc") == [
        "in.nc:4:1: error: the fanuc dialect cannot express a dwell of 0.0005 s (whole milliseconds only)"]


def test_a_cycle_without_dwell_after_one_with_writes_k0() -> None:
    """Fanuc G81 after G82 P500 does not dwell: Fagor's G81 gets K0, whatever Fagor carries over."""
    program = PRO["fanuc"] + "S800 M03\nG82 X5. Y5. Z-6. R2. P500 F50.\nG81 X6.\nG89 X7.\nG85 X8.\nG80\nM30\n"
    out = _translate(program, "fanuc", "fagor")
    assert out.splitlines()[3:7] == ["G81 X5. Y5. Z2. I-6. K0.5 F50.", "G81 X6. Z2. I-6. K0.", "G89 X7. Z2. I-6. K0.5",
                                    "G89 X8. Z2. I-6. K0."]
    assert_verifies_exactly(program, out, "fanuc", "fagor")


def test_the_dwell_is_written_again_after_a_machine_coordinate_move() -> None:
    """A G53 move ends the cycle (a G80 before it: ``cycle_end``), so the next G81 cannot rely on the K of
    the cycle before it: the old writer left K out there and the Fagor program lost the 1 s dwell (verify
    saw it as a rapid where the source dwells)."""
    program = (PRO["fanuc"] + "S800 M03\nG82 X5. Y5. Z-6. R2. P1000 F50.\nG53 X0. Y0.\n"
               "G82 X6. Y5. Z-6. R2. P1000 F50.\nG80\nM30\n")
    out = _translate(program, "fanuc", "fagor")
    assert out.splitlines()[3:7] == ["G81 X5. Y5. Z2. I-6. K1. F50.", "G80", "G53 G00 X0. Y0.",
                                     "G81 X6. Y5. Z2. I-6. K1. F50."]
    assert_verifies_exactly(program, out, "fanuc", "fagor")


def test_every_cycle_call_after_a_dwell_names_its_k() -> None:
    """Whether the 8070 carries K from G81 to G89, or over a cancel, is not confirmed: once a K was written,
    each block naming the cycle code writes its own (K0 without a dwell); before that none is needed."""
    program = (PRO["fanuc"] + "S800 M03\nG81 X4. Y5. Z-6. R2. F50.\nG82 X5. P1000\nG89 X6. P1000\nG80\n"
               "G81 X7. Y5. Z-6. R2. F50.\nG80\nM30\n")
    out = _translate(program, "fanuc", "fagor")
    assert out.splitlines()[3:8] == ["G81 X4. Y5. Z2. I-6. F50.", "G81 X5. Z2. I-6. K1.", "G89 X6. Z2. I-6. K1.", "G80",
                                     "G81 X7. Y5. Z2. I-6. K0. F50."]
    assert_verifies_exactly(program, out, "fanuc", "fagor")


def test_a_cycle_call_writes_the_levels_its_source_carried_over() -> None:
    """Fanuc keeps R and Z from cycle to cycle: G82 X30. P500 drills from R2 to the Z-9 of the repeat before it.
    Whether the 8070 keeps Z and I from one definition to the next is not confirmed, so the call writes them:
    Z2. I-9. (the depth last written), K0.5."""
    program = (PRO["fanuc"] + "S800 M03\nG81 X10. Y0 Z-6. R2. F100.\nX20. Z-9.\nG82 X30. P500\nG80\nM30\n")
    out = _translate(program, "fanuc", "fagor")
    assert out.splitlines()[3:6] == ["G81 X10. Y0. Z2. I-6. F100.", "X20. I-9.", "G81 X30. Z2. I-9. K0.5"]
    assert_verifies_exactly(program, out, "fanuc", "fagor")


def test_a_fanuc_repeat_count_has_no_fagor_word() -> None:
    program = PRO["fanuc"] + "S800 M03\nG91 G81 X5. Z-6. R-2. K3 F50.\nG80\nM30\n"
    assert _errors(program, "fanuc", "fagor") == [
        "in.nc:4:1: error: the fagor dialect cannot express a cycle repeat count K3 (no repeat count in fagor)"]
    assert "K1" not in _translate(program.replace("K3", "K1"), "fanuc", "fagor")


# -- verify: Fanuc -> Fagor -> Fanuc at zero deviation ------------------------------------------------

FANUC_DRILLING = [
    "G21 G17 G90 G54\nS1200 M03\nG00 X0. Y0. Z30.\nG99 G81 X10. Y10. Z-12. R2. F150.\nX20.\nY20.\n"
    "G98 G82 X30. Z-8. R3. P300\nG80\nG00 Z30.\nM05\nM30\n",
    "G21 G17 G90 G55\nS900 M03\nG00 X0. Y0. Z25.\nG91 G99 G81 X12.5 Y-4. Z-20. R-22. F120.\nX12.5\nX12.5\n"
    "G90 G98 G89 X60. Y0. Z-5. R2. P1500 F80.\nG85 X70.\nG80\nM05\nM30\n",
    "G20 G17 G90\nS900 M03\nG00 X0. Y0. Z1.\nG99 G81 X1. Y1. Z-0.5 R0.1 F8.\nX2.\nG80\nM30\n",
]


@pytest.mark.parametrize("program", FANUC_DRILLING)
def test_fanuc_drilling_through_fagor_and_back_verifies_at_zero_deviation(program: str) -> None:
    fagor = _translate(program, "fanuc", "fagor")
    assert_verifies_exactly(program, fagor, "fanuc", "fagor")
    back = _translate(fagor, "fagor", "fanuc")
    assert_verifies_exactly(fagor, back, "fagor", "fanuc")
    assert_verifies_exactly(program, back, "fanuc", "fanuc")
    assert _translate(fagor, "fagor", "fagor") == fagor


def test_a_different_dwell_is_a_deviation_verify_sees() -> None:
    fanuc = PRO["fanuc"] + "S800 M03\nG82 X1. Y1. Z-3. R2. P250 F100.\nG80\nM30\n"
    fagor = PRO["fagor"] + "M03 S800\nG81 X1 Y1 Z2 I-3 K0.5 F100\nG80\nM30\n"
    report = verify_lines(io.StringIO(fanuc), io.StringIO(fagor), file_in="a.nc", file_out="b.nc", source="fanuc",
                          target="fagor", setup=None, target_setup=None, tolerance=0.0)
    assert not report.ok


# -- expressions: the family's spelling reads back through the Fagor reader ----------------------------

def _trees() -> st.SearchStrategy[Expr]:
    leaves = st.one_of(st.integers(-1000, 1000).map(lambda n: Num(n / 8)),
                       st.integers(1, 499).map(lambda n: Var(Num(float(P_BASE + n)))))
    ops = sorted({op for op, _ in BINARY.values()})
    return st.recursive(leaves, lambda inner: st.one_of(
        st.builds(Binary, st.sampled_from(ops), inner, inner),
        st.builds(lambda f, a: Func(f, [a]), st.sampled_from(sorted(FUNCTIONS.values())), inner),
        st.builds(lambda a: Unary("neg", a), inner),
    ), max_leaves=10)


def _canonical(e: Expr) -> Expr:
    if isinstance(e, Unary):
        inner = _canonical(e.operand)
        return Num(-inner.value) if e.op == "neg" and isinstance(inner, Num) else Unary(e.op, inner)
    if isinstance(e, Binary):
        return Binary(e.op, _canonical(e.left), _canonical(e.right))
    if isinstance(e, Func):
        return Func(e.name, [_canonical(a) for a in e.args])
    return e


@settings(max_examples=200, deadline=None)
@given(_trees())
def test_fagor_expression_spelling_reads_back_as_the_same_tree(tree: Expr) -> None:
    text = f"P7={spell_expr(tree)}\nG01 X{spell_word_value(tree)}\n"
    ctx = Fagor.context("in.nc", MachineSetup(), Diagnostics())
    blocks = list(FagorReader(ctx).read(io.StringIO(text)))
    assert not ctx.diagnostics.errors, (text, ctx.diagnostics.errors)
    assign = blocks[0].sections["Assign"]
    assert getattr(assign, "items") == [(Var(Num(float(P_BASE + 7))), _canonical(tree))], text
    x = blocks[1].values.get("X")  # a plain number stays a word, anything else is read as a tree
    assert (x if x is not None else Num(float(blocks[1].words[-1][1]))) == _canonical(tree), text


# -- the set-up attribute --------------------------------------------------------------------------------

def test_the_dwell_unit_is_a_validated_set_up_attribute(cli, tmp_path: Path) -> None:
    good = tmp_path / "good.xml"
    good.write_text('<MachineSetup name="m" dialect="fagor"><Cycles fagorDwellUnit="hundredths"/></MachineSetup>\n')
    assert cli("config", "check", good).status == 0
    program = tmp_path / "p.nc"
    program.write_text("G71 G90\nG00 X0 Y0 Z20\nM03 S800\nG81 X5 Y5 Z2 I-6 K50 F50\nG80\nM30\n")
    result = cli("translate", program, "--from", "fagor", "--to", "fanuc", "--machine", good)
    assert result.status == 0 and b"P500" in result.out
    bad = tmp_path / "bad.xml"
    bad.write_text('<MachineSetup name="m">\n  <Cycles fagorDwellUnit="minutes"/>\n</MachineSetup>\n')
    result = cli("config", "check", bad)
    assert result.status == 1 and "bad.xml:2:" in result.err and "fagorDwellUnit" in result.err
