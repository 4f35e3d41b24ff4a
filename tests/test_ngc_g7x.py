"""LinuxCNC's lathe cycles G70, G71, G71.1, G71.2, G72, G72.1, G72.2 (``postproc.rs274.ngc_g7x``, read by the
LinuxCNC plugin's ``lathe_cycles``), held to the LinuxCNC interpreter.

The oracle is the installed rs274 (LinuxCNC 2.9.0~pre1): every expected move comes from it, none from the code
under test. Random profiles (``tests.support.g7x_profiles``: monotone and pocketed, lines and arcs by I/K or R,
fillets A and chamfers C, in all eight orientations, every code and word combination) are run through both
and their canonical moves compared; a profile rs274 refuses must be refused too. The engine is compared with
its ``legacy`` switch (the installed version's two differing steps); the reading (the plugin, the default
version) on closed profiles, where both versions agree, and on LinuxCNC's own demo program.
"""

from __future__ import annotations

import math

import io
import random
import re
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.rs274.ngc_g7x import V2_9_0, V2_9_1, V2_9_4, NgcCycleError, arc_centre_by_radius, closes, cycle_moves, rules_of
from postproc.rs274.ngc_g7x_segments import Arc, Chamfer, Fillet, Line, Piece
from postproc.setup.machine_setup import ControllerSettings, InputSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.g7x_profiles import CODES, Case, Step, draw
from tests.support.g7x_statements import StatementCase, batch, draw_with_statements
from tests.support.rs274 import RS274Error, available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
DEMO = ROOT / "tests" / "heldout" / "linuxcnc" / "lathe_g70_71_demo.ngc"
RADIUS = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"))
ORACLE = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"),
                      controller=ControllerSettings(version="2.9.0"))
"""The set-up of the rs274 here (2.9.0~pre1: ``interp_g7x.cc`` as v2.9.0's): random profiles end short of the
cycle's X (Z), whose cut depends on the version."""
TOOLS = "T2 P2 X0 Z0 D0.4\nT10 P10 X0 Z0 D0.4\n"
TOLERANCE = 2e-3
"""mm: rs274 prints four decimals."""
SEED = 20261130

needs_rs274 = pytest.mark.skipif(not available(), reason="rs274 (LinuxCNC's interpreter) is not installed")


# -- helpers -----------------------------------------------------------------------------------------
def pieces_of(case: Case) -> list[Piece]:
    """The case's profile as the controller builds it (``convert_g7x``: I/K from the move's start)."""
    here = complex(case.z, case.x)
    pieces: list[Piece] = []
    for step in case.steps:
        end = complex(step.z, step.x)
        if end == here:
            continue
        w = step.words
        if step.g in (0, 1):
            pieces.append(Line(here, end))
        else:
            centre = (arc_centre_by_radius(here, end, w["R"], step.g == 3) if "R" in w
                      else here + complex(w.get("K", 0.0), w.get("I", 0.0)))
            pieces.append(Arc(step.g == 3, here, centre, end))
        if "A" in w:
            pieces.append(Fillet(w["A"], end))
        if "C" in w:
            pieces.append(Chamfer(w["C"], end))
        here = end
    return pieces


def engine(case: Case) -> list[dict[str, Any]]:
    """The engine's moves for ``case`` (as the installed rs274), after the rapid to the cycle's point."""
    w = case.words
    moves = cycle_moves(case.code, pieces_of(case), case.x, case.z, d=w.get("D", 0.0), e=w.get("E", 0.0),
                        i=w.get("I", 1.0), r=w.get("R", 0.5), passes=int(w.get("P", 1)), rules=V2_9_0)
    out: list[dict[str, Any]] = [{"move": "rapid", "x": case.x, "z": case.z}]
    for kind, end, centre in moves:
        move = {"move": kind, "x": end.imag, "z": end.real}
        if centre is not None:
            move.update(cx=centre.imag, cz=centre.real)
        out.append(move)
    return out


def batch_program(cases: list[Case]) -> str:
    """One program running ``cases`` one after the other, each profile its own subprogram."""
    lines = ["G18 G21 G8 G90 G40", "F400"]
    for n, case in enumerate(cases):
        lines += [f"O{101 + n} SUB", *("  " + s.text() for s in case.steps), f"O{101 + n} ENDSUB"]
    for n, case in enumerate(cases):
        lines += [f"G0 X{case.x:.4f} Z{case.z:.4f}", case.program().splitlines()[-2].replace("Q100", f"Q{101 + n}")]
    return "\n".join(lines + ["M2"]) + "\n"


def without_repeats(moves: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Moves to where the tool already is are no moves (rs274 prints some: its G0 to the cycle's point)."""
    out: list[dict[str, Any]] = []
    here: tuple[float, float] | None = None
    for move in moves:
        point = (float(move["x"]), float(move["z"]))
        if move["move"] in ("rapid", "feed") and here is not None and \
                abs(point[0] - here[0]) < 1e-4 and abs(point[1] - here[1]) < 1e-4:
            continue
        out.append(move)
        here = point
    return out


def difference(ours: list[dict[str, Any]], theirs: list[dict[str, Any]]) -> str | None:
    ours, theirs = without_repeats(ours), without_repeats(theirs)
    for n, (a, b) in enumerate(zip(ours, theirs)):
        keys = ["x", "z"] + (["cx", "cz"] if a["move"] in ("cw", "ccw") else [])
        if a["move"] != b["move"] or max(abs(float(a[k]) - float(b[k])) for k in keys) > TOLERANCE:
            return f"move {n}: ours {a}, rs274 {b}"
    if len(ours) != len(theirs):
        return f"ours has {len(ours)} moves, rs274 {len(theirs)}"
    return None


def rs274_moves(text: str) -> list[dict[str, Any]]:
    return [m for m in canonical_moves(run_rs274(text, tool_table=TOOLS)) if "move" in m]


def simulated(text: str, setup: MachineSetup = RADIUS) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="prog.ngc", dialect="linuxcnc", setup=setup)
            if "move" in e]


# -- the engine against rs274 ------------------------------------------------------------------------
@needs_rs274
@pytest.mark.parametrize("code", CODES)
def test_engine_matches_rs274_on_random_profiles(code: str) -> None:
    """Ten random profiles a code: the cases the engine cuts run in one rs274 program, move for move;
    each case the engine refuses is run alone and rs274 must refuse it too."""
    rng = random.Random(f"{SEED}-{code}")
    cut: list[Case] = []
    expected: list[dict[str, Any]] = []
    for _ in range(10):
        case = draw(rng, code)
        try:
            moves = engine(case)
        except NgcCycleError as err:
            with pytest.raises(RS274Error):
                run_rs274(case.program(), tool_table=TOOLS)
            assert str(err)
            continue
        cut.append(case)
        expected.extend(moves)
    assert len(cut) >= 5, "the generator draws mostly profiles the controller cuts"
    theirs = rs274_moves(batch_program(cut))
    assert difference(expected, theirs) is None


# -- the reading against rs274 -----------------------------------------------------------------------
@needs_rs274
def test_reading_matches_rs274_on_random_closed_profiles() -> None:
    """The plugin's reading (subprograms, cycle words, the simulation) on closed profiles of every code."""
    rng = random.Random(SEED)
    cases: list[Case] = []
    while len(cases) < 14:
        case = draw(rng, CODES[len(cases) % len(CODES)])
        if not _closed_for_reading(case):
            continue
        try:
            engine(case)
        except NgcCycleError:
            continue
        cases.append(case)
    text = batch_program(cases)
    assert difference(simulated(text, ORACLE), rs274_moves(text)) is None


def _closed_for_reading(case: Case) -> bool:
    """The reading (of the oracle's version) cuts the case: the controller's own refusals aside."""
    try:
        simulated(Case(case.code, case.x, case.z, case.steps, case.words).program(), ORACLE)
    except (PostprocError, ErrorList) as err:
        assert "G7X error" in str(err) or "rs274" in str(err), str(err)
        return False
    return True


PARAMETRIC = """G18 G8 G21 G90
F100
#<_d>=0
#31=1
O100 SUB
G1 X5 Z[0+#<_d>]
G1 Z[-10+#<_d>]
G2 X[5+#31] Z[-11+#<_d>] R1
G1 X12
O100 ENDSUB
#<_d>=3
G0 X12 Z5
G71 Q100 X12 Z5 D0 I1 R0.5
G70 Q100 X12 Z5
M2
"""
"""A profile whose words read global parameters (as LinuxCNC's nc_files/lathe_g7x_quadrants.ngc, issue 26's
held-out set): ``#<_d>`` is 0 where the subprogram is defined and 3 where the cycles run."""


@needs_rs274
def test_a_profile_with_computed_words_takes_the_parameters_where_the_cycle_runs() -> None:
    """rs274 cuts the profile at Z 3 down to Z -8 (its values at the cycles: -10 + 3 and -11 + 3), not at 0 to
    -11; the reading cuts the same moves."""
    ours, theirs = simulated(PARAMETRIC), rs274_moves(PARAMETRIC)
    assert min(float(m["z"]) for m in theirs) == pytest.approx(-8.0)
    assert difference(ours, theirs) is None


POSITIONAL = """G21 G18 G{mode} G90
F100
O100 SUB
G1 X[#<_x>-{a}] Z[#<_z>-4]
G1 Z[#<_z>-3]
G1 X[#<_x>+{b}]
G1 X[#<_x>+{c}] Z[#5422-4]
O100 ENDSUB
G0 X{far} Z9
G71 Q100 X{x} Z5 D0 I1 R0.5
G70 Q100 X{x} Z5
M2
"""
"""A profile stepped by the current position (as LinuxCNC's ``nc_files/lathe_g7x_face_boring.ngc``, issue 26's
held-out set): each word reads the point the profile's moves so far reach, from the cycle's X and Z, not where the
tool stood before the cycle (X{far} Z9)."""


@needs_rs274
@pytest.mark.parametrize("mode", [8, 7])
def test_a_profile_reading_the_current_position_reads_its_own_point(mode: int) -> None:
    """rs274 (2.9.0~pre1) cuts the G8 profile from the cycle's point X12 Z5 to X2 Z1, Z-2, X6, X12 Z-6 (hand-derived
    from the words, the position read as the profile's point); under G7, where the cycle's X is the diameter 24,
    ``#<_x>`` reads the radius (12 at the cycle's point), so words that add diameters to the radii read (X[#<_x>-8]
    is the diameter 4, radius 2) cut the same. The reading cuts rs274's moves in both."""
    if mode == 8:
        text = POSITIONAL.format(mode=8, a=10, b=4, c=6, far=40, x=12)
        setup = RADIUS
    else:  # the radius 12 read: X[12-8] = 4 (radius 2); 2 read: X[2+4] = 6 (radius 3); 3 read: X[3+21] = 24
        text = POSITIONAL.format(mode=7, a=8, b=4, c=21, far=80, x=24)
        setup = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="diameter"))
    theirs = rs274_moves(text)
    ours = simulated(text, setup)
    if mode == 7:
        ours = [{k: float(v) / 2.0 if k in ("x", "cx") else v for k, v in e.items()} for e in ours]
    assert min(float(m["z"]) for m in theirs) == pytest.approx(-6.0)
    assert difference(ours, theirs) is None
    if mode == 8:
        assert {(float(m["x"]), float(m["z"])) for m in theirs} >= {(2.0, 1.0), (2.0, -2.0), (6.0, -2.0), (12.0, -6.0)}


STATEMENTS = ["O101 REPEAT [2]\nG1 X[#<_x>+1] Z[#<_z>-1]\nG1 Z[#<_z>-0.5]\nO101 ENDREPEAT",
              "#<_step> = 1\nG1 X[#<_x>+#<_step>] Z-2",
              "O101 IF [1 GT 0]\nG1 X3 Z-2\nO101 ENDIF",
              "#1=0\nO101 WHILE [#1 LT 2]\nG1 X[2+#1] Z[-1-#1*1.5]\nG1 Z[-1.5-#1*1.5]\n#1=[#1+1]\nO101 ENDWHILE"]


def _statement_program(statement: str) -> str:
    return f"G18 G8 F100\nO100 SUB\nG1 X1 Z0\n{statement}\nG1 X6 Z-4\nO100 ENDSUB\nG0 X6 Z1\nG70 Q100 X6 Z1\nM2\n"


@needs_rs274
@pytest.mark.parametrize("statement", STATEMENTS)
def test_a_control_statement_in_a_profile_runs_as_rs274_runs_it(statement: str) -> None:
    """LinuxCNC runs a profile's o-word loops, branches and assignments as it reads the profile (rs274 cuts
    ``nc_files/lathe_g7x_face_boring.ngc``'s REPEAT [3] three times); so does the reading (issue 26: before, it
    took a loop's moves once, then refused the statement). rs274's moves, move for move."""
    text = _statement_program(statement)
    ours, theirs = simulated(text), rs274_moves(text)
    assert len(without_repeats(theirs)) >= 4
    assert difference(ours, theirs) is None


def test_a_repeat_in_a_profile_cuts_each_pass() -> None:
    """Hand-derived (no rs274 needed): G70 (D = E = 0, one pass) over X1 Z0, then twice X+1 Z-1 and Z-0.5 from
    the profile's own point, then X6 Z-4 cuts X2 Z-1, X2 Z-1.5, X3 Z-2.5, X3 Z-3, X6 Z-4 after its approach."""
    moves = [(m["move"], float(m["x"]), float(m["z"])) for m in simulated(_statement_program(STATEMENTS[0]))]
    expected = [("feed", 2.0, -1.0), ("feed", 2.0, -1.5), ("feed", 3.0, -2.5), ("feed", 3.0, -3.0),
                ("feed", 6.0, -4.0)]
    assert [(k, pytest.approx(x), pytest.approx(z)) for k, x, z in moves[-5:]] == expected


def _copied(text: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="prog.ngc", source="linuxcnc", target="linuxcnc", setup=RADIUS)
    return out.getvalue()


@pytest.mark.parametrize("statement", STATEMENTS)
def test_a_control_statement_in_a_profile_of_a_copy_is_kept_as_written(statement: str) -> None:
    """A LinuxCNC program copied to LinuxCNC is not run, so neither is its profile: its cycle, subprogram and all,
    is kept as written (was: refused), and LinuxCNC runs the profile's statements where the cycle reads them, as
    it would the source's. A copy of a program to its own controller is the program itself, byte for byte;
    ``verify`` runs both and compares the cycle's moves."""
    text = _statement_program(statement)
    assert _copied(text) == text
    report = verify_lines(io.StringIO(text), io.StringIO(text), file_in="in.ngc", file_out="out.ngc",
                          source="linuxcnc", target="linuxcnc", setup=RADIUS)
    assert report.ok and report.moves >= 4, report.summary()


COMPUTED = [("#<_d>=1\n", "G1 X[2+#<_d>] Z-2", 3.0), ("#31=1\n", "G1 X[2+#31] Z-2", 3.0),
            ("#1=1\n", "G1 X[2+#1] Z-2", 2.0), ("", "G1 X[#<_x>+1] Z-2", 2.0), ("", "G[1] X3 Z-2", 3.0)]
"""A profile's second block with a computed word: reading a global parameter (named, numbered), a local one (the
profile's own call's, 0: ``test_a_local_parameter_in_a_profile_is_the_profiles_own``), the current position (the
profile's point, X1 after its first block), or giving the G code; and the X it reaches where the program runs."""


def _computed_program(before: str, line: str) -> str:
    return f"G18 G8 F100\nO100 SUB\nG1 X1 Z0\n{line}\nG1 X6 Z-4\nO100 ENDSUB\n{before}G0 X6 Z1\nG70 Q100 X6 Z1\nM2\n"


@pytest.mark.parametrize("before, line, x", COMPUTED)
def test_a_computed_profile_word_of_a_copy_is_kept_as_written_whatever_it_reads(
        before: str, line: str, x: float) -> None:
    """A program copied to LinuxCNC is not run, so no parameter has a value where the cycle would read the profile
    here; LinuxCNC gives each its value where the cycle runs [V: rs274 below], so the cycle is kept as written
    (was: refused, the copy of a LinuxCNC lathe program with a parametric profile, as LinuxCNC's own
    ``nc_files/lathe_g7x_quadrants.ngc``, impossible). The copy is the program byte for byte, and rs274 cuts it
    as the simulation of the source does."""
    text = _computed_program(before, line)
    written = _copied(text)
    assert written == text
    if available():
        assert difference(simulated(text), rs274_moves(written)) is None


def test_linuxcncs_quadrants_with_computed_cycle_words_copy_byte_for_byte() -> None:
    """LinuxCNC's own ``nc_files/lathe_g7x_quadrants.ngc`` computes its later cycles' Z (``Z[-14+#<_distance>]``
    after ``#<_distance>=[#<_distance>+12]``): its copy to LinuxCNC was refused ("a computed word in G72 is not
    supported"); the copy is now the program itself, and ``verify`` (which runs both) passes."""
    from postproc.setup.machine_setup import load_setup

    path = ROOT / "tests" / "heldout" / "linuxcnc" / "lathe_g7x_quadrants.ngc"
    setup = load_setup(str(ROOT / "tests" / "heldout" / "setups" / "linuxcnc_lathe_radius.xml"))
    text = path.read_text()
    out = io.StringIO()
    translate(io.StringIO(text), out, file=path.name, source="linuxcnc", target="linuxcnc", setup=setup)
    assert out.getvalue() == text
    report = verify_lines(io.StringIO(text), io.StringIO(text), file_in="in.ngc", file_out="out.ngc",
                          source="linuxcnc", target="linuxcnc", setup=setup)
    assert report.ok and report.moves > 100, report.summary()


def test_after_a_cycle_kept_as_written_the_tool_is_where_the_program_says_next() -> None:
    """The kept cycle's moves are not known to the copy, nor where it leaves the tool: the next absolute move
    places it again, and the copy goes on (the blocks after the cycle are copied as written too)."""
    text = _computed_program("#<_d>=1\n", "G1 X[2+#<_d>] Z-2").replace("M2\n", "G1 X8 Z0\nG91 G1 X1\nG90\nM2\n")
    assert _copied(text) == text


def test_a_copy_that_runs_the_program_writes_the_cycles_moves() -> None:
    """``_kept_as_written`` serves a plain copy alone: a copy that rewrites the program (``--units``) runs it,
    so the profile is run and its computed word takes its value (X3, hand-derived: ``#31`` is 1 where the cycle
    reads it); the simulation of that output cuts what the source's does."""
    text = _computed_program("#31=1\n", "G1 X[2+#31] Z-2")
    out = io.StringIO()
    translate(io.StringIO(text), out, file="prog.ngc", source="linuxcnc", target="linuxcnc", setup=RADIUS,
              units="mm", diagnostics=Diagnostics(warn_stream=io.StringIO()))
    written = out.getvalue()
    assert "#31" not in written
    moves = [(m["move"], float(m["x"]), float(m["z"])) for m in simulated(written)]
    assert [(k, pytest.approx(mx), pytest.approx(mz)) for k, mx, mz in moves[-3:]] == [
        ("rapid", 1.0, 0.0), ("feed", 3.0, -2.0), ("feed", 6.0, -4.0)], written


@pytest.mark.parametrize("before, line, x", COMPUTED)
def test_a_computed_profile_word_of_a_program_that_runs_is_read(before: str, line: str, x: float) -> None:
    """The same programs run (the simulation, a translation to Fanuc): the profile runs with them, each computed
    word taking its value where the cycle reads it (one finishing pass: to X1 Z0, then X``x`` Z-2, then X6 Z-4)."""
    moves = [(m["move"], float(m["x"]), float(m["z"])) for m in simulated(_computed_program(before, line))]
    assert [(k, pytest.approx(mx), pytest.approx(mz)) for k, mx, mz in moves[-3:]] == [
        ("rapid", 1.0, 0.0), ("feed", x, -2.0), ("feed", 6.0, -4.0)]
    translate(io.StringIO(_computed_program(before, line)), io.StringIO(), file="prog.ngc", source="linuxcnc",
              target="fanuc", setup=RADIUS)

@pytest.mark.parametrize("code", ["G70 Q100 X6 Z1", "G71 Q100 X6 Z1 D0.5"])
def test_a_program_flattened_for_its_computed_profile_says_so(code: str) -> None:
    """Flattened for Fanuc, the warning gives the true reason (the cycle computes, so only LinuxCNC takes it as
    written); it said "no subprogram o100 is defined before the cycle", which is defined on line 2: the dry run
    that finds the reason (``postproc.api._keep_check``) did not see the subprograms the reader had found."""
    text = _computed_program("#31=1\n", "G1 X[2+#31] Z-2").replace("G70 Q100 X6 Z1", code)
    warnings = io.StringIO()
    translate(io.StringIO(text), io.StringIO(), file="prog.ngc", source="linuxcnc", target="fanuc", setup=RADIUS,
              diagnostics=Diagnostics(warn_stream=warnings))
    assert warnings.getvalue() == (
        f"prog.ngc:2:1: warning: the program is flattened (its evaluated motion is written): line 9: {code.split()[0]} "
        "(a G70-G72 cycle that computes, kept as written (its moves are known where it runs)) from linuxcnc has no "
        "equivalent in fanuc\n")


LOCAL = "G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X[2+#1] Z-4\nG1 X6\nO100 ENDSUB\n#1=1.5\nG0 X6 Z1\nG70 Q100 X6 Z1\nM2\n"


@needs_rs274
def test_a_local_parameter_in_a_profile_is_the_profiles_own() -> None:
    """The cycle calls its profile as a subprogram: ``#1`` there is the call's own local (0, no argument), not the
    caller's 1.5 [rs274 2.9.0~pre1: the profile's second point is X2, not X3.5]. Refused before issue 26 (the
    reading did not keep the call's level); now run as the controller runs it."""
    ours, theirs = simulated(LOCAL), rs274_moves(LOCAL)
    assert [(m["move"], m["x"], m["z"]) for m in theirs[-2:]] == [("feed", 2.0, -4.0), ("feed", 6.0, -4.0)]
    assert difference(ours, theirs) is None


STATEMENT_CASES = 35
"""Random profiles run through statements in ``make test`` (five a code)."""


@needs_rs274
def test_profiles_run_through_statements_match_rs274() -> None:
    """Random profiles (``tests.support.g7x_statements``: tables of global parameters, moves from the current
    position, WHILE, DO and REPEAT loops, IF/ELSEIF/ELSE branches with decoy moves, locals and calls of other
    subprograms) in every code: the reading runs each profile's statements as rs274 does and cuts rs274's moves.
    Profiles the reading refuses for another reason (not closed, not monotonic) are drawn again."""
    rng = random.Random(f"{SEED}-statements")
    cases: list[StatementCase] = []
    while len(cases) < STATEMENT_CASES:
        drawn = draw_with_statements(rng, CODES[len(cases) % len(CODES)], 200 + 20 * len(cases))
        if not _closed_for_reading(drawn.case):
            continue
        try:
            engine(drawn.case)
        except NgcCycleError:
            continue
        cases.append(drawn)
    statements = sum(any(" WHILE " in b or " REPEAT " in b or " IF " in b or " CALL " in b for b in c.body)
                     for c in cases)
    assert statements >= STATEMENT_CASES // 2, "most profiles hold a loop, a branch or a call"
    for at in range(0, len(cases), 12):
        text = batch(cases[at:at + 12])
        assert difference(simulated(text, ORACLE), rs274_moves(text)) is None


@needs_rs274
def test_demo_without_its_compensation_matches_rs274() -> None:
    """LinuxCNC's own nc_files/lathe_g70_71_demo.ngc (G71.1, G71.2, G70 over a profile with arcs and a fillet)
    with its G42.1 left out: 222 moves, the same as rs274's."""
    text = DEMO.read_text().replace("G42.1 D0.3 L2", "")
    ours, theirs = simulated(text), rs274_moves(text)
    assert len(without_repeats(theirs)) > 200
    assert difference(ours, theirs) is None


def test_demo_refused_where_its_g70_runs_under_compensation() -> None:
    with pytest.raises((PostprocError, ErrorList)) as err:
        simulated(DEMO.read_text())
    assert "G70 with cutter compensation on is not modelled" in str(err.value)
    assert ":32:" in str(err.value)


# -- versions ------------------------------------------------------------------------------------------
def versioned(version: str, mode: str = "radius") -> MachineSetup:
    return MachineSetup(input=InputSettings(machine_type="lathe", x_programming=mode),  # type: ignore[arg-type]
                        controller=ControllerSettings(version=version))


def closing_step(case: Case) -> Step:
    """The line LinuxCNC 2.9.1 and later add to a roughing profile (``convert_g7x``): from its end to the cycle's
    X (G71) or Z (G72)."""
    last = case.steps[-1]
    return Step(1, last.x, case.z) if case.code.startswith("72") else Step(1, case.x, last.z)


def open_cases(version: str, count: int) -> list[tuple[Case, Case]]:
    """Random roughing cases whose profile does not end at the cycle's X (Z), each with its profile as ``version``
    runs it: the same profile (2.9.0), or with the line the version adds written out. Derived from the source
    (``interp_g7x.cc``): from 2.9.1 the line is the only change to a roughing cycle up to 2.9.8 (the files differ in
    that and in G70's compensation alone), so rs274 2.9.0 cutting the profile with the line written out cuts what
    the later version cuts of the open one."""
    rules = rules_of(tuple(int(n) for n in version.split(".")))
    assert rules is not None
    rng = random.Random(f"{SEED}-open-{version}")
    out: list[tuple[Case, Case]] = []
    while len(out) < count:
        case = draw(rng, ("71", "71.1", "71.2", "72", "72.1", "72.2")[len(out) % 6])
        pieces = pieces_of(case)
        facing = case.code.startswith("72")
        if not any(closes(r, facing, pieces, case.x, case.z) for r in (V2_9_1, V2_9_4)):
            continue  # ends at the cycle's X (Z): every version cuts it the same
        cut = Case(case.code, case.x, case.z, case.steps + [closing_step(case)], case.words) \
            if closes(rules, facing, pieces, case.x, case.z) else case
        out.append((case, cut))
    return out


@pytest.mark.parametrize("program", [
    "G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X3 Z-4\nO100 ENDSUB\nG0 X6 Z1\nG71 Q100 X6 Z1\nM2\n",
    "G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X3 Z-4\nG1 X7\nO100 ENDSUB\nG0 X6 Z1\nG71 Q100 X6 Z1\nM2\n"])
def test_without_a_version_a_profile_the_versions_close_differently_is_refused(program: str) -> None:
    """Short of the cycle's X (2.9.1 and 2.9.4 add a line, 2.9.0 does not) or past it (2.9.1-2.9.3 add one back):
    the cut depends on the version, which the set-up does not name."""
    with pytest.raises((PostprocError, ErrorList)) as err:
        simulated(program)
    assert "not at the cycle's X6: LinuxCNC versions cut it differently" in str(err.value)
    assert "<Controller version=" in str(err.value)


@needs_rs274
@pytest.mark.parametrize("version", ["2.9.0", "2.9.2", "2.9.6"])
def test_an_open_roughing_profile_is_cut_as_the_set_ups_version_cuts_it(version: str) -> None:
    """The set-up's ``<Controller version>`` picks the version's cut (``open_cases``): 2.9.0's is rs274's own;
    2.9.1-2.9.3 and 2.9.4-2.9.8 are rs274's cut of the profile with the line their source adds written out. A case
    rs274 refuses must be refused too."""
    setup = versioned(version)
    cut: list[tuple[Case, Case]] = []
    for case, expected in open_cases(version, 12):
        try:
            rs274_moves(expected.program())
        except RS274Error:
            with pytest.raises((PostprocError, ErrorList)):
                simulated(case.program(), setup)
            continue
        cut.append((case, expected))
    assert len(cut) >= 6, "the generator draws mostly profiles the controller cuts"
    ours = simulated(batch_program([case for case, _ in cut]), setup)
    assert difference(ours, rs274_moves(batch_program([expected for _, expected in cut]))) is None


def test_a_profile_past_the_cycles_x_is_closed_back_by_2_9_1_to_2_9_3_only(monkeypatch: pytest.MonkeyPatch) -> None:
    """A G71 profile ending at X7, past the cycle's X6: 2.9.1-2.9.3 add a line back to X6 (``x!=imag(start)``), 2.9.4
    and 2.9.0 do not (2.9.4: only a profile ending short, ``imag(dfront)*(x-imag(start))<0``). Derived from the
    source: 2.9.4 cuts the open profile as 2.9.0 does; 2.9.1-2.9.3 cut it as 2.9.0 cuts the profile with the line
    back written out, where the pocket walk never ends (the bug 2.9.4's bb75d9cc fixed: "I broke the case where the
    leadout was exceeding the starting point"): refused as a cycle that would not end."""
    import postproc.rs274.ngc_g7x as engine_module
    monkeypatch.setattr(engine_module, "MAX_STEPS", 20_000)  # (the bound, not the walk: reached sooner)
    program = "G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X3 Z-4\nG1 X7\n{close}O100 ENDSUB\nG0 X6 Z1\nG71 Q100 X6 Z1\nM2\n"
    open_cut = simulated(program.format(close=""), versioned("2.9.0"))
    assert len(open_cut) > 10
    assert difference(simulated(program.format(close=""), versioned("2.9.4")), open_cut) is None
    for setup, text in ((versioned("2.9.2"), program.format(close="")), (ORACLE, program.format(close="G1 X6\n"))):
        with pytest.raises((PostprocError, ErrorList)) as err:
            simulated(text, setup)
        assert "(the controller would not end)" in str(err.value)


@pytest.mark.parametrize("version, message", [("2.8.4", "has no G70-G72"), ("2.11", "is not modelled")])
def test_a_version_outside_the_modelled_ones_is_refused(version: str, message: str) -> None:
    program = "G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG71 Q100 X6 Z1\nM2\n"
    with pytest.raises((PostprocError, ErrorList)) as err:
        simulated(program, versioned(version))
    assert message in str(err.value) and ":8:" in str(err.value)


@pytest.mark.parametrize("text, problem", [("2.9.x", "should match pattern"), ("2", "should match pattern")])
def test_the_version_attribute_is_checked_and_round_trips(tmp_path: Path, text: str, problem: str) -> None:
    """``config check`` refuses a version that is no release number; ``config dump`` writes a good one back."""
    from postproc.setup.machine_setup import load_setup
    good = tmp_path / "good.xml"
    good.write_text('<MachineSetup dialect="linuxcnc"><Input machineType="lathe"/><Controller version="2.9.4"/>'
                    "</MachineSetup>")
    setup = load_setup(str(good))
    assert setup.controller.version == "2.9.4" and setup.controller.release() == (2, 9, 4)
    bad = tmp_path / "bad.xml"
    bad.write_text(f'<MachineSetup dialect="linuxcnc"><Controller version="{text}"/></MachineSetup>')
    with pytest.raises(PostprocError) as err:
        load_setup(str(bad))
    assert problem in str(err.value)


@needs_rs274
@pytest.mark.parametrize("name", ["lathe_g7x_quadrants", "lathe_g7x_face_boring"])
def test_linuxcncs_own_open_profiles_under_2_9_0_match_rs274(name: str) -> None:
    """LinuxCNC's ``nc_files/lathe_g7x_quadrants.ngc`` (profiles ending short of the cycle's X) and
    ``lathe_g7x_face_boring.ngc`` (a REPEAT in its profile, stepping by ``#<_x>``; its G72 ends short of the cycle's
    Z), with the set-up naming 2.9.0 as the held-back set-up does: rs274's moves, move for move."""
    text = (ROOT / "tests" / "heldout" / "linuxcnc" / f"{name}.ngc").read_text()
    ours, theirs = simulated(text, versioned("2.9.0")), rs274_moves(text)
    assert len(without_repeats(theirs)) > 80
    assert difference(ours, theirs) is None


# -- translations --------------------------------------------------------------------------------------
def _demo_plain() -> str:
    """The demo without its compensation and tool changes (a turret lathe's own matter: item 4 of the task)."""
    text = DEMO.read_text().replace("G42.1 D0.3 L2", "")
    return "\n".join(line for line in text.splitlines() if "M6" not in line) + "\n"


def test_linuxcnc_keeps_its_cycles_byte_for_byte() -> None:
    text = DEMO.read_text().replace("G42.1 D0.3 L2", "")
    out = io.StringIO()
    translate(io.StringIO(text), out, file="demo.ngc", source="linuxcnc", target="linuxcnc", setup=RADIUS)
    assert out.getvalue() == text


def test_normalize_keeps_the_cycles_words() -> None:
    """``--normalize`` rewrites each line from its words: a G70-G72's D (read apart, as a distance) was left out
    (``G71 .. D1`` became ``G71 ..``, another cut, exit 0). Its words now all stay, spelt with their points; rs274
    cuts the normalized demo as it cuts the demo itself."""
    text = _demo_plain()
    setup = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"))
    setup.output.normalize = True
    out = io.StringIO()
    translate(io.StringIO(text), out, file="demo.ngc", source="linuxcnc", target="linuxcnc", setup=setup)
    cycles = [line for line in text.splitlines() if re.match(r"G7[012]\b", line)]
    written = [line for line in out.getvalue().splitlines() if re.match(r"G7[012]\b", line)]
    assert cycles and [re.findall("[A-Z]", line) for line in written] == [re.findall("[A-Z]", line) for line in cycles]
    if available():
        assert difference(rs274_moves(out.getvalue()), rs274_moves(text)) is None


@pytest.mark.parametrize("target", ["fanuc", "gsk", "grblhal"])
def test_cycles_expanded_for_other_controllers_verify(target: str) -> None:
    """Fanuc T, GSK and grblHAL get the cycles' moves (LinuxCNC's algorithm is none of theirs: see
    ``postproc.rs274.ngc_g7x``), and the translation cuts the source's path exactly."""
    text = _demo_plain()
    out = io.StringIO()
    translate(io.StringIO(text), out, file="demo.ngc", source="linuxcnc", target=target, setup=RADIUS,
              on_unsupported="error")
    written = out.getvalue()
    assert not re.search(r"^\s*(N\d+\s*)?G7[0-2]\b", written, re.M), "no cycle is left to the target"
    report = verify_lines(io.StringIO(text), io.StringIO(written), file_in="demo.ngc", file_out="out.nc",
                          source="linuxcnc", target=target, setup=RADIUS, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


# -- refusals --------------------------------------------------------------------------------------------
PROFILE = "O100 SUB\nG1 X1 Z0\nG1 X3 Z-4\nG1 X5\nO100 ENDSUB\n"


@pytest.mark.parametrize("program, message", [
    ("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG71 X6 Z1\nM2\n", "needs Q"),
    ("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG71 Q200 X6 Z1\nM2\n", "no subprogram o200"),
    ("G17 G8 F100\n" + PROFILE + "G0 X6 Z1\nG71 Q100 X6 Z1\nM2\n", "ZX plane"),
    ("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG71 Q100 X6 Z1 I0\nM2\n", "must be above 0"),
    ("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG91 G71 Q100 X0 Z0\nM2\n", "incremental mode"),
    ("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG42.1 D1\nG71 Q100 X6 Z1\nM2\n", "cutter compensation enabled"),
    ("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG70 Q100 X6 Z1 P1.5\nM2\n", "whole number"),
    ("G18 G8 F100\nO100 SUB\nG1 X1 Z0 F50\nG1 X5 Z-4\nO100 ENDSUB\nG0 X6 Z1\nG71 Q100 X6 Z1\nM2\n",
     "ignores it there"),
    ("G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X3 Z-4\nO100 ENDSUB\nG0 X6 Z1\nG71 Q100 X6 Z1\nM2\n",
     "not at the cycle's X"),
    ("G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X3 Z-4 A0.2 C0.2\nG1 X6\nO100 ENDSUB\nG0 X6 Z1\nG71 Q100 X6 Z1\nM2\n",
     "both A and C"),
    ("G18 G8 F100\nO100 SUB\nG1 X1 Z0\nG1 X3 Z-4 A0.2\nG1 X6\nO100 ENDSUB\nG0 X6 Z1\no100 call\nM2\n",
     "only a G70-G72 cycle"),
])
def test_refusals(program: str, message: str) -> None:
    with pytest.raises((PostprocError, ErrorList)) as err:
        simulated(program)
    assert message in str(err.value)


@needs_rs274
def test_refused_g71_under_compensation_is_refused_by_rs274() -> None:
    with pytest.raises(RS274Error, match="cutter compensation"):
        run_rs274("G18 G8 F100\n" + PROFILE + "G0 X6 Z1\nG42.1 D1\nG71 Q100 X6 Z1\nM2\n")


UNDER_COMPENSATION = [(on, cycle) for on in ("G41 D1", "G42", "G41.1 D1", "G42.1 D0.5")
                      for cycle in ("G71", "G71.1", "G71.2", "G72", "G72.1", "G72.2")]


@pytest.mark.parametrize("on, cycle", UNDER_COMPENSATION)
def test_roughing_under_compensation_is_refused_where_and_as_rs274_refuses_it(on: str, cycle: str) -> None:
    """G71/G72 (each sub-cycle) with compensation on, by a tool's radius or by a diameter, either side:
    LinuxCNC refuses the block [V: ``interp_g7x.cc`` ``convert_g7x``: "G%d.%d cannot be used with cutter
    compensation enabled" for every cycle but 70]; so does the reading, quoting rs274's words, at the G word
    of the cycle's line (10)."""
    shown = cycle if "." in cycle else cycle + ".0"
    program = f"G18 G8 G21 F100\n{PROFILE}T1 M6\nG0 X6 Z1\n{on}\n{cycle} Q100 X6 Z1\nG40\nM2\n"
    with pytest.raises((PostprocError, ErrorList)) as err:
        simulated(program)
    assert f":10:1: error: {cycle} with cutter compensation on (rs274: \"{shown} cannot be used with cutter " \
        "compensation enabled\")" in str(err.value)
    if available():
        table = "T1 P1 Z0 D0.04 Q3\n"
        with pytest.raises(RS274Error) as theirs:
            run_rs274(program, tool_table=table)
        assert f"{shown} cannot be used with cutter compensation enabled" in theirs.value.stderr


def test_mill_keeps_the_codes_verbatim() -> None:
    """On a mill set-up the codes are not read (LinuxCNC runs them on a lathe's XZ plane only)."""
    text = "G18 F100\n" + PROFILE + "G0 X6 Z1\nG71 Q100 X6 Z1\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="m.ngc", source="linuxcnc", target="linuxcnc", setup=MachineSetup())
    assert out.getvalue() == text
    with pytest.raises((PostprocError, ErrorList), match="cannot be simulated"):
        simulated(text, MachineSetup())


# -- another family's cycles towards LinuxCNC ------------------------------------------------------------
FANUC_G71 = """O0001
G18 G21 G40 G97 G99
T0101
M3 S500
G0 X12. Z2.
G71 U1. R0.5
G71 P10 Q20 U0. W0. F0.2
N10 G0 X2.
G1 Z-5.
X6. Z-8.
Z-12.
N20 X12.
G0 X20. Z5.
M30
"""
LINUXCNC_G71 = """G18 G21 G8 G90 G40
F100
O100 SUB
G0 X1
G1 Z-5
G1 X3 Z-8
G1 Z-12
G1 X6
O100 ENDSUB
G0 X6 Z2
G71 Q100 X6 Z2 D0 I1 R0.5
M2
"""


@needs_rs274
def test_fanuc_g71_is_not_linuxcnc_g71_so_it_stays_expanded() -> None:
    """The same profile, depth 1 and retract 0.5 (radii): Fanuc T's G71 cuts its first layer one depth below the
    start and goes back along Z at the retracted X [our Fanuc simulation, itself held to hand-derived paths in
    tests/test_lathe.py]; LinuxCNC's cuts the first layer at the start's X and goes back diagonally [rs274]. So a
    Fanuc T or GSK G71 is written to LinuxCNC as its moves, never as LinuxCNC's G71."""
    from postproc.setup.machine_setup import load_setup
    fanuc_setup = load_setup(str(ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"))
    fanuc = [(e["move"], float(e["x"]) / 2.0, float(e["z"])) for e in
             toolpath_events(io.StringIO(FANUC_G71), file="f.nc", dialect="fanuc", setup=fanuc_setup) if "move" in e]
    linuxcnc = [(m["move"], m["x"], m["z"]) for m in rs274_moves(LINUXCNC_G71)]
    assert fanuc[1:4] == [("rapid", 5.0, 2.0), ("feed", 5.0, -12.0), ("rapid", 5.5, -11.5)]
    assert fanuc[4] == ("rapid", 5.5, 2.0)
    assert linuxcnc[1:5] == [("feed", 6.0, -12.0), ("rapid", 6.5, -11.5), ("rapid", 6.5, 1.5), ("rapid", 6.0, 2.0)]
    out = io.StringIO()
    translate(io.StringIO(FANUC_G71), out, file="f.nc", source="fanuc", target="linuxcnc", setup=fanuc_setup)
    assert not re.search(r"^\s*(N\d+\s*)?G7[0-2]\b", out.getvalue(), re.M)


DIAMETER_PROGRAM = """G18 G21 G7 G90 G40
F100
O100 SUB
G0 X2 Z0
G1 W-5
G1 U4 W-3
G3 X8 Z-9 I0 K-1
G1 Z-12
G1 X12
O100 ENDSUB
G0 X12 Z2
G71 Q100 X12 Z2 D0.2 I1 R0.5
G70 Q100 X12 Z2 D0.1 P1
M2
"""


@needs_rs274
def test_diameter_mode_reads_x_and_u_as_diameters() -> None:
    """Under G7 the profile's and the cycle's X and U are diameters, its arc centres, D, I and R radial [rs274]."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="diameter"))
    ours = [{k: float(v) / 2.0 if k in ("x", "cx") else v for k, v in e.items()} for e in simulated(DIAMETER_PROGRAM, setup)]
    theirs = rs274_moves(DIAMETER_PROGRAM)
    assert len(without_repeats(theirs)) > 30
    assert difference(ours, theirs) is None


# -- properties ----------------------------------------------------------------------------------------------
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=60, deadline=None)
@given(st.integers(min_value=0, max_value=2**32))
def test_g70_without_allowance_follows_the_profile(seed: int) -> None:
    """G70 with D = E = 0 in one pass is a rapid towards the cycle's point, a rapid to the profile's first point,
    then the profile itself, piece by piece [K: g-code.adoc "The path given in Q- is followed using the G1
    and G2/G3 commands"] (profiles without corners: a fillet or chamfer changes the path)."""
    case = draw(random.Random(seed), "70")
    for step in case.steps:
        step.words.pop("A", None)
        step.words.pop("C", None)
    case.words = {}
    try:
        moves = engine(case)
    except NgcCycleError:
        return  # a profile the controller refuses (not monotonic): checked against rs274 above
    expected = [(s.x, s.z) for s in case.steps]
    if any(math.dist(a, b) < 2e-3 for a, b in zip(expected, expected[1:])):
        return  # a piece shorter than 0.001 mm is dropped before the finish (the engine's ``corners``, after the
        # ``do_finish`` of the installed rs274's interp_g7x.cc as the engine cites it): held to rs274 by the
        # differential above, not by this hand rule (a chord of 0.002 mm or more is a piece of 0.001 mm or more)
    assert [m["move"] for m in moves[:3]] == ["rapid"] * 3  # (the helper's rapid to the cycle's point first)
    assert (moves[2]["x"], moves[2]["z"]) == pytest.approx(expected[0])  # (the first rapid may stop short of
    # the cycle's point: the approach is cut back to the profile's start Z, or X for a facing profile)
    drawn = [(m["x"], m["z"]) for m in moves[3:]]
    assert len(drawn) == len(expected) - 1
    for (x, z), (ex, ez) in zip(drawn, expected[1:]):
        assert x == pytest.approx(ex, abs=1e-9) and z == pytest.approx(ez, abs=1e-9)
    kinds = [m["move"] for m in moves[3:]]
    assert kinds == [{0: "feed", 1: "feed", 2: "cw", 3: "ccw"}[s.g] for s in case.steps[1:]]
