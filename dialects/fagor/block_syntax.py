"""FagorBlockSyntax: the Fagor 8070's reading of a block's words, the family's word rules with Fagor's
table and hole-cycle words.

* A number without a decimal point is in mm/inch (``X10`` = 10 mm) [K], whatever the set-up's ``Input``.
* In a hole cycle ``Z`` is the reference plane, ``I`` the depth and ``K`` the dwell (a real number in
  the set-up's unit, not a repeat count); the resolve step reads them through ``Fagor.CYCLE_WORDS``.
  Fagor's cycle words are read in the XY plane (G17) only: which axis ``Z`` names in G18/G19 is not
  confirmed [?], so a cycle there is a located error.
* ``G53`` qualifies the block's move, at rapid and in absolute positions (``codes``): a ``G53`` with no axis
  word, under ``G91`` or with ``G01`` (or another motion than ``G00``) in force is a located error, as what
  the 8070 does then (a zero offset deselection? incremental machine positions? a feed move?) is not
  confirmed [?].
* A motion code (``G00``-``G03``) while a fixed cycle is active, without ``G80`` in its block, is a located
  error: whether it ends the cycle on the 8070 is not confirmed [?] (``cycle_end``). So is a ``G53`` move
  there without a motion code (``G53 Z0``): the 8070 programming manual's fixed-cycle and G53 pages were
  not reached (searched: REF 0809, REF 1901 only by their covers), so whether it ends the cycle, keeps it or
  drills at the machine position is [?].
* ``M19`` only where the set-up says ``<Cycles orientation="m19"/>`` [?].
* ``G04 K``: a dwell of K in the cycle dwell's unit.
* ``D<n>`` selects tool offset n (the 8070 takes ``D1`` before any); ``G43`` applies its length, ``G44``
  cancels it (not Fanuc's negative offset), G41/G42 take its radius (``postproc.isg_family.tool_data``).
* Multiple machining (``G160``-``G165``): a block with one of those codes goes, whole and before any
  word rule, to ``multiple_machining`` (the hook below), which reads its words itself (its ``P2.005``
  ranges, its ``I``/``K`` meanings).
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.errors import ProgramError, UnsupportedError
from postproc.ir.expr import Binary, Expr, Num
from postproc.ir import Block, Dwell, Motion
from postproc.rs274.block_syntax import WordBlockSyntax, col_of_word
from postproc.rs274.codes import CodeTable, g_key

from postproc.isg_family.tool_data import expects_register, read_tool_data

from .codes import CODES, PATTERN_CODES
from .cycle_end import GROUP_01
from .cycle_words import cycle_words
from .multiple_machining import multiple_machining


FIRST_OFFSET = 1
"""The tool offset in force before a program selects one [V: 8070 programming manual REF 1709 p.240]."""


class FagorBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, for Fagor 8070 mills."""

    XNAME = "FagorBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "fagor"
    TITLE: ClassVar[str] = "Fagor"
    CODES: ClassVar[CodeTable] = CODES
    POINTLESS_IN_UNITS: ClassVar[bool] = True
    MACHINE_MOVE_INCREMENTAL: ClassVar[str] = "absolute"
    """The family's G53-under-G91 rule steps aside: this reader refuses such a block itself, with the 8070's
    own reason (``machine_move`` below)."""
    CYCLE_K_COUNTS: ClassVar[bool] = False

    def build(self, block: Block, ctx: Context) -> None:
        for letter, num in block.words:
            if letter in "Gg" and g_key(num) in PATTERN_CODES:
                self.multiple_machining(block, ctx, f"G{g_key(num)}", num)
                return
        super().build(block, ctx)
        sections = block.sections
        motion = sections.get("Motion")
        if ctx.state.cycle is not None and isinstance(motion, Motion) and motion.mode in GROUP_01 \
                and "CycleCancel" not in sections and "CycleCall" not in sections:
            code = next((num for letter, num in block.words if letter in "Gg" and g_key(num) in CODES.g
                         and CODES.g[g_key(num)][0] == "01"), "")
            raise UnsupportedError(f"G{code} while a fixed cycle is active: whether a motion code ends the cycle on "
                                   "the 8070 is not confirmed (write G80 before it)",
                                   ctx.at(block, col_of_word(block, "G", code)))
        if "CycleCall" in block.sections:
            plane = block.sections.get("Plane")
            current = getattr(plane, "plane", None) or ctx.state.plane
            if current != "XY":
                code = next(num for letter, num in block.words if letter in "Gg" and g_key(num) in CODES.g
                            and CODES.g[g_key(num)][1] == "cycle")
                raise ProgramError(f"G{code}: Fagor hole cycles are read in the XY plane (G17) only (which axis Z "
                                   "names in G18/G19 is not confirmed)", ctx.at(block, col_of_word(block, "G", code)))

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        length = codes.get("08")
        if length is not None and length[2] == "positive":
            expects_register(values, ctx, FIRST_OFFSET)
        super().g_sections(block, ctx, codes, values, used, cycle_block)
        read_tool_data(block, ctx, values, used, toggles=True, first=FIRST_OFFSET)
        if "MachineCoordinates" in block.sections:
            self.machine_move(block, ctx, codes)

    @staticmethod
    def machine_move(block: Block, ctx: Context, codes: dict[str, Any]) -> None:
        """``G53`` read only where its meaning is the confirmed one: a rapid move, in absolute positions (the
        family's reading makes every ``G53`` move a rapid, Fanuc's rule)."""
        motion = block.sections.get("Motion")
        distance = block.sections.get("DistanceMode")
        at = ctx.at(block, col_of_word(block, "G", "53"))
        if ctx.state.cycle is not None and "01" not in codes and "CycleCancel" not in block.sections:
            raise UnsupportedError("G53 while a fixed cycle is active: whether the 8070 ends the cycle, keeps it or "
                                   "runs it at the machine position is not confirmed (write G80 before it)", at)
        if not isinstance(motion, Motion) or not motion.axes:
            raise UnsupportedError("G53 without an axis word: what it does on the 8070 (a zero offset deselection?) "
                                   "is not confirmed", at)
        if (ctx.state.distance if distance is None else getattr(distance, "mode", None)) != "absolute":
            raise UnsupportedError("G53 under G91: whether the 8070 takes its positions as increments is not "
                                   "confirmed (write G90 in the block)", at)
        code = codes.get("01")
        if (ctx.state.motion if code is None else code[2]) != "rapid":
            raise UnsupportedError("G53 with a motion other than G00 in force: whether the 8070 then moves at the "
                                   "feed rate is not confirmed (write G00 in the block)", at)

    def cycle_data_letters(self, ctx: Context) -> str:
        """Z (the reference plane, an axis letter already), I (the depth) and K (the dwell)."""
        return "IK"

    def _dwell(self, block: Block, ctx: Context, values: dict[str, Any], used: set[str], num: str) -> None:
        """``G04 K``: K in the unit of the cycle dwell (the set-up's ``fagorDwellUnit``)."""
        at = ctx.at(block, col_of_word(block, "G", num))
        if "K" not in values:
            raise ProgramError("G04 needs a dwell time K", at)
        unit = cycle_words(ctx.setup).dwell_unit or 1.0
        k = values["K"]
        used.add("K")
        if isinstance(k, Expr):
            block.add(Dwell(k if unit == 1.0 else Binary("mul", k, Num(unit))))
            return
        if k < 0:
            raise ProgramError("a dwell time cannot be negative", at)
        block.add(Dwell(float(k) * unit))

    def orient(self, block: Block, ctx: Context, num: str, values: dict[str, Any], used: set[str]) -> None:
        """``M19`` is read only on a machine whose set-up says it has it (``<Cycles orientation="m19"/>``):
        the 8070's oriented stop is not confirmed [?]."""
        if ctx.setup.cycles.orientation != "m19":
            raise UnsupportedError(f"M{num}: an oriented spindle stop is not confirmed on the 8070 (a set-up with "
                                   "<Cycles orientation=\"m19\"/> says the machine has M19)",
                                   ctx.at(block, col_of_word(block, "M", num)))
        super().orient(block, ctx, num, values, used)

    def multiple_machining(self, block: Block, ctx: Context, code: str, num: str) -> None:
        """THE HOOK for G160-G165 (``code`` is ``"G160"`` .. ``"G165"``, ``num`` the number as written).

        Called instead of the word rules for the whole block: ``block.words`` holds the raw
        ``(letter, text)`` pairs as lexed (``("P", "2.005")``), ``block.values`` any computed word
        (an ``Expr``), ``block.text`` the line; ``ctx.state`` has the active cycle and position. The
        multiple-machining reader (``multiple_machining.py``) adds the block's ``HolePattern`` and its
        motion, or raises a located ``PostprocError``.
        """
        multiple_machining(block, ctx, code, num)
