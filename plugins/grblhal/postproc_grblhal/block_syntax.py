"""GrblhalBlockSyntax: the grbl family's block rules (``postproc.grbl_family.block_syntax``) with grblHAL's code
table, and what a build may lack checked against the set-up where the program is read: G43 H needs the tool
table (``<Controller toolTable="true">``), G95 a spindle with an encoder (``spindleSync``) [V: grblHAL core
``gcode.c``: G43 needs ``grbl.tool_table.n_tools``, feed per revolution ``spindle->hal->get_data``]. On a lathe
set-up G7/G8, G33 K and G96 S D/G97 are read as grblHAL's lathe mode runs them (``lathe``), and G76 into its moves
(``threading``), elsewhere refused. A program may switch between G7 and G8 (``postproc.rs274.ngc_lathe``): grblHAL
halves the X word of a block whose own G7/G8 (or the mode in force) says diameter, and G76's I, J and K, as rs274
does [V: grblHAL/core f80fc34 ``gcode.c``: ``gc_block.modal.diameter_mode`` set from the block's G7/G8, then
``values.xyz[X_AXIS] /= 2``; ``thread.peak``, ``initial_depth``, ``depth`` halved]."""

from __future__ import annotations

from typing import Any, ClassVar, Mapping

from postproc.context import Context
from postproc.errors import ParseError
from postproc.grbl_family.block_syntax import GrblFamilyBlockSyntax
from postproc.ir import Block, FeedMode, Motion, ToolLengthOffset
from postproc.rs274 import ngc_lathe
from postproc.rs274.block_syntax import col_of_word
from postproc.rs274.codes import CodeTable, g_key
from postproc.rs274.ngc_block_syntax import REAL_LETTERS
from postproc.frames.section import SHARED_OFFSET

from .codes import CODES, G76_ON_A_MILL, M_GROUPS, NO_M19
from .lathe import GRBLHAL_SAID, NO_SYNC as NO_THREAD_SYNC, NOT_LATHE
from .threading import CSS, IN_FORCE, MODE as THREAD_CYCLE, read_g76

NO_TABLE = ("this grblHAL build has no tool table (G43 H needs N_TOOLS above 0 or a tool table plugin): a set-up "
            "with <Controller toolTable=\"true\"/> has one")
NO_SYNC = ("this grblHAL build runs no feed per revolution (G95 needs a spindle with an encoder): a set-up with "
           "<Controller spindleSync=\"true\"/> has one")


class GrblhalBlockSyntax(GrblFamilyBlockSyntax):
    """Lexed words -> neutral sections, for grblHAL."""

    XNAME = "GrblhalBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "grblhal"
    CONTROL: ClassVar[str] = "grblHAL"
    CODES: ClassVar[CodeTable] = CODES
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {2: ("work_offset", 0, 9)}
    """G10 L2 P0-P9 sets a work system's offset (P0 the active one); other G10 forms are kept verbatim."""
    DATA_INCREMENTAL: ClassVar[bool] = False
    DATA_P0_ACTIVE: ClassVar[bool] = True
    FRAME_RULES: ClassVar[str] = SHARED_OFFSET
    """G92/G92.1/G92.2 (``codes``) mean LinuxCNC's."""
    M_GROUPS = M_GROUPS
    NO_M19 = NO_M19
    REAL_LETTERS: ClassVar[frozenset[str]] = REAL_LETTERS | {"E"}
    """E: G76's taper length (``threading``); anywhere else an unused word."""

    def build(self, block: Block, ctx: Context) -> None:
        written = ngc_lathe.program_x_mode(block, ctx) if ctx.lathe else None
        super().build(block, ctx)
        if written is not None:
            block.words = written  # the words as written; their values the set-up's mode
        sections = block.sections
        offset = sections.get("ToolLengthOffset")
        if isinstance(offset, ToolLengthOffset) and offset.mode == "positive" \
                and not ctx.setup.controller.tool_table:
            raise ParseError(NO_TABLE, ctx.at(block, col_of_word(block, "G", "43")))
        mode = sections.get("FeedMode")
        if isinstance(mode, FeedMode) and mode.mode == "per_rev" and not ctx.setup.controller.spindle_sync:
            raise ParseError(NO_SYNC, ctx.at(block, col_of_word(block, "G", "95")))

    def _g_code(self, ctx: Context, block: Block, num: str, codes: dict[str, Any], natives: list[str],
                key: str | None = None) -> None:
        """G7/G8, G33, G96/G97 only on a lathe set-up (``lathe``); G7/G8 read against its ``xProgramming``."""
        code = g_key(num) if key is None else key
        if code == "76" and not ctx.lathe:
            raise ParseError(G76_ON_A_MILL, ctx.at(block, col_of_word(block, "G", num)))
        if code in ngc_lathe.MODES or code in ngc_lathe.LATHE_ONLY:
            where = ctx.at(block, col_of_word(block, "G", num))
            if not ctx.lathe:
                raise ParseError(NOT_LATHE.format(num=num), where)
            if code in ngc_lathe.MODES:  # (a switch: ``program_x_mode`` in ``build``)
                ngc_lathe.read_x_mode(block, ctx, num, True)
                return
            if code == "33" and not ctx.setup.controller.spindle_sync:
                raise ParseError(NO_THREAD_SYNC, where)
        super()._g_code(ctx, block, num, codes, natives, key)

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        extra = ctx.state.extra
        kept: dict[str, Any] | None = None
        for group, (_, kind, arg, num) in list(codes.items()):
            if kind == "spindle_mode":  # G96 S D / G97 (``postproc.rs274.ngc_lathe``)
                del codes[group]
                ngc_lathe.read_spindle_mode(block, ctx, str(arg), num, values, used, GRBLHAL_SAID)
                extra[CSS] = arg == "css"
            elif arg == THREAD_CYCLE:  # G76: H spring passes, E/L its tapers (``threading``)
                kept = {letter: values.pop(letter) for letter in ("H", "E", "L") if letter in values}
        if kept is None and IN_FORCE in extra and ("01" in codes or "09" in codes):
            del extra[IN_FORCE]  # another motion mode: grblHAL clears the thread data at the next G76
        super().g_sections(block, ctx, codes, values, used, cycle_block)
        if kept:
            values.update(kept)
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion):
            if motion.mode == "thread":
                ngc_lathe.read_thread(block, ctx, motion, values, used, GRBLHAL_SAID)
            elif motion.mode == THREAD_CYCLE:
                read_g76(block, ctx, motion, values, used)

    def _check_cycle_words(self, block: Block, ctx: Context, values: dict[str, Any], cycle_block: bool) -> None:
        """A lathe's G76 takes L (its tapers, ``threading``), no repeat count."""
        if ctx.lathe and any(letter.upper() == "G" and g_key(num) == "76" for letter, num in block.words):
            return
        super()._check_cycle_words(block, ctx, values, cycle_block)
