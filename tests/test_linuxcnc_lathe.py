"""LinuxCNC as a lathe: reading its lathe words, and Fanuc T / GSK lathe programs translated to it.

Expected texts are derived by hand from the rules in ``postproc_linuxcnc.lathe`` / ``lathe_writer`` (each
checked with rs274 2.9): the mode line ``G18 G7``, ``G96 S.. D..`` carrying the Fanuc-family clamp, a thread
as ``G33 .. K..`` with its F on a line before it, K along the path (``postproc.geometry.thread_lead``). The done-when
programs (the bundled Fanuc T and GSK examples, and the seed's GSK G71/G70) verify at zero deviation and
run in rs274 with the same moves as their source.
"""

from __future__ import annotations

import io
import math
import re
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.ir import NativeCode
from postproc.ir.lathe_sections import SpindleClamp, SpindleMode, ThreadLead
from postproc.setup.machine_setup import InputSettings, MachineSetup, load_setup
from postproc.simulate.verify import verify_lines
from postproc.api import read_program
from tests.support.rs274 import available, run_rs274
from tests.test_lathe import SEED
from tests.test_lathe_rs274 import TOOLS, difference, ours, theirs

ROOT = Path(__file__).resolve().parents[1]
SETUPS = ROOT / "examples" / "setups"
FANUC_T = load_setup(str(SETUPS / "fanuc_0i_tf.xml"))
GSK = load_setup(str(SETUPS / "gsk_980tdc.xml"))
LINUXCNC_LATHE = load_setup(str(SETUPS / "linuxcnc_lathe.xml"))
PROGRAMS = [("fanuc", FANUC_T, p) for p in sorted((ROOT / "examples" / "fanuc-lathe").glob("*.nc"))] + \
    [("gsk", GSK, p) for p in sorted((ROOT / "examples" / "gsk").glob("*.nc"))]


def write(text: str, source: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target="linuxcnc", setup=setup)
    return out.getvalue()


def code_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line[:1] not in ("(", "%", "")]


# -- done when ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("dialect,setup,path", [*PROGRAMS, ("gsk", GSK, "seed")],
                         ids=[p.name for _, _, p in PROGRAMS] + ["gsk-seed"])
def test_done_when_lathe_programs_verify_and_run_in_rs274(dialect: str, setup: MachineSetup, path: Path | str) -> None:
    text = SEED if path == "seed" else Path(path).read_text()
    ngc = write(text, dialect, setup)
    assert code_lines(ngc)[0] == "G18 G7"
    report = verify_lines(io.StringIO(text), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc", source=dialect,
                          target="linuxcnc", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    # the spindle's speed, its mode (G96 / G97) and G96's clamp, which the path does not show, in force alike
    # (verify lists a difference: ``test_verify_lists_a_lost_g96_and_a_lost_clamp``)
    assert not [line for line in report.ignored if line.startswith("spindle")], report.summary()
    if available():
        problem = difference(ours(text, dialect, setup), theirs(ngc))
        assert problem is None, f"{problem}\n\n{ngc}"
        assert spindle_modes_rs274(ngc) == spindle_modes_read(text, dialect, setup), ngc


NO_CLAMP = 1e30
"""rs274's ``SET_SPINDLE_MODE`` maximum for a G96 without D (it prints 1e30) [V: rs274 2.9, run here]."""


def spindle_modes_rs274(ngc: str) -> list[float]:
    """The spindle modes rs274 sets running ``ngc``: 0 for rpm (G97), else constant surface speed with that clamp
    (``SET_SPINDLE_MODE(spindle css_maximum)``), repeats and the power-on rpm left out, and the program end's
    reset to rpm (M2/M30 print ``SET_SPINDLE_MODE(0 0.0000)`` among their resets, M30 then ``PALLET_SHUTTLE()``,
    before ``PROGRAM_END()`` [V: rs274 2.9, run here]) too: a Fanuc or GSK program has no such call to compare it
    with."""
    calls = run_rs274(ngc, tool_table=TOOLS)
    end = next(i for i, call in enumerate(calls) if "PROGRAM_END" in call)
    end = next(i for i in range(end - 1, end - 4, -1) if "SET_SPINDLE_MODE(0 0.0000)" in calls[i])
    values = [float(call.split("(", 1)[1].split()[1].rstrip(")")) for call in calls[:end] if "SET_SPINDLE_MODE" in call]
    return _changes([NO_CLAMP if v > 1e29 else v for v in values])


def spindle_modes_read(text: str, dialect: str, setup: MachineSetup) -> list[float]:
    """The same, from the source as its own dialect reads it: a clamp (Fanuc ``G50 S``, LinuxCNC ``D``) limits
    constant surface speed only, from the G96 it is in force at [K: Fanuc 0i-TF, "Constant surface speed
    control"; V: LinuxCNC G96 D]."""
    css, clamp, values = False, NO_CLAMP, []
    for block in read_program(io.StringIO(text), file="in.nc", dialect=dialect, setup=setup):
        limit = block.sections.get("SpindleClamp")
        if isinstance(limit, SpindleClamp):
            clamp = float(limit.rpm)  # type: ignore[arg-type]
        mode = block.sections.get("SpindleMode")
        if isinstance(mode, SpindleMode):
            css = mode.mode == "css"
        if isinstance(limit, SpindleClamp) or isinstance(mode, SpindleMode):
            values.append(clamp if css else 0.0)
    return _changes(values)


def _changes(values: list[float]) -> list[float]:
    out: list[float] = []
    for v in values:
        if (out[-1] if out else 0.0) != v:
            out.append(v)
    return out


def test_done_when_the_bundled_programs_carry_css_feed_per_rev_and_threads() -> None:
    outputs = {p.name: write(p.read_text(), d, s) for d, s, p in PROGRAMS}
    assert "G96 D2500 S180 M3" in outputs["o2001_stepped_shaft.nc"].splitlines()  # G50 S2500 + G96 S180
    assert all("G95" in text for name, text in outputs.items() if name.startswith("o2"))  # Fanuc T: G99
    for name in ("o2003_thread.nc", "o0103_thread.nc"):
        assert any(line.startswith("G33 ") and " K" in line for line in outputs[name].splitlines()), name


CSS_SOURCE = "G50 S2500\nG96 S180 M03\nG00 X50. Z2.\nG01 X40. F0.2\nM30\n"
"""Fanuc T: the clamp 2500 rpm, then constant surface speed 180 m/min (DIALECTS.md 2.2)."""
CSS_KEPT = "G18 G7\nG21 G95\nG96 D2500 S180 M3\nG0 X50. Z2.\nG1 X40. F0.2\nM2\n"
"""The same written by hand for LinuxCNC: ``G96 D.. S..``, D the clamp [V: LinuxCNC G-code reference, G96]."""


@pytest.mark.parametrize("out, listed", [
    (CSS_KEPT, []),
    (CSS_KEPT.replace("G96 D2500 S180", "G97 S180"),
     ["spindle speed clamp differs: IN 2500 rpm (line 1); OUT never set",
      "spindle speed mode differs: IN constant surface speed (line 2); OUT rpm (line 3)"]),
    (CSS_KEPT.replace("G96 D2500 S180", "G96 S180"), ["spindle speed clamp differs: IN 2500 rpm (line 1); OUT never set"]),
    (CSS_KEPT.replace("D2500", "D3000"), ["spindle speed clamp differs: IN 2500 rpm (line 1); OUT 3000 rpm (line 3)"]),
], ids=["kept", "g96-lost", "clamp-lost", "clamp-changed"])
def test_verify_lists_a_lost_g96_and_a_lost_clamp(out: str, listed: list[str]) -> None:
    """A translation that loses G96 or its clamp cuts the same path at another spindle speed: the path cannot show
    it, so verify lists it as it lists a different S (docs/verify.md: listed, the exit status unchanged). Before
    issue 29's audit a G97 in place of the G96 verified "ok" with nothing listed. Hand-written pairs."""
    report = verify_lines(io.StringIO(CSS_SOURCE), io.StringIO(out), file_in="in.nc", file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=FANUC_T, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    assert [line for line in report.ignored if line.startswith("spindle")] == listed, report.summary()


MODES_SOURCE = "G21 G99 G97 S500 M03\nG00 X50. Z2.\nG01 X40. F0.2\nG98\nG01 Z-10. F100.\nG99\nG01 X45. F0.1\nM30\n"
"""Fanuc T: per revolution (G99), a feed per minute (G98) in the middle, per revolution again (DIALECTS.md 2.2)."""
MODES_KEPT = "G18 G7\nG21 G95 G97 S500 M3\nG0 X50. Z2.\nG1 X40. F0.2\nG94\nG1 Z-10. F100.\nG95\nG1 X45. F0.1\nM2\n"
"""The same written by hand for LinuxCNC (G95 per revolution, G94 per minute)."""


@pytest.mark.parametrize("out, mismatch", [
    (MODES_KEPT, None),
    (MODES_KEPT.replace("G94\n", ""), "IN has feed per minute from here, OUT a feed to X40 Z-10 F100"),
    (MODES_KEPT.replace("G95\nG1 X45.", "G1 X45."), "IN has feed per revolution from here, OUT a feed to X45 Z-10 F0.1"),
    (MODES_KEPT.replace("G94\n", "").replace("G95\nG1 X45.", "G1 X45."),
     "IN has feed per minute from here, OUT a feed to X40 Z-10 F100"),
], ids=["kept", "g94-lost", "g95-lost", "both-lost"])
def test_verify_sees_a_change_of_feed_mode_in_mid_program(out: str, mismatch: str | None) -> None:
    """F100 per revolution where the source feeds 100 mm/min is a crash; until issue 29's audit verify compared a
    move's F but not its feed mode after the header's, so every one of these verified "ok". Hand-written pairs."""
    report = verify_lines(io.StringIO(MODES_SOURCE), io.StringIO(out), file_in="in.nc", file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=FANUC_T, tolerance=0.0)
    assert report.mismatch == mismatch, report.summary()
    assert report.ok == (mismatch is None)
    if mismatch is None:
        assert code_lines(write(MODES_SOURCE, "fanuc", FANUC_T))[3:8] == ["G1 X40. F0.2", "G94 F0.2",
                                                                           "G1 Z-10. F100.", "G95 F100.", "G1 X45. F0.1"]


# -- writing, by hand ----------------------------------------------------------------------------------
# (a program without units gets the millimetres it was read in, G21: postproc.lowering.units_at_start)

def test_a_clamp_while_css_is_on_is_a_new_g96_with_the_speed_in_force() -> None:
    text = write("G96 S180 M03\nG00 X50. Z2.\nG50 S3000\nG01 X40. F0.2\nG97 S800\nG96 S150\n", "fanuc", FANUC_T)
    assert code_lines(text) == ["G18 G7", "G21", "G95 G96 S180 M3", "G0 X50. Z2.", "G96 S180 D3000",
                                "G1 X40. F0.2", "G97 S800", "G96 D3000 S150", "M2"]


def test_a_clamp_before_css_waits_for_its_g96() -> None:
    text = write("G50 S2000\nG97 S500 M03\nG96 S120\n", "gsk", GSK)
    assert code_lines(text) == ["G18 G7", "G21", "G97 S500 M3", "G96 D2000 S120", "M2"]
    assert "(G50 S2000)" in text  # the block itself wrote nothing: its trace


def test_a_straight_thread_is_g33_with_its_lead_and_f_before_it() -> None:
    text = write("G97 S500 M03\nG00 X30. Z5.\nG32 Z-20. F1.5\nG00 X40.\nG01 Z-25.\n", "fanuc", FANUC_T)
    assert code_lines(text)[4:] == ["F1.5", "G33 Z-20. K1.5", "G0 X40.", "G1 Z-25.", "M2"]  # F stays the lead


def test_a_taper_thread_gets_k_along_its_path() -> None:
    text = write("G97 S500 M03\nG00 X30. Z5.\nG32 X32. Z-15. F2.\n", "fanuc", FANUC_T)
    line = next(line for line in text.splitlines() if line.startswith("G33"))
    k = float(re.search(r"K([0-9.]+)", line).group(1))  # type: ignore[union-attr]
    assert k == pytest.approx(2.0 * math.hypot(1.0, 20.0) / 20.0, abs=1e-6)  # radius 1 over Z 20


def test_a_face_thread_is_refused_at_its_line() -> None:
    with pytest.raises(ErrorList) as caught:
        write("G97 S500 M03\nG00 X30. Z5.\nG32 X60. Z4. F1.\n", "fanuc", FANUC_T)
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:3:1: error: the linuxcnc dialect cannot express a thread whose major axis is X (a face thread: "
        "LinuxCNC's distance per revolution K along such a path in diameter mode is not in our sources)"]


def test_a_radius_program_gets_g8_and_keeps_its_x() -> None:
    radius = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"))
    assert code_lines(write("G99 G00 X30. Z5.\n", "fanuc", radius)) == ["G18 G8", "G21 G95 G0 X30. Z5.", "M2"]


# -- reading LinuxCNC lathe programs -----------------------------------------------------------------

def read(text: str, setup: MachineSetup = LINUXCNC_LATHE) -> list:  # type: ignore[type-arg]
    return read_program(io.StringIO(text), file="in.ngc", dialect="linuxcnc", setup=setup)


def errors(text: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        read(text)
    return [str(e) for e in caught.value.errors]


def test_lathe_words_read_into_sections() -> None:
    blocks = read("G18 G7 G21\nG96 S150 D2200 M3\nG0 X20. Z2.\nG33 X22. Z-2. K1.\nG97 S500\nM2\n")
    css = blocks[1].sections
    assert css["SpindleMode"] == SpindleMode("css") and css["SpindleClamp"] == SpindleClamp(2200.0)
    lead = blocks[3].sections["ThreadLead"]
    assert isinstance(lead, ThreadLead)
    assert lead.lead == pytest.approx(1.0 * 4.0 / math.hypot(1.0, 4.0))  # K along the path, radius 1 over Z 4
    assert blocks[4].sections["SpindleMode"] == SpindleMode("rpm")


def test_lathe_words_refused_as_rs274_refuses_them() -> None:
    assert errors("G7 G8\nM2\n") == [  # (a switch alone is read: tests/test_linuxcnc_x_mode_switch.py)
        'in.ngc:1:4: error: G7 and G8 in one block, one modal group (rs274: "Two g codes used from same modal group"; '
        'grblHAL: error 21)']
    assert errors("G96 D2000 M3\nM2\n") == [
        'in.ngc:1:1: error: G96 needs S, the surface speed (rs274: "S word missing with G96")']
    assert errors("G0 X20. Z2.\nG33 Z-10.\nM2\n") == [
        'in.ngc:2:1: error: G33 needs K, the distance per spindle revolution (rs274: "K word missing with '
        'g33/g33.1")']
    assert errors("G0 X20. Z2.\nG33 Z-10. K1. F0.2\nM2\n") == [
        'in.ngc:2:15: error: F beside G33 (rs274: "F word used with a g33/g33.1"; set the feed rate in a block '
        'before)']
    assert errors("G96 S100 D2000\nG97 S500\nG96 S120\nM2\n") == [
        "in.ngc:3:1: error: G96 without D after one with D: the controller lifts the spindle clamp, which the "
        "Fanuc family's clamp cannot say; write D again"]


def test_g33_on_a_mill_set_up_stays_verbatim() -> None:
    blocks = read("G33 Z-1. K1.\nM2\n", MachineSetup())
    assert isinstance(blocks[0].sections.get("NativeCode"), NativeCode)


def test_a_linuxcnc_lathe_program_round_trips_byte_for_byte() -> None:
    text = "G18 G7 G21 G95\nG96 S150 D2200 M3\nG0 X20. Z2.\nF0.2\nG33 X22. Z-2. K1.\nG1 X30.\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.ngc", source="linuxcnc", target="linuxcnc", setup=LINUXCNC_LATHE)
    assert out.getvalue() == text


# -- LinuxCNC lathe programs towards the Fanuc family ------------------------------------------------

def from_linuxcnc(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.ngc", source="linuxcnc", target=target, setup=LINUXCNC_LATHE)
    return out.getvalue()


@pytest.mark.parametrize("target", ["fanuc", "gsk"])
def test_g96_with_its_clamp_is_g50_s_then_g96(target: str) -> None:
    text = from_linuxcnc("G18 G7 G21 G95\nG96 S150 D2200 M3\nG0 X20. Z2.\nM2\n", target)
    assert text.splitlines()[1:3] == ["G50 S2200", "G96 S150 M03"]  # one block would hold two S words


@pytest.mark.parametrize("target", ["fanuc", "gsk"])
def test_a_g33_thread_is_g32_with_its_lead_and_the_feed_rate_restated(target: str) -> None:
    program = ("G18 G7 G21 G95\nS500 M3\nG0 X20. Z2.\nG1 Z0. F0.2\nG33 Z-10. K1.5\nG0 X24.\nG1 X22. Z-12.\n"
               "G33 X24. Z-16. K2.\nG1 X30.\nM2\n")
    text = from_linuxcnc(program, target)
    # K2. along a path of radius 1 over Z 4 is a lead of 2 * 4 / sqrt(17) = 1.940285 along Z
    assert text.splitlines()[4:9] == ["G32 Z-10. F1.5", "G00 X24.", "G01 X22. Z-12. F0.2",
                                      "G32 X24. Z-16. F1.940285", "G01 X30. F0.2"]
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.ngc", file_out="out.nc",
                          source="linuxcnc", target=target, setup=LINUXCNC_LATHE, tolerance=0.0)
    assert report.ok, report.summary()


def test_linuxccs_threading_with_computed_g33_words_copies_byte_for_byte() -> None:
    """LinuxCNC's own ``nc_files/threading.ngc`` threads with ``g33z[.1 + #7]k#4`` in an o-word loop: its copy to
    LinuxCNC was refused ("a computed word in G33 is not supported"), though the copy is the program itself and
    LinuxCNC evaluates the words as it runs them. Kept as written now (the lead is known where the program runs:
    ``verify``, which runs both, compares the threading moves)."""
    from pathlib import Path

    from postproc.setup.machine_setup import load_setup
    from postproc.simulate.verify import verify_lines

    root = Path(__file__).resolve().parents[1]
    text = (root / "tests" / "heldout" / "linuxcnc" / "threading.ngc").read_text()
    setup = load_setup(str(root / "tests" / "heldout" / "setups" / "linuxcnc_lathe_radius.xml"))
    out = io.StringIO()
    translate(io.StringIO(text), out, file="threading.ngc", source="linuxcnc", target="linuxcnc", setup=setup)
    assert out.getvalue() == text
    report = verify_lines(io.StringIO(text), io.StringIO(text), file_in="in.ngc", file_out="out.ngc",
                          source="linuxcnc", target="linuxcnc", setup=setup, allow_ignored=True)
    assert report.ok and report.max_deviation == 0.0 and report.moves > 20, report.summary()


def test_computed_g33_words_to_another_dialect_are_refused_as_a_translation_limit() -> None:
    """The same ``threading.ngc`` to Fanuc: the computed ``G33`` words cannot be carried, so the translation is
    refused, located, as a limit of the translation (``UnsupportedError``), not as a fault of the program: LinuxCNC
    runs the source (the copy above; the held-back corpus counted a ``ProgramError`` here as a translation that
    calls a valid source invalid)."""
    from postproc.errors import UnsupportedError

    root = Path(__file__).resolve().parents[1]
    text = (root / "tests" / "heldout" / "linuxcnc" / "threading.ngc").read_text()
    setup = load_setup(str(root / "tests" / "heldout" / "setups" / "linuxcnc_lathe_radius.xml"))
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(text), io.StringIO(), file="threading.ngc", source="linuxcnc", target="fanuc",
                  setup=setup)
    errors = caught.value.errors
    assert errors and all(isinstance(e, UnsupportedError) for e in errors), [type(e) for e in errors]
    assert ("threading.ngc:36:1: error: a computed word in G33 is not supported (write the numbers)"
            in [str(e) for e in errors]), [str(e) for e in errors]
