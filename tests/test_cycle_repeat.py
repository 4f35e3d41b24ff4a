"""The next-hole lane (``postproc.fast.holes``): a block that only moves an active cycle to its next hole
(``X.. Y..``) is resolved from the block before it when nothing it depends on has changed. The record, its
motion, where the tool ends and every error must be what resolving it from its words gives. Programs mix
next-hole blocks with every change that touches a cycle (feed, levels, G98/G99, G90/G91, units, plane,
spindle, dwell, repeats, cancels, moves) and are read twice, with the lane and without it
(``postproc.fast.reading.hole_lane`` answering None), for every reading dialect the lane is chosen for."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import io

import postproc.fast.reading as reading
from postproc.api import read_program, translate
from postproc.cycles.resolve import CannedCycleResolveSyntax
from postproc.errors import ErrorLevel, ErrorList
from postproc.fast.holes import NextHoleLane
from postproc.errors import Diagnostics
from postproc.ir import Block, CompoundMotion
from postproc.lowering.point_after import _moves_end
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup

CALLS = ["G81", "G82 P300", "G83 Q2.", "G73 Q1.5", "G84", "G85", "G86", "G89 P200", "G76 Q0.5", "G87 Q0.5"]
"""Cycle codes with the words each needs besides the levels (fanuc and LinuxCNC read them all)."""
CHANGES = ["F200.", "F80.", "G98", "G99", "G91", "G90", "G20", "G21", "G18", "G17", "M03", "M04", "M05",
           "G80", "G0 Z12.", "G1 X3. F100.", "Z-6.", "R1.", "P400", "K2", "K0", "G04 P100", "N5", "(NOTE)",
           "S900", "T2", "G54", "G55"]


@st.composite
def programs(draw: st.DrawFn) -> str:
    lines = ["G21 G17 G90 G0 X0. Y0. Z20.", "S1000 M03", "F150."]
    for _ in range(draw(st.integers(1, 14))):
        kind = draw(st.integers(0, 3))
        if kind == 0:
            code = draw(st.sampled_from(CALLS))
            z = draw(st.sampled_from(["-5.", "-9.", "3."]))
            r = draw(st.sampled_from(["2.", "0.5", "-8."]))
            lines.append(f"{draw(st.sampled_from(['G98 ', 'G99 ', '']))}{code} X1. Y2. Z{z} R{r}")
        elif kind == 1:
            lines.append(draw(st.sampled_from(CHANGES)))
        else:
            x = draw(st.sampled_from(["", "X4.", "X-7.5", "X0.", "X-0."]))
            y = draw(st.sampled_from(["", "Y3.", "Y0.25", "Y-2."]))
            lines.append(" ".join(w for w in (draw(st.sampled_from(["", "N20"])), x, y,
                                               draw(st.sampled_from(["", "(H)"]))) if w) or "X1.")
    return "\n".join(lines) + "\nG80\nM30\n"


def _lane_dialects() -> tuple[str, ...]:
    """The reading dialects whose resolver takes the lane (Fagor's letters differ: its programs are refused
    alike, or read alike)."""
    registry = default_registry()
    out = []
    for name in sorted(registry.dialects):
        dialect = registry.dialect(name)
        steps = dialect.pipeline(MachineSetup()).steps
        if any(isinstance(step, CannedCycleResolveSyntax) and reading.hole_lane(step) is not None for step in steps):
            out.append(name)
    return tuple(out)


DIALECTS = _lane_dialects()


@contextmanager
def lanes(make: Any) -> Iterator[None]:
    """The run's next-hole lane made by ``make(resolver)`` (None: no lane)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(reading, "hole_lane", make)
        yield


def resolved(program: str, dialect: str, remember: bool) -> list[Any]:
    """Each block's sections (the cycle's motion made) and the errors, comparable."""
    with lanes(reading.hole_lane if remember else lambda resolver: None):
        try:
            blocks = read_program(program.splitlines(keepends=True), file="t.nc", dialect=dialect)
        except ErrorList as err:
            return ["errors", *[str(e) for e in err.errors]]
    return [_sections(block) for block in blocks]


def _sections(block: Block) -> list[Any]:
    out: list[Any] = [block.line]
    for key, section in block.sections.items():
        if isinstance(section, CompoundMotion):
            try:
                out.append((key, [repr(item._key()) for item in section.items]))
            except Exception as err:  # an expansion refused when read: the same refusal both ways
                out.append((key, "refused", str(err)))
        else:
            key_of = getattr(section, "_key", None)
            out.append((key, repr(key_of()) if key_of is not None else repr(section)))
    return out


@pytest.mark.parametrize("dialect", DIALECTS)
@settings(max_examples=100, deadline=None)
@given(program=programs())
@example(program="G21 G17 G90 G0 X0. Y0. Z20.\nS1000 M03\nF150.\nG99 G81 X1. Y2. Z-5. R2.\nX4.\nY3.\nF80.\nX0.\n"
                 "G98\nX-7.5\nG91\nX4.\nG90\nY-2.\nG80\nM30\n")
@example(program="G21 G17 G90 G0 X0. Y0. Z20.\nS1000 M03\nF150.\nG83 Q2. X1. Y2. Z-5. R2.\nX4.\nX0. Y3.\nR1.\n"
                 "X4.\nG18\nX4.\nG17\nN20 X-7.5 (H)\nM30\n")
@example(program="G21 G17 G90 G0 X0. Y0. Z20.\nS1000 M03\nF150.\nG84 X1. Y2. Z-5. R2.\nX4.\nM04\nX0.\nG20\n"
                 "X4.\nG21\nY3.\nM30\n")
def test_a_next_hole_block_resolves_as_from_its_words(program: str, dialect: str) -> None:
    assert resolved(program, dialect, True) == resolved(program, dialect, False)


def test_next_hole_blocks_are_remembered() -> None:
    """The comparison above is not between two runs of the same path: in a row of holes, each block after
    the first repeat is made from the remembered one, and a feed change between makes the next from its
    words again."""
    made: list[bool] = []

    class Spy(NextHoleLane):
        def repeat(self, block: Block, ctx: Any) -> bool:
            done = super().repeat(block, ctx)
            if done or self.offered:  # a next-hole block (the resolver asks the lane of every block first)
                made.append(done)
            return done

    program = "G21 G17 G90 G0 X0. Y0. Z20.\nG99 G81 X1. Y2. Z-5. R2. F100.\nX2.\nX3.\nX4.\nF90.\nX5.\nX6.\nM30\n"
    with lanes(Spy):
        blocks = read_program(program.splitlines(keepends=True), file="t.nc", dialect="fanuc")
    assert made == [False, True, True, False, True]
    assert [b.sections["CannedCycle"].position["X"] for b in blocks if "CannedCycle" in b.sections] == [
        1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    assert [b.sections["CannedCycle"].feed for b in blocks if "CannedCycle" in b.sections] == [100.0] * 4 + [90.0] * 2


def test_the_lane_is_chosen_where_the_base_resolves() -> None:
    """Fanuc's and LinuxCNC's resolvers take the lane; a resolver class that overrides a method the lane
    skips does not, whatever the override does (a plugin declares nothing)."""

    class Checking(CannedCycleResolveSyntax):
        def _check(self, *args: Any) -> None:
            super()._check(*args)

    assert {"fanuc", "linuxcnc"} <= set(DIALECTS)
    assert isinstance(reading.hole_lane(CannedCycleResolveSyntax("fanuc")), NextHoleLane)
    assert reading.hole_lane(Checking("fanuc")) is None


def ends_given(program: str, target: str) -> int:
    """Translate ``program`` from Fanuc to ``target`` (a target that expands the cycles, so the steps that
    follow the point ask where each hole's moves end); every end the lane gave a next-hole block's motion
    (``holes.moves_end``) and the run kept must be what the general walk over its moves finds
    (``point_after.compound_end``'s). How many it gave."""
    given: list[tuple[CompoundMotion, object]] = []

    class Spy(NextHoleLane):
        def repeat(self, block: Block, ctx: Any) -> bool:
            done = super().repeat(block, ctx)
            compound = block.sections.get("CompoundMotion")
            if done and isinstance(compound, CompoundMotion) and compound.ended:
                given.append((compound, compound.end))
            return done

    with lanes(Spy):
        try:
            translate(program.splitlines(keepends=True), io.StringIO(), file="t.nc", source="fanuc", target=target,
                      setup=MachineSetup(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
        except ErrorList:
            pass
    for compound, end in given:
        if compound.end is end:  # (a step that replaced the moves forgot it, and walked the new ones)
            assert repr(end) == repr(_moves_end(compound.items))  # (repr: -0.0 is not 0.0 here)
    return len(given)


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
@settings(max_examples=100, deadline=None)
@given(program=programs())
@example(program="G21 G17 G90 G0 X0. Y0. Z20.\nS1000 M03\nF150.\nG99 G81 X1. Y2. Z-5. R2.\nX4.\nY3.\nX-0.\n"
                 "G98 G83 Q2. X1. Y2. Z-5. R2.\nX4.\nX0. Y3.\nG18\nX4.\nG17\nN20 X-7.5 (H)\nG80\nM30\n")
def test_a_next_hole_motion_ends_where_its_moves_do(program: str, target: str) -> None:
    ends_given(program, target)


def test_next_hole_motions_are_given_their_end() -> None:
    """The comparison above is not empty: in the cycles benchmark's rows, every next-hole block after the
    second is given where its moves end."""
    program = ("G21 G17 G90 G0 X0. Y0. Z10.\nS1800 M03\nG99 G81 X0. Y0.0 Z-5. R2. F150.\nX6.35 Y0.0\nX12.7 Y0.0\n"
               "X19.05 Y0.0\nG80\nG98 G83 X0. Y5.0 Z-12. R2. Q3. F120.\nX6.35 Y5.0\nX12.7 Y5.0\nG80\nM30\n")
    assert ends_given(program, "linuxcnc") == 3
    assert ends_given(program, "grbl") == 3


def translated(program: str, target: str, remember: bool) -> tuple[str, list[str]]:
    """``program`` from Fanuc to ``target``, with the next-hole lane or without: the output and the errors."""
    out = io.StringIO()
    with lanes(reading.hole_lane if remember else lambda resolver: None):
        try:
            translate(program.splitlines(keepends=True), out, file="t.nc", source="fanuc", target=target,
                      setup=MachineSetup(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
        except ErrorList as err:
            return out.getvalue(), [str(e) for e in err.errors]
    return out.getvalue(), []


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
def test_a_computed_next_hole_word_goes_as_without_the_lane(target: str) -> None:
    """The resolver asks the lane before it looks for a computed word: the lane declines a next-hole block
    with one (``X#1``), which the resolver then keeps verbatim (kept symbolically to Fanuc) or has computed
    first, as without the lane; and the blocks after it too."""
    program = ("#1=5.\nG21 G17 G90 G0 X0. Y0. Z20.\nS1000 M03\nG99 G81 X1. Y2. Z-5. R2. F100.\nX2.\nX3.\nX#1\n"
               "X4.\nY#1\nX6.\nG80\nM30\n")
    with_lane = translated(program, target, True)
    assert "X" in with_lane[0] and with_lane == translated(program, target, False)
