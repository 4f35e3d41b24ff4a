"""Words whose value is a variable or an expression (issue #31 items 6-8): every section that takes a
number from a word holds the expression too, in both builds; each target keeps it symbolically where it
can spell it, else the program is flattened and the value evaluated, else a located error.

The compiled build checks a section's field types at run time (docs/compiled.md): ``H#1`` in a
``ToolLengthOffset.register`` typed ``int`` was a ``TypeError`` there ("int or None object expected;
got postproc.ir.expr.Var") for every target. ``tests/support/section_types.py`` makes the pure build see it.
"""

from __future__ import annotations

import copy
import io

import pytest

from postproc.api import read_program, translate
from postproc.rs274.cycle_semantics import FANUC, RS274
from postproc.errors import Diagnostics, ErrorList
from postproc.ir import Block
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools
from tests.support.fuzzing import WRITERS
from tests.support.output_rules import problems
from tests.support.rs274 import available, canonical_moves, motions, run_rs274
from tests.support.section_types import mistyped
from postproc.setup.machine_setup import MachineSetup


def _translate(program: str, source: str, target: str) -> tuple[str, list[str]]:
    """The output and the warnings; raises ErrorList as translate does."""
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue().splitlines()


def _verified(program: str, source: str, target: str) -> str:
    """Translate, check the target accepts the output, and verify it against the source at zero tolerance."""
    text, _ = _translate(program, source, target)
    assert problems(target, text, MachineSetup()) == []
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                          source=source, target=target, setup=with_tools(), tolerance=0.0)
    assert report.ok, report.summary()
    return text


def _sections(program: str, dialect: str) -> list[Block]:
    return read_program(io.StringIO(program), file="p.nc", dialect=dialect)


# -- item 6: offset registers, and every other word a variable may give ------------------------------

REGISTERS = {
    "fanuc": "G21 G90 G0 X0 Y0 Z10.\n#1=2\n#517=1\nG0 G43 H#1 Z1.\nG41 D#517 G1 X1. Y1. F100.\nG40 G1 X2.\nM30\n",
    "linuxcnc": "G21 G90 G0 X0 Y0 Z10\n#1=2\n#<r>=1\nG0 G43 H#1 Z1\nG41 D#<r> G1 X1 Y1 F100\nG40 G1 X2\nM2\n",
    "isg": "G71 G90 G00 X0 Y0 Z10\nP17=1\nG41 D[P17] G01 X1 Y1 F100\nG40 G01 X2\nM30\n",
}


@pytest.mark.parametrize("dialect", sorted(REGISTERS))
def test_a_computed_register_is_a_section_value_the_compiled_build_accepts(dialect: str) -> None:
    blocks = _sections(REGISTERS[dialect], dialect)
    kept = [b.sections[k] for b in blocks for k in ("ToolLengthOffset", "CutterCompensation") if k in b.sections]
    assert kept and all(not isinstance(getattr(s, "register"), int) for s in kept if s.mode not in ("off", "cancel"))
    assert [m for b in blocks for m in mistyped(b)] == []


@pytest.mark.parametrize("target", WRITERS)
@pytest.mark.parametrize("source", ["fanuc", "linuxcnc"])
def test_a_computed_register_translates_everywhere_or_is_refused_where_it_is(source: str, target: str) -> None:
    """The issue's 'G0 G43 H#1 Z1.' and 'G41 D#517' towards every writer: written (kept or evaluated) and
    verified, or refused by located errors (grbl has no tool table, gsk is a lathe...)."""
    try:
        _verified(REGISTERS[source], source, target)
    except ErrorList as errs:
        assert all(e.location is not None and e.location.line >= 1 for e in errs.errors), errs


@pytest.mark.parametrize("source, target", [("fanuc", "linuxcnc"), ("linuxcnc", "fanuc")])
def test_a_register_is_kept_symbolically_by_a_target_with_variables(source: str, target: str) -> None:
    """Fanuc and LinuxCNC spell '#1' and '#2' alike: the registers stay the variables (the same offsets as
    the source's, whatever the variables hold when the program runs)."""
    program = "G21 G90 G0 X0 Y0 Z10.\n#1=2\n#2=1\nG0 G43 H#1 Z1.\nG41 D#2 G1 X1. F100.\nG40 G1 X2.\nM30\n"
    text = _verified(program, source, target)
    assert "H#1" in text and "D#2" in text


def test_a_computed_orientation_angle_is_kept_by_linuxcnc_and_checked_when_evaluated_for_fanuc() -> None:
    """LinuxCNC's M19 R<angle> [V: rs274]; Fanuc's M19 orients to the set-up's angle (0 here): a computed
    angle is known only when it runs, so the program is flattened and the evaluated angle checked."""
    program = "G21 G90\n#1=0\nM19 R#1\nM2\n"
    assert "M19 R#1" in _verified(program, "linuxcnc", "linuxcnc")
    text, warnings = _translate(program, "linuxcnc", "fanuc")
    assert "M19" in text and "#1" not in text and any("flattened" in w for w in warnings)
    with pytest.raises(ErrorList) as refused:
        _translate(program.replace("#1=0", "#1=90"), "linuxcnc", "fanuc")
    assert str(refused.value).startswith("p.nc:3:1: error:") and "90 deg" in str(refused.value)
    assert [m for b in _sections(program, "linuxcnc") for m in mistyped(b)] == []


# -- item 7: G10 with an expression -------------------------------------------------------------------

G10 = "G21 G90 G0 X0 Y0 Z0\nG90 G10 L2 P1 X[1+1] Y0 Z0\nG0 X0\nM30\n"


def test_g10_with_an_expression_is_written_for_linuxcnc_and_moves_as_rs274_runs_it() -> None:
    """G10 L2 P1 X2 makes G54's X offset 2 mm: 'G0 X0' goes to X2 in machine coordinates (by hand; rs274
    sets the offset to 2 and moves to program X0 in it)."""
    text = _verified(G10, "fanuc", "linuxcnc")
    assert "G10 L2 P1 X[" in text
    source = [e for e in toolpath_events(io.StringIO(G10), file="p.nc", dialect="fanuc") if "move" in e]
    assert source[-1]["x"] == pytest.approx(2.0)
    if available():
        calls = run_rs274(text)
        assert any(c.endswith("SET_G5X_OFFSET(1, 2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)") for c in calls)
        assert motions(canonical_moves(calls))[-1]["x"] == pytest.approx(0.0)


def test_g10_with_an_expression_has_an_ir_form() -> None:
    block = _sections(G10, "fanuc")[1]
    setting = block.sections["DataSetting"]
    back = type(setting).from_xml(setting.make_xml_source())
    assert back == setting and not isinstance(back.values["X"], float)  # type: ignore[attr-defined]


def test_g10_with_a_computed_entry_is_kept_verbatim_and_evaluated_elsewhere() -> None:
    """Which work system 'G10 L2 P#1' sets is known when it runs: Fanuc keeps it as written, LinuxCNC
    gets the evaluated program (G10 L2 P2 X1.)."""
    program = "G21 G90 G0 X0 Y0 Z0\n#1=2\nG10 L2 P#1 X1. Y0 Z0\nG55 G0 X0\nM30\n"
    assert _translate(program, "fanuc", "fanuc")[0] == program
    text = _verified(program, "fanuc", "linuxcnc")
    assert "G10 L2 P2 X1." in text


# -- item 8: a modal cycle with a hole, then a loop ---------------------------------------------------

CYCLE_THEN_LOOP = ("G21 G90 G0 X0 Y0 Z10.\nG81 X1. Y1. Z-1. R1. F100.\nX2.\n#501=0\nWHILE[#501LT3]DO1\n"
                   "#501=#501+1\nEND1\nG80\nM30\n")


@pytest.mark.parametrize("target", ["linuxcnc", "isg", "fanuc"])
def test_a_modal_cycle_with_a_hole_then_a_loop_translates(target: str) -> None:
    """Deciding whether the loop can be kept copies the modal state, whose next-hole memo holds the
    cycle's resolve step and its rules: copying those rules failed in the compiled build
    (FrozenInstanceError: cannot assign to field 'name')."""
    _verified(CYCLE_THEN_LOOP, "fanuc", target)


def test_cycle_rules_are_shared_by_copies() -> None:
    """A family's rules are constants: a copy is the same object, never rebuilt field by field."""
    assert copy.deepcopy(RS274) is RS274 and copy.copy(FANUC) is FANUC


# -- lathes: G50 and the turret's T ---------------------------------------------------------------------

def _lathe() -> MachineSetup:
    from postproc.setup.machine_setup import load_setup
    return load_setup("examples/setups/fanuc_0i_tf.xml")


def test_a_computed_coordinate_setting_and_clamp_are_kept_and_have_an_ir_form() -> None:
    """'G50 X#1' was float(Var): a TypeError in both builds. Fanuc keeps it as written; the section holds
    the expression and serialises it."""
    program = "#1=100.\nG50 X#1 Z[#1/2]\nG50 S#1\nG0 X10. Z2.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="fanuc", setup=_lathe())
    assert out.getvalue() == program
    blocks = read_program(io.StringIO(program), file="p.nc", dialect="fanuc", setup=_lathe())
    assert [m for b in blocks for m in mistyped(b)] == []
    for block in blocks[1:3]:
        for section in block.sections.values():
            assert type(section).from_xml(section.make_xml_source()) == section


def test_a_computed_lathe_tool_is_evaluated_for_a_mill_control() -> None:
    """Fanuc T's T0101 is tool 1 with offset 1; 'T#1' kept as LinuxCNC's T#1 selected tool 101. Which tool
    it names is known when it runs: the program is flattened (T1 M6, as for a written T0101)."""
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO("#1=101\nT#1\nG0 X10. Z2.\nM30\n"), out, file="p.nc", source="fanuc", target="linuxcnc",
              setup=_lathe(), diagnostics=Diagnostics(warn_stream=warnings))
    assert "T1 M6" in out.getvalue() and "#1" not in out.getvalue() and "flattened" in warnings.getvalue()


# -- a computed repeat count ----------------------------------------------------------------------------

def test_a_computed_repeat_count_runs_its_holes() -> None:
    """'G81 ... K#2' (#2=2.): the run spells the evaluated K with a point, as every K (an arc's K is a
    length), and it was refused as a count ('address K takes no decimal point'). In G90, K2 drills the
    hole twice: two feeds down (by hand)."""
    program = "G21 G90 G17 G0 X0 Y0 Z10.\n#2=2.\nG81 X4. Z-1. R1. K#2 F100.\nG80\nM30\n"
    feeds = [e for e in toolpath_events(io.StringIO(program), file="p.nc", dialect="fanuc") if e.get("move") == "feed"]
    assert [(e["x"], e["z"]) for e in feeds] == [(4, -1), (4, -1)]
    for target in ("fanuc", "linuxcnc", "isg"):
        _verified(program, "fanuc", target)
    with pytest.raises(ErrorList) as refused:
        list(toolpath_events(io.StringIO(program.replace("#2=2.", "#2=2.5")), file="p.nc", dialect="fanuc"))
    assert str(refused.value).startswith("p.nc:3:") and "whole number" in str(refused.value)


@pytest.mark.parametrize("line", ["G50 X10. Z#24", "G50 S[#24*100]", "G4 U0.5", "G4 U#24"])
def test_a_lathe_block_comes_back_from_its_xml(line: str) -> None:
    """The IR's XML (``postproc ir``) keeps a computed G50 whatever its axes' order, and a dwell's U word
    (the block syntax renamed it X and the XML lost its value)."""
    block = read_program(io.StringIO(f"#24=1.\n{line}\nM30\n"), file="p.nc", dialect="fanuc", setup=_lathe())[1]
    assert Block.from_xml(block.make_xml_source()) == block


def test_a_computed_feed_in_a_block_that_changes_units_is_scaled_for_linuxcnc() -> None:
    """LinuxCNC reads F in the units in force before its block [V: rs274]: Fanuc's 'G20 G1 X1. F#1' (an
    inch rate) is written F[#1*25.4], as F10. is written F254.; rs274 sets the same rate for both."""
    program = "G21 G90 G0 X0 Y0 Z1.\n#1=10.\nG20 G1 X1. F#1\nM30\n"
    computed = _verified(program, "fanuc", "linuxcnc")
    written = _verified(program.replace("#1=10.\n", "").replace("F#1", "F10."), "fanuc", "linuxcnc")
    assert "F[#1*25.4]" in computed and "F254." in written
    if available():
        rates = [[c for c in run_rs274(text) if "SET_FEED_RATE" in c][-1].split()[-1] for text in (computed, written)]
        assert rates[0] == rates[1]
