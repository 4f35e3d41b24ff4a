"""NgcBlockSyntax: LinuxCNC's reading of a block, the RS274/NGC word rules with LinuxCNC's code table.

G41.1/G42.1 (cutter compensation by the diameter D, L a lathe tool's orientation) stay verbatim
(``NativeCode``) and, in a block that does nothing else, carry a ``DynamicCutterCompensation`` the
simulation applies (``postproc.compensation.dynamic``) [V: LinuxCNC interp_convert.cc
convert_cutter_compensation_on: "G41.1 with no D word", "G41.1 with L word, but plane is not G18"].
"""

from __future__ import annotations

from typing import Any, ClassVar, Mapping

from postproc.compensation.dynamic import DynamicCutterCompensation
from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, NativeCode, PathControl
from postproc.rs274.codes import CodeTable, g_key
from postproc.rs274 import ngc_lathe as lathe
from postproc.rs274.ngc_block_syntax import REAL_LETTERS, NgcWordBlockSyntax
from postproc.frames.section import SHARED_OFFSET

from . import arc_centres
from .codes import CODES, M_GROUPS
from .rigid_tap import MODE as RIGID_TAP, read_rigid_tap
from .threading import MODE as THREAD_CYCLE, read_g76
from .lathe_cycles import (CODE_OF as G7X_MODES, MODES as G7X_CODES, check_profile_block, follow_compensation,
                           read_g7x)
from .tool_entry import TABLES as TOOL_TABLES, read_tool_entry

RS274_SAID = lathe.Said(s_missing='rs274: "S word missing with G96"',
                        f_beside='rs274: "F word used with a g33/g33.1"',
                        k_missing='rs274: "K word missing with g33/g33.1"')
"""What rs274 2.9 says where the lathe words are refused [V]."""
DYNAMIC_SIDES: dict[str, str] = {"41.1": "left", "42.1": "right"}
"""G41.1/G42.1 -> the side of the path."""
_DYNAMIC_WORDS = frozenset("NDL")
"""The words a dynamic compensation block may have besides its G code to be simulated."""


class NgcBlockSyntax(NgcWordBlockSyntax):
    """Lexed words -> neutral sections, for LinuxCNC milling (RS274/NGC)."""

    XNAME = "NgcBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "linuxcnc"
    CONTROL: ClassVar[str] = "LinuxCNC"
    CODES: ClassVar[CodeTable] = CODES
    N_FIRST: ClassVar[bool] = True
    FEED_MODE_RESETS_FEED: ClassVar[bool] = True
    MACHINE_MOVE_INCREMENTAL: ClassVar[str] = "error"
    """rs274 refuses G53 under G91: "Cannot use g53 incremental" [V: interp_check.cc, rs274 2.9.0~pre1 run
    here]."""
    CUTTER_TAKES_LOADED_TOOL: ClassVar[bool] = True
    """[K: LinuxCNC G-code reference, G41/G42: "if there is no D word, the radius of the currently loaded
    tool is used"; V: rs274, T1 M6 then G41 offsets by tool 1's radius]."""
    CYCLE_CANCEL_WITH_MOTION: ClassVar[bool] = True
    REAL_LETTERS: ClassVar[frozenset[str]] = REAL_LETTERS | {"E"}
    """E: G76's taper length (``threading``); anywhere else an unused word."""
    M_GROUPS: ClassVar[dict[int, str]] = M_GROUPS
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {
        2: ("work_offset", 0, 9), 1: ("tool_entry", 1, 2**31 - 1), 10: ("tool_entry_at_point", 1, 2**31 - 1),
        11: ("tool_entry_at_point_9", 1, 2**31 - 1)}
    """G10 L2 P0-P9 sets a work system's offset (P0 the active one), G10 L1/L10/L11 a tool table entry
    (``tool_entry``); other G10 forms are kept verbatim."""
    DATA_INCREMENTAL: ClassVar[bool] = False
    DATA_P0_ACTIVE: ClassVar[bool] = True
    DATA_ROTATION: ClassVar[bool] = True
    FRAME_RULES: ClassVar[str] = SHARED_OFFSET
    DYNAMIC_LENGTH_BARE: ClassVar[bool] = True
    """A bare ``G43.1`` keeps the length in force [V: rs274 2.9, ``G43.1 Z3`` then ``G43.1`` prints
    ``USE_TOOL_LENGTH_OFFSET(0 0 3, ...)`` again]."""

    def _native(self, block: Block, ctx: Context, natives: list[str], raw: dict[str, str]) -> None:
        super()._native(block, ctx, natives, raw)
        side = DYNAMIC_SIDES.get(natives[0]) if len(natives) == 1 else None
        if side is None:
            return
        code = f"G{natives[0]}"
        values = block.values
        if "D" not in values:
            raise ProgramError(f"{code} with no D word (the tool's diameter)",
                               ctx.at(block, ctx.column_of(block, "G")))
        orientation = values.get("L")
        if orientation is not None and ctx.state.plane != "ZX":
            raise ProgramError(f"{code} with an L word (a lathe tool's orientation), but the plane is not G18",
                               ctx.at(block, ctx.column_of(block, "L")))
        diameter = values["D"]
        if isinstance(diameter, Expr) or isinstance(orientation, Expr):
            return  # known when the program runs: the run reads the block again with numbers
        for letter, num in block.words:
            up = letter.upper()
            if up not in _DYNAMIC_WORDS and not (up == "G" and g_key(num) == natives[0]):
                return  # another word acts too: the block stays verbatim and the simulation refuses it
        block.sections["NativeCode"].inert = True  # type: ignore[attr-defined]
        block.add(DynamicCutterCompensation(side, float(diameter),
                                            None if orientation is None else int(orientation)))

    X_MODE_SWITCHES: ClassVar[bool] = False
    """G7/G8 switching inside a program is read (``postproc.rs274.ngc_lathe.program_x_mode``): the lathe's."""
    SPECIAL_G: ClassVar[frozenset[str]] = frozenset(lathe.MODES) | lathe.LATHE_ONLY | {"76"} | frozenset(G7X_CODES)
    """G7/G8, G33, G96/G97, G76 and G70-G72.2: read here (``special_g_code``) before the code table."""

    def special_g_code(self, ctx: Context, block: Block, num: str, key: str, natives: list[str]) -> bool:
        """G7/G8 are read against how X reads (``postproc.rs274.ngc_lathe.read_x_mode``: a lathe's
        ``xProgramming``, a mill's radius), G33 and G96/G97 into lathe sections, G76 into its moves
        (``threading``) on a lathe set-up; on a mill those stay verbatim (``toolpath`` and ``verify`` refuse them)."""
        if key in lathe.MODES:
            lathe.read_x_mode(block, ctx, num, self.X_MODE_SWITCHES)
            return True
        if not ctx.lathe and (key in lathe.LATHE_ONLY or key == "76" or key in G7X_CODES):
            natives.append(key)  # G33, G76, G70-G72, G96/G97 on a mill: verbatim, as before the lathe reading
            return True
        return False

    def _check_cycle_words(self, block: Block, ctx: Context, values: dict[str, Any], cycle_block: bool) -> None:
        """A lathe's G76 takes L (its tapers, ``threading``), no repeat count."""
        if ctx.lathe and any(letter.upper() == "G" and g_key(num) == "76" for letter, num in block.words):
            return
        super()._check_cycle_words(block, ctx, values, cycle_block)

    OWN_CODES: ClassVar[frozenset[str]] = frozenset(("spindle_mode", THREAD_CYCLE, arc_centres.GROUP, "path",
                                                     *G7X_MODES))
    """G96/G97, G76, G70-G72.2, G90.1/G91.1 and G61/G64: read around the family's sections (``before_sections``,
    ``after_sections``)."""
    OWN_STATE: ClassVar[frozenset[str]] = frozenset((arc_centres.STATE_KEY,))
    OWN_MOTION: ClassVar[frozenset[str]] = frozenset(("thread", RIGID_TAP, THREAD_CYCLE, *G7X_MODES))

    def before_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                        used: set[str]) -> dict[str, Any] | None:
        spring: dict[str, Any] = {}
        for group, (_, kind, arg, num) in list(codes.items()):
            if kind == "spindle_mode":  # G96 S D / G97 (``lathe``)
                del codes[group]
                lathe.read_spindle_mode(block, ctx, str(arg), num, values, used, RS274_SAID)
            elif arg == THREAD_CYCLE:  # G76: H spring passes, E/L its tapers (``threading``)
                spring.update((letter, values.pop(letter)) for letter in ("H", "E", "L") if letter in values)
            elif arg in G7X_MODES:  # G70-G72: their words are the cycle's (``lathe_cycles``), D a real (``_real_d``)
                spring.update((letter, values.pop(letter)) for letter in "QDEPIRKUW" if letter in values)
                if _D_KEY in ctx.state.extra:
                    spring["D"] = ctx.state.extra.pop(_D_KEY)
        return spring

    def after_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                       used: set[str], kept: dict[str, Any] | None) -> None:
        if kept:
            values.update(kept)
        if arc_centres.GROUP in codes or arc_centres.STATE_KEY in ctx.state.extra:
            arc_centres.apply_mode(block, ctx, codes)
        sections = block.sections
        path = sections.get("PathControl")
        if path is not None and path.mode == "cutting" and (  # type: ignore[attr-defined]
                "P" in values and "P" not in used or "Q" in values and "Q" not in used):
            _blending_tolerance(block, ctx, path, values, used)  # type: ignore[arg-type]
        motion = sections.get("Motion")
        if motion is not None and motion.mode == "thread":  # type: ignore[attr-defined]
            lathe.read_thread(block, ctx, motion, values, used, RS274_SAID)  # type: ignore[arg-type]
        elif motion is not None and motion.mode == RIGID_TAP:  # type: ignore[attr-defined]
            read_rigid_tap(block, ctx, motion, values, used)  # type: ignore[arg-type]
        elif motion is not None and motion.mode == THREAD_CYCLE:  # type: ignore[attr-defined]
            read_g76(block, ctx, motion, values, used)  # type: ignore[arg-type]
        elif motion is not None and motion.mode in G7X_MODES:  # type: ignore[attr-defined]
            read_g7x(block, ctx, motion, values, used)  # type: ignore[arg-type]

    def _data_setting(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                      used: set[str]) -> bool:
        """G10 L1 (``tool_entry``) here; every other G10 as the family reads it."""
        ell = values.get("L")
        if ell in TOOL_TABLES:
            number = next(n for letter, n in block.words if letter.upper() == "G" and g_key(n) == "10")
            if read_tool_entry(block, ctx, number, values, ell):
                used.update(values)
                return True
            block.add(NativeCode(self.DIALECT, f"G{number} ({self.CODES.native_g['10']})", block.text or ""))
            return False
        return super()._data_setting(block, ctx, codes, values, used)

    @staticmethod
    def _path_tolerance(codes: dict[str, Any], natives: list[str], raw: dict[str, str]) -> None:
        """``G64 P Q`` is read into ``PathControl`` (``_blending_tolerance``), not kept verbatim."""


_D_KEY = "ngc.g7x_d"
"""``ctx.state.extra`` key: the D of the block's G70-G72, read as a real (``_real_d``)."""


def _real_d(block: Block, ctx: Context) -> list[tuple[str, str]] | None:
    """D in a G70-G72 block is a distance (a real, rs274 ``read_d``), not the whole tool number the family
    reads elsewhere: it is taken out of the words and read here. Returns the words as written (None: no D), which
    the block gets back once read: a writer that rewrites the block from its words (``--normalize``) wrote the
    cycle without its D (was: ``G71 .. D1`` normalized to ``G71 ..``, another cut, exit 0)."""
    ctx.state.extra.pop(_D_KEY, None)
    for index, (letter, num) in enumerate(block.words):
        if letter in "Dd" and not (block.values and "D" in block.values):
            try:
                ctx.state.extra[_D_KEY] = float(num)
            except ValueError:
                raise ProgramError(f"D{num} is not a number", ctx.at(block, ctx.column_of(block, "D"))) from None
            words = block.words
            block.words = words[:index] + words[index + 1:]
            return words
    return None


class NgcLatheBlockSyntax(NgcBlockSyntax):
    """LinuxCNC's reading of a lathe program's block (``linuxcnc_lathe.xml``): the G70-G72 cycles' D read as a
    distance, their profile blocks followed through the subprogram definitions and the cutter compensation in
    force followed for them (``lathe_cycles``). A class of its own: a mill's blocks keep the compiled ``build``
    with no interpreted step before it."""

    XNAME = "NgcLatheBlockSyntax"
    __slots__ = ()
    X_MODE_SWITCHES: ClassVar[bool] = True

    def build(self, block: Block, ctx: Context) -> None:
        sections = block.sections
        if "Control" in sections or "NativeCode" in sections:
            check_profile_block(block, ctx)
        written = lathe.program_x_mode(block, ctx)
        for letter, num in block.words:
            if (letter == "G" or letter == "g") and g_key(num) in G7X_CODES:
                if lathe.X_MODE_KEY in ctx.state.extra:
                    raise ProgramError(f"G{num} while the program writes X in the mode other than the set-up's "
                                       "(G7/G8): a G70-G72 cycle is read only in the set-up's mode",
                                       ctx.at(block, ctx.column_of(block, "G", num)))
                with_d = _real_d(block, ctx)
                break
        else:
            with_d = None
        super().build(block, ctx)
        if written is not None:
            block.words = written  # the words as written; their values the set-up's mode
        elif with_d is not None:
            block.words = with_d  # the cycle's D back among its words, read (``_real_d``)
        follow_compensation(block, ctx)


def _blending_tolerance(block: Block, ctx: Context, path: PathControl, values: dict[str, Any], used: set[str]) -> None:
    """``G64 P- Q-``: P the path tolerance, Q the naive-CAM tolerance [V: LinuxCNC ``g-code.adoc`` "G64 Path
    Blending"; rs274 prints ``SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, P)`` and ``SET_NAIVECAM_TOLERANCE(Q)``,
    Q taking P's value when left out]. Either may be given alone; neither moves a controlled point."""
    taken = {k: values[k] for k in "PQ" if k in values and k not in used}  # (not a dwell's P)
    for letter in taken:
        if isinstance(values.get(letter), Expr):
            raise ProgramError(f"a computed {letter} in G64 is not supported (write the number)",
                               ctx.at(block, ctx.column_of(block, letter)))
    tolerance, naive = taken.get("P"), taken.get("Q")
    path.tolerance = None if tolerance is None else float(tolerance)
    path.naive = None if naive is None else float(naive)
    used.update(taken)
