"""Frames across a program's constructs: set before a loop the translation's dry run judges, set in a subprogram
and in force after its return, set before a call and cancelled after it, and a subprogram defined before a frame
command (``postproc.frames.run_order``; the frame the run has reached is ``Context.frame_run``, which the dry run
starts from a copy of, ``postproc.api``).

Each case is translated, its moves checked against points derived by hand, and the translation verified against
the source (``verify``, no tolerance: both toolpaths simulated independently of the frame evaluation's text order).
A program kept symbolically is evaluated in the order of its text; where that is not the order of the run (a
frame command after a call or after a subprogram's text), the translation flattens the program instead.
"""

from __future__ import annotations

import io
import re
from pathlib import Path
from typing import Any

from postproc.api import translate
from postproc.simulate.verify import verify_lines


def _translated(text: str, source: str, target: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = translate(io.StringIO(text), out, file="t.nc", source=source, target=target)
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="t.nc", file_out="o.nc",
                          source=source, target=target, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out.getvalue()
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def _xy(text: str) -> list[tuple[float, float]]:
    """The X and Y of every move written with both."""
    return [(float(x), float(y)) for x, y in re.findall(r"^G0?[01] X(-?[\d.]+) Y(-?[\d.]+)", text, re.M)]


def _flattened(warnings: list[str]) -> bool:
    return any("flattened" in w and "a coordinate frame in a program kept symbolically" in w for w in warnings)


ROTATED_LOOP = """G21 G17 G90 G94
G00 X0. Y0. Z5.
G68 X0. Y0. R30.
G00 X0. Y0.
#1=0
WHILE [#1 LT 3] DO1
G01 X[#1*10.] F100.
#1=#1+1
END1
G69
M30
"""


def test_the_dry_run_starts_from_the_frame_set_before_the_loop() -> None:
    """Kept symbolically, the loop's move gives X only, which the rotation (set before the first construct) mixes
    into Y: the dry run, started from the frame the run has reached, finds it and the program is flattened. A dry
    run started without that frame would keep the program, and its real run would then refuse the move."""
    out, warnings = _translated(ROTATED_LOOP, "fanuc", "linuxcnc")
    assert _flattened(warnings) and "while" not in out
    # by hand: (0,0), (10,0) and (20,0) turned 30 degrees about the origin
    assert _xy(out) == [(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (8.660254, 5.0), (17.320508, 10.0)]


FRAME_IN_SUBPROGRAM = """%
O1000
G21 G17 G90 G94
G00 X0. Y0. Z5.
M98 P2000
G01 X10. Y0. F100.
G01 X10. Y10.
G69
G50
G52 X0. Y0.
G00 X0. Y0.
M30
O2000
G52 X100. Y0.
G51 X0. Y0. P2000
G68 X0. Y0. R90.
G00 X0. Y0.
M99
%
"""


def test_a_frame_set_in_a_subprogram_moves_the_blocks_after_its_return() -> None:
    """G52, G51 and G68 set in a subprogram stay in force after its M99: the main program's moves after the call
    carry them. Evaluated in the text's order, those moves came before the subprogram's text (and went out
    unshifted, ``verify`` 92 mm off): the program is flattened."""
    out, warnings = _translated(FRAME_IN_SUBPROGRAM, "fanuc", "linuxcnc")
    assert _flattened(warnings) and "\nM98" not in out
    # by hand: scaled x2 about the local zero, turned 90 degrees about it, shifted by G52 X100:
    # (0,0) -> (100,0); (10,0) -> (20,0) -> (0,20) -> (100,20); (10,10) -> (20,20) -> (-20,20) -> (80,20)
    assert _xy(out) == [(0.0, 0.0), (100.0, 0.0), (100.0, 20.0), (80.0, 20.0), (0.0, 0.0)]


CALL_UNDER_A_FRAME = """%
O1000
G21 G17 G90 G94
G00 X0. Y0. Z5.
G52 X100.
M98 P2000
G52 X0.
G00 X0. Y0.
M30
O2000
G00 X5. Y5.
M99
%
"""


def test_a_subprogram_called_under_a_frame_cancelled_after_the_call() -> None:
    """The subprogram runs under the G52 in force at its call, which the main program cancels after it: in the
    text's order its move would come after the cancel. Flattened, its move carries the offset."""
    out, warnings = _translated(CALL_UNDER_A_FRAME, "fanuc", "linuxcnc")
    assert _flattened(warnings) and "\nM98" not in out
    assert _xy(out) == [(0.0, 0.0), (105.0, 5.0), (0.0, 0.0)]


def test_a_subprogram_called_under_a_frame_that_stays_is_flattened() -> None:
    """With no frame command after the call, the subprogram's text still runs under the frame of its call, which is
    evaluated into the coordinates: a call under it is flattened (the called text may be a library's, below), the
    subprogram's move carried."""
    text = CALL_UNDER_A_FRAME.replace("G52 X0.\n", "")
    out, warnings = _translated(text, "fanuc", "linuxcnc")
    assert _flattened(warnings) and "\nM98" not in out
    assert _xy(out) == [(0.0, 0.0), (105.0, 5.0), (100.0, 0.0)]  # (the run's order: the call, then X0 Y0)


def test_a_call_under_a_frame_to_a_library_subprogram_is_flattened(cli: Any, tmp_path: Path) -> None:
    """A library's subprogram (``--lib``) kept as ``M98 P2000`` would run on the target without the G52 evaluated
    into the caller's moves (its move to X5 Y5 instead of X105 Y5: exit 0 on main before this rule): flattened, its
    move carries the offset."""
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "O2000.nc").write_text("O2000\nG01 X5. Y5. F100.\nM99\n")
    main = "O1000\nG21 G17 G90 G94\nG00 X0. Y0. Z5.\n#1=1\nG52 X100. Y0.\nM98 P2000\nG00 X0. Y0.\nM30\n"
    (tmp_path / "main.nc").write_text(main)
    result = cli("translate", "--from", "fanuc", "--to", "linuxcnc", "--lib", lib, tmp_path / "main.nc")
    assert result.status == 0, result.err
    out = result.out.decode()
    assert "flattened" in result.err and "\nM98" not in out
    # by hand: the start, the main program's (0,0) under G52 X100 is (100,0) after the call's (105,5)
    assert _xy(out) == [(0.0, 0.0), (105.0, 5.0), (100.0, 0.0)]


def test_a_subprogram_defined_before_a_frame_command_and_called_after_it() -> None:
    """A LinuxCNC ``o100 sub`` defined before a G52 and called after it runs under the G52: in the text's order its
    move came before the frame command (and went out unshifted to Fanuc, ``verify`` 100 mm off): flattened."""
    text = "G21 G17 G90\nG0 X0 Y0 Z5\no100 sub\nG0 X5 Y5\no100 endsub\nG52 X100\no100 call\nG0 X0 Y0\nM2\n"
    out, warnings = _translated(text, "linuxcnc", "fanuc")
    assert _flattened(warnings) and "\nG65" not in out
    assert _xy(out) == [(0.0, 0.0), (105.0, 5.0), (100.0, 0.0)]
