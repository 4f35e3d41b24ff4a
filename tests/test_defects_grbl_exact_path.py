"""grbl's power-on path mode is the exact path (G61) (issue 26/29, defects).

It is the exact path, not the exact stop: grbl refuses G61.1 ("[G61.1 not supported]", ``gcode.c``), and LinuxCNC's
manual names the two apart ("G61 Exact Path mode", "G61.1 Exact Stop mode", ``g-code.adoc``) [V]. The two reach
the same programmed points; the exact stop also stops the machine at each block end. So the IR has the mode
``exact_path`` (``PathControl``), LinuxCNC writes it G61, Fanuc (no exact path code) its exact stop G61 [K], and
``verify`` compares the two as one, with a note. A Fanuc or GSK lathe, whose table has no path code [?], does not
get it: the program asked for nothing (it is grbl's only mode), so the translation is written with a warning, not
refused, and ``verify`` lists the difference.

grbl runs one path control mode, the exact path, and it is the mode in force at power-on [V: grbl 1.1 ``gcode.h``
``CONTROL_MODE_EXACT_PATH // G61 (Default: Must be zero)``; grblHAL core ``gcode.h`` ``ControlMode_ExactPath``
"G61 - Default"]. The dialects said so only for verify's sake (``PATH_CONTROL``) and took a grbl program as
starting in the cutting mode: towards a controller that powers on blending (Fanuc, LinuxCNC: G64 [K]) nothing was
written, and the target blended the corners grbl reaches. Now ``PATH_CONTROL_AT_START`` says G61, so the exact stop
is written before the first move (``postproc.lowering.path_at_start``), and the simulation records it there.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.plugins import default_registry
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.pair_checks import PairChecks

SQUARE = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG0 Z5\nM30\n"


@pytest.mark.parametrize(("source", "target", "first"), [
    ("grbl", "fanuc", "G61 G00 X0. Y0. Z5."), ("grbl", "linuxcnc", "G61 G0 X0. Y0. Z5."),
    ("grblhal", "fanuc", "G61 G00 X0. Y0. Z5."), ("grblhal", "linuxcnc", "G61 G0 X0. Y0. Z5."),
])
def test_a_grbl_program_keeps_its_exact_path_on_a_blending_controller(source: str, target: str, first: str) -> None:
    check = PairChecks(MachineSetup())
    out = check.translate(SQUARE, source, target)
    assert out.splitlines()[1] == first, out
    check.verify(SQUARE, out, source, target)


@pytest.mark.parametrize("name", ["grbl", "grblhal"])
def test_the_dialect_says_g61_at_power_on(name: str) -> None:
    dialect = default_registry().dialect(name)
    assert dialect.PATH_CONTROL_AT_START == "exact_path" == dialect.PATH_CONTROL


@pytest.mark.parametrize("name", ["grbl", "grblhal"])
def test_grbls_g61_reads_as_the_exact_path(name: str) -> None:
    dialect = default_registry().dialect(name)
    writer = dialect.writer_class(dialect.context("t.nc", MachineSetup(), Diagnostics(warn_stream=io.StringIO())))
    assert writer is not None
    assert writer.CODES.g["61"] == ("15", "path", "exact_path")  # type: ignore[attr-defined]


def test_the_verify_report_says_the_exact_path_was_compared_as_the_exact_stop() -> None:
    out = PairChecks(MachineSetup()).translate(SQUARE, "grbl", "fanuc")
    report = verify_lines(io.StringIO(SQUARE), io.StringIO(out), file_in="a.nc", file_out="b.nc", source="grbl",
                          target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()
    assert any("exact path (line 2) compared as the exact stop" in note for note in report.ignored), report.ignored
    # the Fanuc output without its G61 blends from power-on: the difference is listed and fails the comparison
    bare = out.replace("G61 ", "")
    report = verify_lines(io.StringIO(SQUARE), io.StringIO(bare), file_in="a.nc", file_out="b.nc", source="grbl",
                          target="fanuc", tolerance=0.0)
    assert not report.ok and any(note.startswith("path control differs") for note in report.ignored), report.ignored


def test_a_fanuc_exact_stop_reaches_grbl_as_its_g61() -> None:
    """Fanuc's G61 (exact stop) on grbl: grbl's one mode, G61, the same points (grbl has no G61.1 [V: gcode.c])."""
    program = "G21 G90 G17\nG61 G0 X0 Y0 Z5\nG1 X10 F100\nG64 G1 Y10\nM30\n"
    out = PairChecks(MachineSetup()).translate(program, "fanuc", "grbl")
    assert out.splitlines()[1].startswith("G61 G0"), out
    assert "G64" not in out and "G61.1" not in out, out
    PairChecks(MachineSetup()).verify(program, out, "fanuc", "grbl")


LATHE = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"))


@pytest.mark.parametrize("target", ["fanuc", "gsk"])
def test_towards_a_lathe_without_path_codes_the_power_on_mode_is_a_warning(target: str) -> None:
    """grblHAL lathe -> Fanuc/GSK T: written (was refused: "cannot express path control exact_stop"), with a
    warning at the first move; verify lists the source's exact path against the target's mode, never set."""
    program = "G18 G7 G21\nG0 X20. Z2.\nG1 Z-10. F100.\nX30.\nM2\n"
    warnings = io.StringIO()
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="grblhal", target=target, setup=LATHE,
              diagnostics=Diagnostics(warn_stream=warnings))
    assert "G61" not in out.getvalue(), out.getvalue()
    assert warnings.getvalue().startswith(f"in.nc:2:1: warning: the grblhal controller runs this program in the "
                                          f"exact path mode from power-on; a {target} lathe has no path control"), \
        warnings.getvalue()
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source="grblhal", target=target, setup=LATHE, tolerance=0.0, allow_ignored=True)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    assert "path control differs: IN exact path (line 2); OUT never set" in report.ignored, report.ignored


def test_a_program_that_sets_g64_first_gets_no_warning_on_a_fanuc_lathe() -> None:
    warnings = io.StringIO()
    translate(io.StringIO("G18 G21\nG1 X20. Z2. F100.\nM2\n"), io.StringIO(), file="in.nc", source="grblhal",
              target="fanuc", setup=LATHE, diagnostics=Diagnostics(warn_stream=warnings))
    assert "power-on" in warnings.getvalue()
    warnings = io.StringIO()
    translate(io.StringIO("G18 G21\nG61\nG1 X20. Z2. F100.\nM2\n"), io.StringIO(), file="in.nc",
              source="grblhal", target="fanuc", setup=LATHE, diagnostics=Diagnostics(warn_stream=warnings),
              on_unsupported="warn")
    assert "power-on" not in warnings.getvalue()  # (the program's own G61: refused by name, as before)


@pytest.mark.parametrize("name", ["fanuc", "gsk", "linuxcnc", "grbl", "grblhal", "mach3"])
def test_lathe_path_control_says_what_the_lathe_table_has(name: str) -> None:
    """``Dialect.LATHE_PATH_CONTROL`` held to the code table a lathe program is written with."""
    dialect = default_registry().dialect(name)
    if "lathe" not in dialect.MACHINE_TYPES:
        return
    ctx = dialect.context("t.nc", LATHE, Diagnostics(warn_stream=io.StringIO()))
    writer = dialect.writer_class(ctx)
    assert writer is not None
    codes = writer(ctx, name, dialect).codes  # type: ignore[call-arg, attr-defined]  # (the lathe table on a lathe)
    assert dialect.LATHE_PATH_CONTROL == any(codes.spell("path", mode) is not None
                                             for mode in ("exact_stop", "exact_path")), name


def test_a_grbl_copy_writes_no_g61() -> None:
    out = io.StringIO()
    translate(io.StringIO(SQUARE), out, file="in.nc", source="grbl", target="grbl",
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert out.getvalue() == SQUARE
