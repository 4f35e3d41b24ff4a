"""The cycle resolution reads cycle words through the reading dialect's ``CycleWords``: the same hole
programmed with other letters (Fagor's reading: Z the reference plane, I the depth) resolves to the same
motion, and messages name the cycle and its words in the reading dialect's spelling."""

from __future__ import annotations

from typing import ClassVar

import pytest

from dialects.fanuc import Fanuc
from dialects.fanuc.block_syntax import FanucBlockSyntax
from dialects.fanuc.reader import FanucReader
from postproc.context import Context
from postproc.cycle_words import CycleWords
from postproc.cycles import CannedCycleResolveSyntax
from postproc.errors import Diagnostics, ErrorLevel, PostprocError
from postproc.ir import Block
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.syntaxes.syntax import Pipeline, Syntax
from postproc.syntaxes.modal_state import ModalStateSyntax

LEVEL_Z_DEPTH_I = CycleWords(names={"drill": "G81", "peck_deep": "G83"}, return_to_r="G99", level="Z",
                             peck="Q", shift="Q", dwell="P", bottom={"XY": "I"}, repeat=("N",))
"""A Fagor-like reading: Z is the reference plane, I the hole bottom (test-only letters for the rest)."""


class SpellLevelZDepthI(Syntax):
    """Rewrites a Fanuc cycle block's words into the other letters: R -> Z (level), Z -> I (bottom)."""

    XNAME: ClassVar[str] = "SpellLevelZDepthI"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        values = block.values
        if "CycleCall" in block.sections or ("R" in values and ctx.state.cycle is not None):
            bottom, level = values.pop("Z", None), values.pop("R", None)
            if bottom is not None:
                values["I"] = bottom
            if level is not None:
                values["Z"] = level


def resolve(text: str, words: CycleWords, rename: bool) -> list[Block]:
    setup = MachineSetup(input=InputSettings(decimal_point="calculator"))
    ctx = Context("t.nc", setup, Diagnostics(ErrorLevel.IMMEDIATE), "test", words)
    steps: list[Syntax] = [FanucBlockSyntax()]
    if rename:
        steps.append(SpellLevelZDepthI())
    steps += [CannedCycleResolveSyntax("fanuc"), ModalStateSyntax()]
    return list(Pipeline("test", steps).run(FanucReader(ctx).read(text.splitlines(keepends=True)), ctx))


PROGRAM = "G21 G17 G90\nG00 X0 Y0 Z50\nG98 G83 X10 Y5 Z-12 R2 Q4 F100\nX20\nG80\n"


def test_other_letters_resolve_to_the_same_motion() -> None:
    fanuc = resolve(PROGRAM, Fanuc.CYCLE_WORDS, rename=False)  # type: ignore[arg-type]
    other = resolve(PROGRAM, LEVEL_Z_DEPTH_I, rename=True)
    for line in (3, 4):
        a = fanuc[line - 1].sections["CompoundMotion"].items  # type: ignore[attr-defined]
        b = other[line - 1].sections["CompoundMotion"].items  # type: ignore[attr-defined]
        assert a == b and len(a) > 4
        ca, cb = fanuc[line - 1].sections["CannedCycle"], other[line - 1].sections["CannedCycle"]
        assert (ca.r, ca.bottom, ca.q) == (cb.r, cb.bottom, cb.q) == (2.0, -12.0, 4.0)  # type: ignore[attr-defined]


def test_messages_name_the_readers_letters() -> None:
    with pytest.raises(PostprocError) as errs:
        resolve("G21 G17 G90\nG00 X0 Y0 Z50\nG98 G81 X10 Y5 R2 F100\n", LEVEL_Z_DEPTH_I, rename=True)
    assert str(errs.value) == "t.nc:3:5: error: G81 needs a hole bottom I"
    with pytest.raises(PostprocError) as errs:
        resolve("G21 G17 G90\nG00 X0 Y0 Z50\nG98 G81 X10 Y5 Z-3 F100\n", LEVEL_Z_DEPTH_I, rename=True)
    assert str(errs.value) == "t.nc:3:5: error: G81 needs an R level Z"


def test_a_dialect_without_cycle_words_cannot_resolve_cycles() -> None:
    with pytest.raises(PostprocError, match="declares no cycle words"):
        setup = MachineSetup()
        ctx = Context("t.nc", setup, Diagnostics(ErrorLevel.IMMEDIATE), "bare")
        steps: list[Syntax] = [FanucBlockSyntax(), CannedCycleResolveSyntax("fanuc"), ModalStateSyntax()]
        text = "G00 X0. Y0. Z50.\nG81 X1. Z-1. R1. F100.\n"
        list(Pipeline("bare", steps).run(FanucReader(ctx).read(text.splitlines(keepends=True)), ctx))


def test_rs274_dialects_name_cycles_from_their_own_tables() -> None:
    assert Fanuc.CYCLE_WORDS is not None
    assert Fanuc.CYCLE_WORDS.name("peck_deep") == "G83" and Fanuc.CYCLE_WORDS.return_to_r == "G99"
    assert Fanuc.CYCLE_WORDS.repeat_letters("K+L") == ("K", "L")


def test_linuxcnc_messages_spell_linuxcnc_codes() -> None:
    from postproc.api import read_program
    from postproc.errors import ErrorList
    with pytest.raises(ErrorList) as errs:
        read_program(["G21 G17 G90\n", "G0 X0 Y0 Z10\n", "G98 G84 X1 Y0 Z-1 R2 F100\n"], file="t.ngc",
                     dialect="linuxcnc")
    assert [str(e) for e in errs.value.errors] == ["t.ngc:3:5: error: G84 needs the spindle turning clockwise (M3)"]
