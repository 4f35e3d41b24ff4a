"""The ISG (Beckhoff TwinCAT CNC) dialect: lossless reading, the spelling of every construct, the
collisions with Fanuc's numbers in both directions, and hostile input.

Expected texts are written by hand from DIALECTS.md 1.3/3.3 (ISG) and the Fanuc/LinuxCNC tables; motion
is checked against LinuxCNC's rs274 in ``test_isg_oracle.py``.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import Limits, MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples" / "isg").glob("*.nc")) + sorted(
    (ROOT / "tests" / "golden" / "isg" / "oracle").glob("*.nc"))


CYLINDER_AXIS = load_setup(ROOT / "examples" / "setups" / "isg_twincat_cylinder.xml")
"""A machine with the U axis ``prof_open_close.nc`` programs (on the default XYZ one it is refused)."""


def _translate(text: str, source: str, target: str, warn: bool = False,
               setup: MachineSetup | None = None) -> tuple[str, str]:
    out = io.StringIO(newline="")
    warnings = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target, setup=setup,
              on_unsupported="warn" if warn else "error", diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def _errors(text: str, source: str, target: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, source, target)
    return [str(e) for e in caught.value.errors]


def _moves(text: str, dialect: str, setup: MachineSetup | None = None) -> list[dict[str, object]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect, setup=setup)
            if "move" in e]


# -- lossless ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_isg_program_reads_and_writes_back_byte_for_byte(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert _translate(text, "isg", "isg", setup=CYLINDER_AXIS)[0] == text


LEXICAL = [
    "G01X10Y20F100\n",                       # no separators
    "N10 G01 X10 ( outer ( nested ) comment ) Y5 F100\n",
    "G01 X10 F100 ( unclosed comment runs to the end\n",
    "G01 X10 F100 ; the rest is a comment\n",
    "/ G01 X1 F100\n/3 G01 X2\n/10 G01 X3\n",
    "G01 X10 \\\n  Y20 F100\n",              # continuation
    "#COMMENT BEGIN\nanything ( at all $IF\nnot the end: #COMMENT END\nN5 #COMMENT END\nG00 X1\n",
    "G00 X0\n$GOTO N200\nG00 X5\nN200: G00 X1\n",
    "P1=0\n[AGAIN] G01 X[P1] F100\nP1=P1+1\n$IF P1 < 3 $GOTO [AGAIN]\n$GOTO [DONE]\nG01 X99\n[DONE]\nM30\n",
    "P1='16#FA1B' P2='0x0ED2' P3='H1869f' P4='2#101'\n",
    "#VAR\nV.L.DEPTH\nV.L.FEED = 200\n#ENDVAR\nG01 X[V.L.FEED] F[V.L.FEED]\n",
    "G01 XP1 Y-P3 Z[P2*COS[P6]] F100\n",
    "#MSG [\"HELLO\"]\n#TOOL DATA [T1 D1]\n#MC_COMMAND [A=1]\n",
    "#MSG [\"done :) (not a comment; nor this\"] (a comment)\n",
    "G00 X10\r\nG01 Y5 F100\r\n",
]


@pytest.mark.parametrize("text", LEXICAL)
def test_isg_lexical_forms_round_trip(text: str) -> None:
    blocks = read_program(io.StringIO(text, newline=""), file="in.nc", dialect="isg")
    assert blocks
    assert _translate(text, "isg", "isg")[0] == text


def test_isg_structure_is_read_into_neutral_sections() -> None:
    text = "(c)\n%L SUB\nG01 X1\nM17\n%main\nN10 G71 G90\nP1=2\nLL SUB\nL other.nc\nM30\n"
    blocks = read_program(io.StringIO(text), file="in.nc", dialect="isg")
    control = {b.line: type(b.get("Control")).__name__ for b in blocks if b.get("Control") is not None}
    assert control == {2: "SubStart", 4: "SubEnd", 8: "Call", 9: "Call"}
    assert blocks[1].get("Control").name == "<SUB>"
    assert blocks[7].get("Control").name == "<SUB>" and blocks[8].get("Control").name == "other.nc"
    assert blocks[4].get("ProgramStart").name == "main"
    assert blocks[5].get("Units").system == "mm"
    assert blocks[6].get("Assign").items[0][0].index.value == 501.0  # P1 is the neutral #501


def test_a_number_without_a_point_is_millimetres_whatever_the_set_up_says() -> None:
    from postproc.setup.machine_setup import InputSettings
    setup = MachineSetup(input=InputSettings(decimal_point="least-increment"))
    moves = _moves("G71 G90 G00 X10 Y2.5 Z-3\n", "isg", setup)
    assert (moves[0]["x"], moves[0]["y"], moves[0]["z"]) == (10, 2.5, -3)


# -- the spelling of every construct (validate_all) -----------------------------------------------------

KEEP = [
    # ISG source, what Fanuc gets (kept as macro B), what LinuxCNC gets (kept as o-words)
    ("P1=2\nG01 X[P1*2] F100\nM30\n", "#501=2.\nG01 X[#501*2.] F100.\nM30\n",
     "#501=2.\nG1 X[#501*2.] F100.\nM30\n"),
    ("P1=0\n$WHILE P1 < 3\nG01 X[P1] F100\nP1=P1+1\n$ENDWHILE\nM30\n",
     "#501=0.\nWHILE [#501 LT 3.] DO1\nG01 X#501 F100.\n#501=#501+1.\nEND1\nM30\n",
     "#501=0.\no1 while [#501 LT 3.]\nG1 X#501 F100.\n#501=[#501+1.]\no1 endwhile\nM30\n"),
    # $FOR: the counter set before the loop, tested against the end, grown before the loop's end
    ("$FOR P10 = 1, 7, 3\nG01 X[P10] F100\n$ENDFOR\nM30\n",
     "#510=1.\nWHILE [#510 LE 7.] DO1\nG01 X#510 F100.\n#510=#510+3.\nEND1\nM30\n",
     "#510=1.\no1 while [#510 LE 7.]\nG1 X#510 F100.\n#510=[#510+3.]\no1 endwhile\nM30\n"),
    ("$FOR P10 = 5, 1, -2\n$FOR P11 = 0, 1, 1\nG01 X[P10] Y[P11] F100\n$ENDFOR\n$ENDFOR\nM30\n",
     "#510=5.\nWHILE [#510 GE 1.] DO1\n#511=0.\nWHILE [#511 LE 1.] DO2\nG01 X#510 Y#511 F100.\n"
     "#511=#511+1.\nEND2\n#510=#510-2.\nEND1\nM30\n",
     "#510=5.\no1 while [#510 GE 1.]\n#511=0.\no2 while [#511 LE 1.]\nG1 X#510 Y#511 F100.\n"
     "#511=[#511+1.]\no2 endwhile\n#510=[#510-2.]\no1 endwhile\nM30\n"),
]


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
@pytest.mark.parametrize("source, fanuc, linuxcnc", KEEP, ids=range(len(KEEP)))
def test_isg_program_kept_symbolically(source: str, fanuc: str, linuxcnc: str, target: str) -> None:
    out, warnings = _translate(source, "isg", target)
    assert warnings == ""
    # a program without units reaches another dialect with the ones it was read in (G21), in a block of its
    # own before the first that reads a value (postproc.lowering.units_at_start)
    assert out == "G21\n" + (fanuc if target == "fanuc" else linuxcnc)
    report = verify_lines(io.StringIO(source), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="isg", target=target, tolerance=0.0)
    assert report.ok, report.summary()


@pytest.mark.parametrize("loop", ["$FOR P10 = 1, P2, 1", "$FOR P10 = 1, 4, P2"])
@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
def test_a_counted_loop_with_a_computed_end_or_step_is_flattened(loop: str, target: str) -> None:
    source = f"P2=2\n{loop}\nG01 X[P10] F100\nP2=P2+1\n$ENDFOR\nM30\n"
    out, warnings = _translate(source, "isg", target)
    assert "the program is flattened" in warnings and "counted loop whose end or step is computed" in warnings
    report = verify_lines(io.StringIO(source), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="isg", target=target, tolerance=0.0)
    assert report.ok, report.summary()


WRITE = [
    # neutral construct read from Fanuc / LinuxCNC, and how ISG spells it
    ("fanuc", "G20 G90 G17\nG00 X1. Y2.\nM30\n", "G17 G70 G90\nG00 X1. Y2.\nM30\n"),
    ("fanuc", "G21 G91\nG01 X10 F100.\nM30\n", "G71 G91\nG01 X0.01 F100.\nM30\n"),
    ("fanuc", "G21\nG04 X1.5\nM30\n", "G71\nG04 X1.5\nM30\n"),
    ("linuxcnc", "G21\n#501=3\n#502=[#501*2+1]\nG0 X#502\nM2\n", "G71\nP1=3\nP2=P1*2+1\nG00 XP2\nM02\n"),
    ("linuxcnc", "G21\n#510=0\no1 while [#510 LT 2]\nG1 X#510 F100\n#510=[#510+1]\no1 endwhile\nM2\n",
     "G71\nP10=0\n$WHILE P10 < 2\nG01 XP10 F100.\nP10=P10+1\n$ENDWHILE\nM02\n"),
    ("linuxcnc", "G21\n#501=1\no2 if [#501 GT 0.5]\nG0 X1\no2 else\nG0 X2\no2 endif\nM2\n",
     "G71\nP1=1\n$IF P1 > 0.5\nG00 X1.\n$ELSE\nG00 X2.\n$ENDIF\nM02\n"),
    ("linuxcnc", "G21\n#501=0\no3 do\n#501=[#501+1]\no3 while [#501 LT 3]\nG0 X#501\nM2\n",
     "G71\nP1=0\n$DO\nP1=P1+1\n$ENDDO P1 < 3\nG00 XP1\nM02\n"),
]


@pytest.mark.parametrize("source, text, isg", WRITE)
def test_isg_spelling_of_neutral_constructs(source: str, text: str, isg: str) -> None:
    out, warnings = _translate(text, source, "isg")
    assert warnings == ""
    assert out == isg
    assert _translate(out, "isg", "isg")[0] == out  # reads back in ISG
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source=source, target="isg", tolerance=0.0)
    assert report.ok, report.summary()


# -- collisions, both ways ------------------------------------------------------------------------------

def test_fanuc_inch_metric_become_isg_g70_g71_and_back() -> None:
    assert _translate("G20\nG0 X1.\nM30\n", "fanuc", "isg")[0] == "G70\nG00 X1.\nM30\n"
    assert _translate("G21\nG0 X1.\nM30\n", "fanuc", "isg")[0] == "G71\nG00 X1.\nM30\n"
    assert _translate("G70\nG00 X1\nM30\n", "isg", "fanuc")[0] == "G20\nG00 X1.\nM30\n"
    assert _translate("G71\nG00 X1\nM30\n", "isg", "fanuc")[0] == "G21\nG00 X1.\nM30\n"


@pytest.mark.parametrize("code, meaning", [
    ("G20", "end of mirroring"), ("G21", "mirroring"), ("G22", "mirroring"), ("G23", "mirroring"),
    ("G98", "set the negative software limit switch"), ("G99", "set the positive software limit switch"),
    ("G74", "programmable homing"), ("G92", "coordinate preset"), ("G81", "implicit subroutine call: runs the file "
    "the machine builder configured"), ("G89", "implicit subroutine call: runs the file the machine builder configured"),
    ("G61", "polynomial blending for one block"), ("G261", "polynomial blending on"),
    ("G161", "arc centre in absolute coordinates"),
])
@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_isg_codes_that_collide_never_reach_another_dialect(code: str, meaning: str, target: str) -> None:
    text = f"G71 G90\nG00 X0 Y0\n{code} X10\nM30\n"
    errors = _errors(text, "isg", target)
    assert errors == [f"in.nc:3:1: error: {code} ({meaning}) from isg has no equivalent in {target}"] or \
        errors[0].startswith(f"in.nc:3:1: error: {code} ({meaning}")
    out, warnings = _translate(text, "isg", target, warn=True)
    assert f"UNSUPPORTED LINE 3: {code} X10" in out
    assert f"{code} ({meaning})" in warnings


@pytest.mark.parametrize("code", ["G20", "G21", "G22", "G23", "G98", "G99", "G74", "G92", "G80", "G89", "G161"])
def test_isg_codes_that_collide_are_never_simulated(code: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _moves(f"G71 G90\nG00 X0 Y0\n{code} X10\nM30\n", "isg")
    assert str(caught.value.errors[0]).startswith(f"in.nc:3:1: error: {code} (")
    assert "cannot be simulated" in str(caught.value.errors[0])


def test_fanuc_return_levels_and_cycle_cancel_never_reach_isg_text() -> None:
    fanuc = "G21 G90 G17\nG00 X0. Y0. Z20.\nS1000 M03\nG99 G81 X10. Y5. Z-3. R2. F100.\nG98 X20.\nG80\nM30\n"
    out, warnings = _translate(fanuc, "fanuc", "isg")
    words = [w for line in out.splitlines() if not line.startswith("(") for w in line.split()]
    assert not {"G98", "G99", "G80", "G81"} & set(words), out
    report = verify_lines(io.StringIO(fanuc), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target="isg", tolerance=0.0)
    assert report.ok, report.summary()


@pytest.mark.parametrize("fanuc, isg", [("G61", "G360"), ("G64", "G359"), ("G09 G01 X2. F100.", "G60 G01 X2. F100.")])
def test_fanuc_exact_stop_modes_are_isg_g360_g359_g60_never_g61(fanuc: str, isg: str) -> None:
    """[V] TF5200 "Exact stop (G60/G360/G359)": ISG's G61 is polynomial blending (rounded corners), so
    Fanuc's G61 is written G360; and back, each reads as the Fanuc code it came from."""
    text = f"G21\n{fanuc}\nG0 X1.\nM30\n"
    out = _translate(text, "fanuc", "isg")[0]
    assert out.splitlines()[1] == isg and "G61" not in out
    assert _translate(out, "isg", "fanuc")[0].splitlines()[1] == fanuc


def test_an_array_element_keeps_its_block_verbatim_and_is_refused_elsewhere() -> None:
    text = "G71 G90 G00 X0 Y0 Z5\nP100[2]=5\nG01 X[P100[2]] F100\nM30\n"
    assert _translate(text, "isg", "isg")[0] == text
    assert _errors(text, "isg", "fanuc")[0] == ("in.nc:2:1: error: P parameter arrays (not modelled) from isg has no "
                                                "equivalent in fanuc")
    with pytest.raises(ErrorList) as caught:
        _moves(text, "isg")
    assert str(caught.value.errors[0]).startswith("in.nc:2:1: error: P parameter arrays (not modelled) cannot be "
                                                  "simulated")


@pytest.mark.parametrize("dwell, seconds", [("G04 X4.5", 4.5), ("G04 3", 3.0), ("G04 P1", 2.0),
                                             ("G04 V.L.T", 1.5), ("N5 G04 [P1*2]", 4.0)])
def test_isg_dwell_forms(dwell: str, seconds: float) -> None:
    """The manual's forms: the time after the first main axis (X) or alone, in seconds, direct or
    parameterised; each round-trips and dwells as long."""
    text = f"G71\nP1=2\nV.L.T=1.5\n{dwell}\nM30\n"
    assert _translate(text, "isg", "isg")[0] == text
    events = list(toolpath_events(io.StringIO(text), file="in.nc", dialect="isg"))
    assert [e["seconds"] for e in events if e.get("event") == "dwell"] == [seconds]


def test_named_labels_are_jumped_to() -> None:
    text = ("G71 G90 G00 X0 Y0 Z5\nP1 = 0\n[AGAIN] G01 X[P1*10+10] F100\nP1 = P1 + 1\n$IF P1 < 3 $GOTO [AGAIN]\n"
            "$GOTO [DONE]\nG01 X99\n[DONE]\nG00 Z20\nM30\n")
    assert [(m["line"], m["x"], m["z"]) for m in _moves(text, "isg")] == [
        (1, 0, 5), (3, 10, 5), (3, 20, 5), (3, 30, 5), (9, 30, 20)]


def test_g162_the_default_arc_centre_mode_adds_nothing() -> None:
    moves = _moves("G71 G90 G17 G162\nG00 X0 Y0 Z5\nG02 X10 Y0 I5 J0 F100\nM30\n", "isg")
    assert moves[1]["cx"] == 5 and moves[1]["cy"] == 0


# -- # commands ---------------------------------------------------------------------------------------

CYL = "G71 G90\nG00 X0 Y0 Z10\nN70 #CYL[EDGES=4 ROUNDING=5 LENGTH1=20]\nG01 X10 F100\nN90 #CYL OFF\nM30\n"


def test_cyl_round_trips_and_is_refused_by_name_elsewhere() -> None:
    assert _translate(CYL, "isg", "isg")[0] == CYL
    errors = _errors(CYL, "isg", "fanuc")
    assert errors[0] == "in.nc:3:1: error: #CYL (cylinder surface transformation) from isg has no equivalent in fanuc"
    assert errors[1].startswith("in.nc:5:1: error: #CYL OFF")
    out, warnings = _translate(CYL, "isg", "fanuc", warn=True)
    assert "(UNSUPPORTED LINE 3: N70 #CYL[EDGES=4 ROUNDING=5 LENGTH1=20])" in out
    assert "#CYL (cylinder surface transformation)" in warnings


def test_cyl_is_never_simulated() -> None:
    with pytest.raises(ErrorList) as caught:
        _moves(CYL, "isg")
    assert str(caught.value.errors[0]).startswith("in.nc:3:")
    assert "#CYL (cylinder surface transformation) cannot be simulated" in str(caught.value.errors[0])


# -- hostile input ------------------------------------------------------------------------------------

SMALL = MachineSetup(limits=Limits(loop_iterations=1000, call_depth=8))
HOSTILE = [
    ("G71\nP1=1\n$WHILE P1 > 0\nG01 X1 F100\nP1=P1+1\n$ENDWHILE\nM30\n", "in.nc:6:1: error: loop '$ENDWHILE' "
     "exceeds the set-up's bound of 1000 loop iterations"),
    ("G71\n$FOR P1 = 0, 1000000000, 1\nG01 X1 F100\n$ENDFOR\nM30\n", "in.nc:4:1: error: loop '$ENDFOR' exceeds the "
     "set-up's bound of 1000 loop iterations"),
    # a test nothing in the loop changes, or an iteration as the one before: refused at once (test_defects_loops)
    ("G71\nP1=1\n$WHILE P1 > 0\nG01 X1 F100\n$ENDWHILE\nM30\n", "in.nc:3:1: error: loop '$WHILE P1 > 0' never ends"),
    ("G71\n$FOR P1 = 0, 10, 0\nG01 X1 F100\n$ENDFOR\nM30\n", "in.nc:4:1: error: loop '$ENDFOR' never ends"),
    ("%L REC\nG01 X1 F100\nLL REC\nM17\n%main\nG71\nLL REC\nM30\n", "in.nc:3:1: error: 'LL REC' exceeds the "
     "set-up's bound of 8 nested calls"),
    ("G71\nP1=0\nG01 X[10/P1] F100\nM30\n", "in.nc:3:5: error: division by zero in 10/#501"),
    ("G71\nP1=1\n$IF P1 > 0\nG01 X1 F100\nM30\n", "in.nc:3:1: error: $IF is never closed ($ENDIF missing)"),
    ("G71\n$ENDIF\nM30\n", "in.nc:2:1: error: $ENDIF does not close an open $IF"),
    ("G71\nG01 X[P7] F100\nM30\n", "in.nc:2:5: error: P7 is read before it is set"),
    ("G71\nP1=1\n$GOTO [NOWHERE]\nM30\n", "in.nc:3:1: error: '$GOTO [NOWHERE]': no block labelled NOWHERE"),
    ("G71\nG01 X[V.A.ACT_POS.X] F100\nM30\n", "in.nc:2:5: error: V.A.ACT_POS.X is known only to the machine"),
    ("G71\nP1=1\n$SWITCH P1\n$CASE 1\nG01 X1 F100\n$CASE 2\nG01 X2\n$ENDSWITCH\nM30\n",
     "in.nc:6:1: error: '$CASE 2' is reached from the branch before it, which does not end with a break"),
]


@pytest.mark.parametrize("text, message", HOSTILE, ids=range(len(HOSTILE)))
def test_hostile_isg_input_gives_located_errors(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _moves(text, "isg", SMALL)
    assert str(caught.value.errors[0]).startswith(message), str(caught.value.errors[0])


# -- regressions found by tests/test_isg_fuzz.py ------------------------------------------------------

def test_a_continued_block_commented_out_stays_one_comment_line() -> None:
    out, _ = _translate("G71 G90 G00 X0 Y0 Z10\nG01 X10 \\\nG161\nM30\n", "isg", "grbl", warn=True)
    assert "(UNSUPPORTED LINE 2: G01 X10 \\ G161)\n" in out
    read_program(io.StringIO(out), file="out.nc", dialect="grbl")


def test_an_unset_p_parameter_fails_translation_where_fanuc_would_read_it_vacant() -> None:
    assert _errors("G71 G90 G00 X0 Y0 Z10\nP1=1\nG01 XP1 Y-P2 F200\nM30\n", "isg", "fanuc") == [
        "in.nc:3:5: error: P2 is read before it is set"]


# An arc whose end is computed: from X1 Y0 with its centre 5 mm along +X (6, 0), the end X20 Y0 lies
# 14 mm from the centre, not 5 (by hand); G165 would move the centre (25 - 196) / (2 * 19) = 4.5 mm onto the
# chord's bisector, past P-CHAN-00059's 2 mm and 5 % of the corrected radius sqrt(110.5 - 20.25) = 9.5 mm. The symbolic text hides that from the reading steps; the
# run before keeping finds it (LinuxCNC would refuse the kept program only when it runs).
COMPUTED_BAD_ARC = "G71 G90 G00 X0 Y0 Z10 F100\nP1=1\nG01 X[P1] Y0\nG02 X20 Y0 I5 J0\nM30\n"
BAD_ARC_ERROR = ("in.nc:4:12: error: arc end point is not on the circle: radius 5.0000 mm at the start, "
                 "14.0000 mm at the end (the controller accepts a move of the centre up to 2 mm here)")


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "fagor"])
def test_an_arc_off_its_circle_in_a_program_kept_symbolically_is_a_located_error(target: str) -> None:
    assert _errors(COMPUTED_BAD_ARC, "isg", target) == [BAD_ARC_ERROR]


def test_an_arc_off_its_circle_is_the_same_error_kept_symbolically_and_flattened() -> None:
    # grbl has no variables: the program is flattened, and the reading steps see the evaluated arc
    assert _errors(COMPUTED_BAD_ARC, "isg", "grbl") == [BAD_ARC_ERROR]


def test_an_arc_off_its_circle_in_a_loop_is_refused_at_each_pass_as_flattened() -> None:
    # passes P1 = 0, 1, 2: the arc starts at X0, X1, X2 with its centre 5 mm further along X; its end
    # X20 lies 15, 14, 13 mm from that centre
    text = ("G71 G90 G00 X0 Y0 Z10 F100\nP1=0\n$WHILE P1 < 3\nG01 X[P1] Y0\nG02 X20 Y0 I5 J0\nP1=P1+1\n"
            "$ENDWHILE\nM30\n")
    expected = [f"in.nc:5:12: error: arc end point is not on the circle: radius 5.0000 mm at the start, "
                f"{r}.0000 mm at the end (the controller accepts a move of the centre up to 2 mm here)"
                for r in (15, 14, 13)]
    assert _errors(text, "isg", "linuxcnc") == expected
    assert _errors(text, "isg", "grbl") == expected


def test_an_arc_with_a_computed_end_on_its_circle_is_still_kept_symbolically() -> None:
    # from X1 Y0 around (6, 0): X11 Y0 is 5 mm from the centre, a half circle
    out, warnings = _translate("G71 G90 G00 X0 Y0 Z10 F100\nP1=1\nG01 X[P1] Y0\nG02 X[P1+10] Y0 I5 J0\nM30\n",
                               "isg", "linuxcnc")
    assert "#501" in out and not warnings


def test_a_feed_move_before_any_feed_rate_in_a_program_kept_symbolically_is_a_located_error() -> None:
    # LinuxCNC refuses 'G1 X#501' with no F in force when it runs it; flattened for grbl, the same error
    text = "G71 G90 G00 X0 Y0 Z10\nP1=1\nG01 X[P1]\nM30\n"
    expected = ["in.nc:3:1: error: a feed move with no feed rate (program F first)"]
    assert _errors(text, "isg", "linuxcnc") == expected
    assert _errors(text, "isg", "grbl") == expected


def test_a_feed_rate_before_the_first_construct_is_in_force_for_the_run() -> None:
    out, _ = _translate("G71 G90 G00 X0 Y0 Z10\nG01 X1 F50\nP1=1\nG01 X[P1]\nM30\n", "isg", "linuxcnc")
    assert "G1 X#501\n" in out


def test_a_return_in_the_main_program_is_refused_not_a_restart() -> None:
    # Fanuc's M99 in a main program starts it again: ISG's M17 there must not become one
    assert _errors("G71 G90 G00 X0 Y0 Z10\nP1=1\nM17\n", "isg", "fanuc") == [
        "in.nc:3:1: error: 'M17' returns from the main program (it ends a subroutine)"]


def test_a_linuxcnc_named_subprogram_becomes_a_numbered_fanuc_one_too() -> None:
    ngc = "o<corner> sub\nG1 X#1 Y#2 F300\no<corner> endsub\nG21 G90 G0 X0 Y0 Z5\no<corner> call [10] [5]\nM2\n"
    out, warnings = _translate(ngc, "linuxcnc", "fanuc")
    assert out == "G21 G90 G00 X0. Y0. Z5.\nG65 P2000 A10. B5.\nM02\nO2000\nG01 X#1 Y#2 F300.\nM99\n"
    report = verify_lines(io.StringIO(ngc), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="linuxcnc", target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()


def test_a_local_subroutine_becomes_a_numbered_fanuc_subprogram_after_the_main_program() -> None:
    isg = ("%L CORNER\nG01 X[P1] Y[P2] F300\nP1 = P1 + 5\nM17\n%100\nG71 G90 G00 X0 Y0 Z5\nP1 = 0\n"
           "$FOR P2 = 1, 3, 1\n  LL CORNER\n$ENDFOR\nG00 Z20\nM30\n")
    fanuc = ("O0100\nG21 G90 G00 X0. Y0. Z5.\n#501=0.\n#502=1.\nWHILE [#502 LE 3.] DO1\nG65 P2000\n#502=#502+1.\n"
             "END1\nG00 Z20.\nM30\nO2000\nG01 X#501 Y#502 F300.\n#501=#501+5.\nM99\n")
    out, warnings = _translate(isg, "isg", "fanuc")
    assert warnings == "" and out == fanuc
    report = verify_lines(io.StringIO(isg), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="isg", target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()
    # a main program numbered like the subroutine (known only after it): flattened, never two O2000
    out, warnings = _translate(isg.replace("%100", "%2000"), "isg", "fanuc")
    assert "subprogram 2000 (its number is already given to subprogram <CORNER>)" in warnings
    assert out.count("O2000") == 1 and "G65" not in out


# -- implicit subroutine calls G80-G89 --------------------------------------------------------------------

def test_an_implicit_call_runs_the_file_the_set_up_names(tmp_path: Path) -> None:
    from postproc.setup.machine_setup import load_setup
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "drill_cycle.nc").write_text("%drill_cycle.nc\nG00 Z2\nG01 Z-5 F100\nG00 Z10\nM17\n")
    (tmp_path / "m.xml").write_text('<MachineSetup name="isg" dialect="isg"><Library path="lib"/>'
                                    '<CodeCall code="G81" file="drill_cycle.nc"/></MachineSetup>')
    setup = load_setup(tmp_path / "m.xml")
    text = "G71 G90 G00 X0 Y0 Z10\nG00 X10 Y10\nG81\nG00 X20\nG81\nM30\n"
    moves = [(m["x"], m["z"], m["move"]) for m in _moves(text, "isg", setup)]
    assert moves == [(0, 10, "rapid"), (10, 10, "rapid"), (10, 2, "rapid"), (10, -5, "feed"), (10, 10, "rapid"),
                     (20, 10, "rapid"), (20, 2, "rapid"), (20, -5, "feed"), (20, 10, "rapid")]
    assert _translate(text, "isg", "isg", setup=setup)[0] == text
    out, warnings = _translate(text, "isg", "fanuc", setup=setup)  # the file's motion, flattened
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="out.nc", source="isg",
                          target="fanuc", setup=setup, tolerance=0.0)
    assert report.ok, report.summary()
    # without the set-up's word for it, the call is refused (test_isg_codes_that_collide_...)
    assert _errors(text, "isg", "fanuc")[0].startswith("in.nc:3:1: error: G81 (implicit subroutine call")


@pytest.mark.parametrize("element, message", [
    ('<CodeCall code="G81"/>', "<CodeCall> takes two attributes"),
    ('<CodeCall code="81" file="a.nc"/>', "<CodeCall> code '81' is not a letter and a whole number"),
    ('<CodeCall code="G81" file="a.nc"/><CodeCall code="G081" file="b.nc"/>', '<CodeCall code="G81"> appears twice'),
])
def test_code_call_set_up_errors(tmp_path: Path, element: str, message: str) -> None:
    from postproc.errors import ConfigError
    from postproc.setup.machine_setup import load_setup
    (tmp_path / "m.xml").write_text(f'<MachineSetup name="isg">{element}</MachineSetup>')
    with pytest.raises(ConfigError) as caught:
        load_setup(tmp_path / "m.xml")
    assert message in caught.value.message
