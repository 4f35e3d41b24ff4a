"""A Fanuc or GSK lathe program whose G71-G73 profile computes (``X[#1]``) copied to its own dialect: the cycle is
kept as written, byte for byte (DESIGN.md), with a G70 on the same profile; ``verify`` runs the copy and the source
and finds the same moves. A translation to another dialect still needs the moves: flattened (its evaluated motion
written) or refused, located. Before: "G71: a computed word in the profile cannot be expanded" refused the copy."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup
from postproc.simulate.verify import verify_lines

LATHE = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"))

SAME_PROGRAM = ("O1000\nG21 G18 G40 G99\nT0101\nG97 S500 M03\n#1=40.\nG00 X62. Z2.\n{rough}"
                "N10 G00 X[#1]\nG01 Z-20. F[#2]\nX60.\nN20 Z-40.\nG70 P10 Q20\nG00 X100. Z100.\nM30\n")
"""A computed profile in the program itself, finished by G70 on the same N10..N20 (#2: the feed, set below)."""

SUBPROGRAM = ("O1000\nG21 G18 G40 G99\nT0101\nG97 S500 M03\n#1=40.\n#2=0.15\nG00 X62. Z2.\nM98 P2000\n"
              "G00 X100. Z100.\nM30\nO2000\n{rough}N10 G00 X[#1]\nG01 Z-20. F[#2]\nX60.\nN20 Z-40.\nG70 P10 Q20\n"
              "M99\n")
"""The cycle and its computed profile in an M98 subprogram."""

ROUGHING = {"G71": "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\n",
            "G73": "G73 U3. W0. R3\nG73 P10 Q20 U0.4 W0.1 F0.2\n"}


def _program(frame: str, rough: str) -> str:
    text = frame.format(rough=ROUGHING[rough])
    return text if "#2=" in text else text.replace("#1=40.\n", "#1=40.\n#2=0.15\n")


def _translate(text: str, source: str, target: str) -> tuple[str, str]:
    out, warned = io.StringIO(), io.StringIO()
    translate(text.splitlines(keepends=True), out, file="in.nc", source=source, target=target, setup=LATHE,
              diagnostics=Diagnostics(warn_stream=warned))
    return out.getvalue(), warned.getvalue()


def _deviation(source: str, out: str, src: str, dst: str) -> float:
    report = verify_lines(source.splitlines(keepends=True), out.splitlines(keepends=True), file_in="in.nc",
                          file_out="out.nc", source=src, target=dst, setup=LATHE)
    assert report.ok, report.summary()
    return report.max_deviation


@pytest.mark.parametrize("dialect", ["fanuc", "gsk"])
@pytest.mark.parametrize("frame", [SAME_PROGRAM, SUBPROGRAM], ids=["same", "subprogram"])
@pytest.mark.parametrize("rough", ["G71", "G73"])
def test_a_computed_profile_is_copied_as_written(dialect: str, frame: str, rough: str) -> None:
    program = _program(frame, rough)
    written, warned = _translate(program, dialect, dialect)
    assert written == program
    assert warned == ""
    if dialect == "fanuc":
        assert _deviation(program, written, dialect, dialect) == 0.0
        return
    # GSK's macros are kept verbatim, not run (dialects/gsk): no simulation knows #1, so verify refuses the source
    # and the copy alike, at the same located line (the cycle's moves are known only on the machine)
    with pytest.raises(ErrorList) as caught:
        _deviation(program, written, dialect, dialect)
    line = program.splitlines().index("N10 G00 X[#1]") + 1  # (located at the profile block that computes)
    found = str(caught.value)
    for name in ("in.nc", "out.nc"):
        assert f"{name}:{line}:1: error: {rough}: a computed word in the profile cannot be expanded" in found


@pytest.mark.parametrize("frame", [SAME_PROGRAM, SUBPROGRAM], ids=["same", "subprogram"])
def test_a_computed_profile_is_flattened_for_another_dialect(frame: str) -> None:
    """LinuxCNC runs the program's variables but not a Fanuc G71: the program is flattened, its moves exact."""
    program = _program(frame, "G71")
    written, warned = _translate(program, "fanuc", "linuxcnc")
    assert "X[#1]" not in written and "#1" not in written
    assert "warning: the program is flattened" in warned
    assert _deviation(program, written, "fanuc", "linuxcnc") < 1e-9


def test_a_computed_profile_is_refused_where_nothing_is_flattened() -> None:
    """grbl has no variables: the program is evaluated and expanded; a profile that computes from a variable
    never set is refused, located at the profile block (before: the same refusal; it must not turn into a copy)."""
    program = _program(SAME_PROGRAM, "G71").replace("#1=40.\n", "")
    with pytest.raises(ErrorList) as caught:
        _translate(program, "fanuc", "grbl")
    assert str(caught.value).startswith("in.nc:")


def test_a_copy_with_units_still_needs_the_moves() -> None:
    """A copy that changes the program (``--units``) is no copy as written: a kept lathe cycle's parameters are not
    converted, so it is refused, located at the cycle (as before this change), never kept as written."""
    program = _program(SAME_PROGRAM, "G71")
    with pytest.raises(ErrorList) as caught:
        translate(program.splitlines(keepends=True), io.StringIO(), file="in.nc", source="fanuc", target="fanuc",
                  setup=LATHE, units="inch", diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert "in.nc:9:1: error: a lathe cycle kept for the target (turn rough) cannot be converted" in str(caught.value)
