"""Lowering of hole cycles: keep native where the target runs the cycle, else write the exact expansion
(expand_canned_cycles), plus the writer's native cycle words and the oriented-stop policies."""

from __future__ import annotations

import io
from pathlib import Path
from typing import ClassVar

import pytest

from dialects.fanuc import Fanuc
from dialects.fanuc.writer import FanucWriter
from postproc.api import read_blocks, translate
from postproc.cycles.lowering import expand_canned_cycles
from postproc.dialect import Dialect
from postproc.errors import Diagnostics, ErrorLevel
from postproc.lowering.lower import TRANSFORMS, lower_for
from postproc.plugins import default_registry
from postproc.rs274.codes import CodeTable
from postproc.setup.machine_setup import CycleSettings, MachineSetup

GOLDEN = Path(__file__).resolve().parent / "golden" / "fanuc" / "cycles"
HEAD = "G21 G17 G90 G54\nS1000 M03\nG00 X0. Y0. Z50.\n"


class OtherWriter(FanucWriter):
    DIALECT: ClassVar[str] = "other"


class Other(Dialect):
    """A Fanuc-like target of another name (blocks are generated, not copied) without G73-G76/G85-G89."""

    NAME = "other"
    WRITER = OtherWriter
    NATIVE_CYCLES = frozenset({"drill", "drill_dwell", "peck_deep"})
    CYCLE_SEMANTICS = "fanuc"
    SPINDLE_ORIENTATION = False


class Ngc(Other):
    NATIVE_CYCLES = Fanuc.NATIVE_CYCLES
    CYCLE_SEMANTICS = "rs274"


def write(text: str, target: type[Dialect], on_unsupported: str = "error", **cycles: object) -> tuple[str, Diagnostics]:
    default_registry()
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    setup = MachineSetup(cycles=CycleSettings(**cycles))  # type: ignore[arg-type]
    ctx, blocks = read_blocks(text.splitlines(keepends=True), "t.nc", Fanuc, setup, diagnostics)
    out = io.StringIO()
    assert target.WRITER is not None
    target.WRITER(ctx, "fanuc").write(lower_for(blocks, ctx, target, on_unsupported), out)
    return out.getvalue(), diagnostics


def test_the_transform_is_registered() -> None:
    default_registry()
    assert expand_canned_cycles in TRANSFORMS


@pytest.mark.parametrize("path", sorted(GOLDEN.glob("*.nc")), ids=lambda p: p.stem)
def test_fanuc_to_fanuc_keeps_native_cycles_byte_for_byte(path: Path) -> None:
    out = io.StringIO()
    translate(path.read_text().splitlines(keepends=True), out, file=str(path), source="fanuc", target="fanuc")
    assert out.getvalue() == path.read_text()


def test_fanuc_to_fanuc_with_expand_all_writes_the_motion_and_names_the_source() -> None:
    text = HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nX20.\nG80\nM30\n"
    out = io.StringIO()
    translate(text.splitlines(keepends=True), out, file="t.nc", source="fanuc", target="fanuc",
              setup=MachineSetup(cycles=CycleSettings(expand="all")))
    assert out.getvalue() == HEAD + (
        "G99 F200.\n"
        "(drill from line 4: G99 G81 X10. Y10. Z-5. R2. F200.)\n"
        "G00 X10. Y10. Z50.\n"
        "G00 Z2.\n"
        "G01 Z-5.\n"
        "G00 Z2.\n"
        "(drill from line 5: X20.)\n"
        "G00 X20. Y10. Z2.\n"  # a hole's first move names every axis, the next ones what they change
        "G01 Z-5.\n"
        "G00 Z2.\n"
        "G80\nM30\n")


def test_expand_names_kinds() -> None:
    text = HEAD + "G98 G81 X10. Y10. Z-5. R2. F200.\nG80\nG98 G83 X20. Y10. Z-5. R2. Q2. F100.\nG80\n"
    out, _ = write(text, Fanuc, expand="peck_deep")
    assert "G98 G81 X10. Y10. Z-5. R2. F200.\n" in out
    assert "(peck_deep from line 6: G98 G83 X20. Y10. Z-5. R2. Q2. F100.)\n" in out
    assert not [line for line in out.splitlines() if line.startswith("G83") or " G83" in line.split("(")[0]]


def test_native_cycles_are_generated_in_the_targets_words() -> None:
    text = HEAD + "G99 G82 X10. Y10. Z-5. R2. P500 F200.\nX20. K2\nG91 X5.\nG90 G80\n"
    out, diagnostics = write(text, Other)
    assert not diagnostics.errors
    assert out.splitlines()[3:] == ["G99 G82 X10. Y10. Z-5. R2. P500 F200.", "X20. K2", "G91 X5.", "G90 G80"]


def test_a_cycle_the_target_lacks_is_expanded() -> None:
    out, _ = write(HEAD + "G98 G85 X10. Y10. Z-5. R2. F200.\nG80\n", Other)
    assert out.splitlines()[3:] == [
        "G98 F200.", "(bore_feed from line 4: G98 G85 X10. Y10. Z-5. R2. F200.)", "G00 X10. Y10. Z50.",
        "G00 Z2.", "G01 Z-5.", "G01 Z2.", "G00 Z50.", "G80"]  # after the first, a move names what it changes


def test_expansion_restores_the_motion_mode_of_the_program() -> None:
    """After G80 a bare X30. is a rapid again; the expansion ended with a feed, so it says G00."""
    out, _ = write(HEAD + "G99 G85 X10. Y10. Z-5. R2. F200.\nG80\nX30.\n", Fanuc, expand="all")
    assert out.splitlines()[-5:] == ["G01 Z-5.", "G01 Z2.", "G00", "G80", "X30."]


def test_once_expanded_the_rest_of_the_cycle_is_expanded() -> None:
    """G85 cancels nothing on the source, but its expansion's G00/G01 cancel the target's cycle."""
    text = HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nG85 X20.\nG81 X30.\nX40.\nG80\nG81 X50. Z-5. R2.\n"
    out, _ = write(text, Other)
    lines = out.splitlines()
    assert lines[3] == "G99 G81 X10. Y10. Z-5. R2. F200."
    assert "(drill from line 6: G81 X30.)" in lines and "(drill from line 7: X40.)" in lines
    assert lines[-1] == "G81 X50. Z-5. R2."


def test_targets_moving_by_other_rules_get_the_expansion() -> None:
    out, _ = write(HEAD + "G98 G81 X10. Y10. Z-5. R2. F200.\nG80\n", Ngc)
    assert "(drill from line 4: G98 G81 X10. Y10. Z-5. R2. F200.)" in out


G76 = HEAD + "G98 G76 X10. Y10. Z-15. R2. Q0.5 F80.\nG80\n"


def test_oriented_stop_refused_by_default() -> None:
    out, diagnostics = write(G76, Other)
    assert [str(e) for e in diagnostics.errors] == [
        "t.nc:4:1: error: G76 needs an oriented spindle stop, which the other dialect cannot make "
        "(set <Cycles orientation=\"stop\"/> or \"m19\")"]
    assert "G76" not in out


def test_oriented_stop_as_a_program_stop() -> None:
    out, diagnostics = write(G76, Other, orientation="stop")
    assert not diagnostics.errors
    assert "(orient the spindle to 0 deg by hand, then cycle start)\nM00\nG00 X10.5 Y10. Z-15.\n" in out


def test_oriented_stop_as_m19() -> None:
    out, _ = write(G76, Other, orientation="m19")
    assert "M19\nG00 X10.5 Y10. Z-15.\n" in out


def test_oriented_stop_in_warn_mode_comments_the_block_out() -> None:
    out, diagnostics = write(G76, Other, on_unsupported="warn")
    assert not diagnostics.errors and len(diagnostics.warnings) == 1
    assert "(UNSUPPORTED LINE 4: G98 G76 X10. Y10. Z-15. R2. Q0.5 F80.)\n" in out


def test_a_native_cycle_the_writer_cannot_spell_is_unsupported() -> None:
    class Bare(OtherWriter):
        CODES: ClassVar[CodeTable] = CodeTable(row for row in FanucWriter.CODES.rows if row[2] != "cycle")

    class Claims(Other):
        WRITER = Bare

    _, diagnostics = write(HEAD + "G98 G81 X10. Y10. Z-5. R2. F200.\n", Claims)
    assert [e.message for e in diagnostics.errors] == ["the other dialect cannot express the drill cycle"]
