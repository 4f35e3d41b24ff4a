"""NgcWordBlockSyntax: the RS274/NGC reading of a block (LinuxCNC, grbl), through the dialect's code table.

It reuses the family's block logic where the meaning is the same (``WordBlockSyntax.g_sections``:
modal sections, motion, arcs, modal cycle repetition) and replaces what RS274/NGC reads differently:

* numbers mean what they say: ``X10`` is 10 units, there is no decimal-point scaling;
* the dwell's ``P`` and a cycle's ``P`` are seconds, as a real number;
* ``L`` is the cycle repeat count; ``K`` in a drilling cycle is an error;
* cancelling a cycle leaves no motion mode in force: axis words after it need a motion code;
* a tool length offset without ``H`` uses the tool in the spindle (the one the last tool change loaded, not
  a ``T`` selected since: rs274 ``T1 M6 T2 G43`` applies tool 1); the orient code's ``R`` gives the angle;
* where the dialect says ``FEED_BEFORE_UNITS`` (``ctx.feed_before_units``: LinuxCNC, Mach3), ``F`` in a
  block that changes units is in the old units: the controller sets the feed rate before it changes units
  (its order of execution; rs274 prints ``SET_FEED_RATE`` before ``USE_LENGTH_UNITS``), so the neutral
  Feed, in the block's units, is converted;
* a spindle stop or coolant off in a block that moves is made before the motion (the RS274/NGC order
  of execution): the section is flagged ``before_motion`` (``postproc.ir.event_order``);
* codes in the table's ``native_g``/``native_m``/``user_m`` are kept verbatim, tagged with ``DIALECT``;
  codes in its ``refused_g``/``refused_m`` are refused with a located error; any other M code is an error;
* a word whose value the reader left as an expression (``X[#1*2]``: an ``Expr`` in ``block.values``,
  a program kept symbolically) carries that ``Expr`` into its section (``Motion.axes``, ``Feed``,
  ``Dwell``, ...); checks that need the number (a cycle's ``L``, a dwell's sign) wait for the program
  to run. A computed G or M code (``G#10``) leaves the meaning of the whole block to run time: the
  block is kept as ``NativeCode``. Executed programs reach this step with numbers only.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import Any, ClassVar, Final

from postproc.context import Context, word_columns
from postproc.errors import ParseError, ProgramError
from postproc.ir.event_order import moves
from postproc.ir.expr import Binary, Expr, Num
from postproc.ir import Block, Dwell, NativeCode, SpindleOrientation
from postproc.ir.state import MM_PER_INCH

from .block_syntax import DATA_KEY, WordBlockSyntax, col_of_word, second_col
from .codes import g_key

REAL_LETTERS = frozenset("XYZABCUVWIJKRQPF")
"""Addresses read as real numbers, exactly as written."""
INTEGER_LETTERS = frozenset("NTHDL")
_STATE_KEY: Final = "NgcBlockSyntax"
"""``ctx.state.extra`` key: True while a cycle cancel leaves no motion mode in force."""
_LOADED_KEY: Final = "NgcBlockSyntax.loaded"
"""``ctx.state.extra`` key: the tool the last tool change loaded (absent or None: unknown)."""
_MOTION_GROUP: Final = ("01", "09")
_NOT_NEGATIVE = {"T": "a tool number", "H": "a tool length register", "D": "a cutter radius register",
                 "L": "a repeat count"}
"""Whole-number addresses rs274 refuses negative [V: "Negative tool id" (T-1), "Requested tool -1 not found
in the tool table" (G43 H-1), "G41 requires D word to be a whole number" (D-1), "Negative l word used"
(G81 L-1)]; grbl refuses a negative T [V: gcode.c, STATUS_NEGATIVE_VALUE for F, N, P, T and S] (its L
is only G10's, whose L-1 it does not know)."""


_RETURN_AXES: Final = "XYZABCUVW"
"""The axis words a reference return may name (its intermediate point)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class NgcWordBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, RS274/NGC word rules; subclasses give the code table."""

    __slots__ = ()
    CONTROL: ClassVar[str] = ""
    """How messages name the controller ("K in a drilling cycle: <CONTROL> counts repeats with L")."""
    NATIVE_M_WORDS: ClassVar[str] = "PQ"
    REAL_LETTERS: ClassVar[frozenset[str]] = REAL_LETTERS
    INTEGER_LETTERS: ClassVar[frozenset[str]] = INTEGER_LETTERS
    N_FIRST: ClassVar[bool] = False
    """A block number stands first in its block (after a block delete ``/``) or not at all (rs274: "Bad
    character 'n' used"); grbl reads N anywhere."""
    CYCLE_CANCEL_WITH_MOTION: ClassVar[bool] = False
    """The cycle cancel may share a block with a motion or cycle code, which wins (rs274 runs ``G80 G0
    Z1.`` as ``G0 Z1.``); grbl refuses it (error 21, one command per modal group)."""
    FEED_MODE_RESETS_FEED: ClassVar[bool] = False
    """A feed mode code (G93/G94/G95) sets the feed rate to zero, even one that selects the mode in force
    (LinuxCNC; checked with rs274); grbl keeps it unless it leaves inverse time."""
    M_GROUPS: ClassVar[dict[int, str]] = {}
    OWN_CODES: ClassVar[frozenset[str]] = frozenset()
    """The dialect reads a block further itself (``before_sections``, ``after_sections``) when one of its G codes
    has its modal group, kind or argument here, ``OWN_STATE``, or ``OWN_MOTION``; every other block stays in the
    compiled family code (an interpreted override of ``g_sections`` cost LinuxCNC's reading ~8k instructions
    a block)."""
    OWN_STATE: ClassVar[frozenset[str]] = frozenset()
    """... or while one of these ``ctx.state.extra`` keys is set ..."""
    OWN_MOTION: ClassVar[frozenset[str]] = frozenset()
    """... or when its motion mode (after the family's sections) is one of these (``after_sections`` only)."""
    SPECIAL_G: ClassVar[frozenset[str]] = frozenset()
    """G codes (``g_key``) the dialect reads itself (``special_g_code``) before its code table does: a
    hook called for these only, so that the other codes of every block stay in the compiled family base
    (an interpreted override of ``_g_code`` cost LinuxCNC's reading ~8k instructions a G word)."""
    HOOK_DECLARATIONS: ClassVar[dict[str, tuple[str, ...]]] = {
        "special_g_code": ("SPECIAL_G",),
        "before_sections": ("OWN_CODES", "OWN_STATE"),
        "after_sections": ("OWN_CODES", "OWN_STATE", "OWN_MOTION"),
    }
    """Hook -> the declarations that make it run: a subclass that overrides a hook and leaves all of them empty
    has a hook that is never called. The conformance suite checks it (``postproc.testing``)."""
    CUTTER_TAKES_LOADED_TOOL: ClassVar[bool] = False
    """G41/G42 without D takes the radius of the tool in the spindle (LinuxCNC); the reading fills in its
    number as the register, or refuses the block where it is not known. False: the register stays absent."""
    """M number -> the controller's modal group: two M codes of one group in a block are an error (rs274
    "Two m codes used from same modal group", grbl error 21). M codes not listed conflict by meaning."""

    def build(self, block: Block, ctx: Context) -> None:
        words = block.words
        if not words:
            return
        exprs = block.values
        if exprs:
            ctx.state.symbolic = True  # the reader left computed values: a program kept symbolically
            if self._computed_code(block, ctx, exprs):
                return
        else:
            lane = ctx.block_lane  # the run's plain-block lane, where it applies (``postproc.fast.plain_ngc``)
            if lane is not None and lane.read(block, ctx, words):
                return
        codes: dict[str, tuple[str, str, object, str]] = {}
        natives: list[str] = []
        raw: dict[str, str] = {}
        mcodes: list[tuple[int, str]] = []
        if self.N_FIRST:
            self._check_n_first(block, ctx)
        for letter, num in words:
            up = letter.upper()
            if up == "G":
                self._g_code(ctx, block, num, codes, natives)
            elif up == "M":
                at = ctx.at(block, col_of_word(block, "M", num))
                if "." in num:
                    raise ParseError(f"M code M{num} takes no decimal point", at)
                number = int(num)
                refused = self.CODES.refused_m.get(number)
                if refused is not None:
                    raise ParseError(refused, at)
                mcodes.append((number, num))
            elif up in raw:
                raise ParseError(f"address {up} appears twice in one block", ctx.at(block, second_col(block, up)))
            else:
                raw[up] = num
        # each check below is called only where it can find something: compiled, a method call on a plugin's
        # instance goes through Python (~1.2k instructions), and a plain block needs none of them
        if len(mcodes) > 1:
            self._check_m_groups(block, ctx, mcodes)
        if "15" in codes:
            self._path_tolerance(codes, natives, raw)
        data_setting = natives == [DATA_KEY] and bool(self.DATA_TABLES)
        if natives and not data_setting:
            self._native(block, ctx, natives, raw)
            return
        if self._machine_move_kept(block, ctx, codes, raw, ctx.state.distance):
            return
        values = block.values
        real, integer, dialect = self.REAL_LETTERS, self.INTEGER_LETTERS, self.DIALECT  # a plugin's: read once
        if exprs:
            for up, num in raw.items():
                if up not in values:
                    values[up] = _word_value(block, ctx, up, num, real, integer, dialect)
                elif up not in real and up not in integer and up != "S":
                    _word_value(block, ctx, up, num, real, integer, dialect)  # an address the dialect does not use
        else:
            for up, num in raw.items():
                values[up] = _word_value(block, ctx, up, num, real, integer, dialect)
        if data_setting:
            used = {"N"}
            if self._data_setting(block, ctx, codes, values, used):
                self.g_sections(block, ctx, codes, values, used, False)
                self.m_sections(block, ctx, mcodes, values, used)
                self.finish_words(block, ctx, values, used)
            return
        state = ctx.state
        extra = state.extra
        cycle_block = "09" in codes and codes["09"][1] == "cycle" or (
            state.cycle is not None and "01" not in codes and "09" not in codes)
        if cycle_block or "L" in values:
            self._check_cycle_words(block, ctx, values, cycle_block)
        home = codes.get("00")
        if home is not None and home[1] == "home" and not any(k in values for k in _RETURN_AXES):
            # [V] rs274: a bare G28 prints a traverse of every axis to the stored G28 position (0 0 0 in a fresh
            # run); [K] grbl and RS274/NGC v3 (Mach3) go to the stored position too; Fanuc moves no axis
            raise ProgramError(f"G{home[3]} with no axis word moves every axis to the position stored on the machine "
                               f"(by G{home[3]}.1 or its settings), which the program does not give: name the axes "
                               "it returns", ctx.at(block, col_of_word(block, "G", home[3])))
        before = extra.get(_LOADED_KEY, _NONE_LOADED)
        if any(self.CODES.m.get(number, ("", None))[0] == "tool_change" for number, _ in mcodes):
            selected = values["T"] if "T" in values else state.tool
            extra[_LOADED_KEY] = selected if isinstance(selected, (int, Expr)) else None  # M6 runs before G43
        if "08" in codes and codes["08"][2] == "positive" and "H" not in values:
            self._loaded_tool(block, ctx, values)
        if self.CUTTER_TAKES_LOADED_TOOL and "07" in codes and codes["07"][2] in ("left", "right") \
                and "D" not in values:
            self._loaded_cutter(block, ctx, values, before)
        no_motion = extra.get(_STATE_KEY, False)
        if "01" in codes or "09" in codes:
            no_motion = codes.get("09", ("", ""))[1] == "cycle_cancel" and "01" not in codes
            extra[_STATE_KEY] = no_motion
        if no_motion and not cycle_block and "01" not in codes and codes.get("00", ("", ""))[1] != "home":
            axis = next((k for k in values if k in "XYZABCUVW"), None)
            if axis is not None:
                raise ProgramError(f"axis words with no motion mode in force ({self.spell('cycle_cancel')} cancels it: "
                                   f"program {self.spell('motion', 'rapid')} or {self.spell('motion', 'linear')})",
                                   ctx.at(block, ctx.column_of(block, axis)))
        if "01" in codes:
            self._check_feed_mode_code(block, ctx, codes, values)
        used = {"N"}
        if cycle_block:
            used.add("L")
        if codes.get("00", ("", ""))[1] == "dwell":
            self._ngc_dwell(block, ctx, values, used, codes.pop("00")[3])
        self.g_sections(block, ctx, codes, values, used, cycle_block)
        if "MachineCoordinates" in block.sections:
            self._machine_move(block, ctx, codes)
        self.m_sections(block, ctx, mcodes, values, used)
        self.finish_words(block, ctx, values, used)
        if ctx.feed_before_units and "Units" in block.sections and "Feed" in block.sections:
            _feed_in_old_units(block, ctx)
        _stops_before_motion(block)
        if self.FEED_MODE_RESETS_FEED and "FeedMode" in block.sections and "Feed" not in block.sections:
            ctx.state.feed = None  # the modal step applies the mode and leaves the feed rate unset

    def _check_n_first(self, block: Block, ctx: Context) -> None:
        numbers = [i for i, (letter, _) in enumerate(block.words) if letter == "N" or letter == "n"]
        if not numbers:
            return  # the common block: no N at all
        text = block.text or ""
        first = len(text) - len(text.lstrip(" \t"))
        if text[first:first + 1] == "/":
            first += 1
            first += len(text[first:]) - len(text[first:].lstrip(" \t"))
        if numbers == [0] and text[first:first + 1] in ("N", "n"):
            return  # one N, the first word, where the text starts: no column to find
        for col, letter, _ in word_columns(text):
            if letter in "Nn" and col != first + 1:
                raise ParseError(f"a block number stands first in its block ({self.CONTROL} refuses N elsewhere)",
                                 ctx.at(block, col))

    def _check_m_groups(self, block: Block, ctx: Context, mcodes: list[tuple[int, str]]) -> None:
        """Two M codes of one modal group (``M_GROUPS``) in a block are an error (called for two or more)."""
        groups = self.M_GROUPS
        if len(mcodes) < 2 or not groups:
            return
        seen: dict[str, str] = {}
        for number, num in mcodes:
            group = groups.get(number)
            if group is None:
                continue
            if group in seen:
                raise ParseError(f"M codes M{seen[group]} and M{num} are both in one modal group "
                                 f"({self.CONTROL} runs one of each group per block)",
                                 ctx.at(block, col_of_word(block, "M", num)))
            seen[group] = num

    def _check_feed_mode_code(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any]) -> None:
        """A feed motion code needs a feed rate in force even with no axis words: rs274 refuses a bare
        ``G1`` ("Cannot do g1 with zero feed rate"), grbl too (error 22). A program that computes is
        left to the run, where the order of execution is known. Called for a block with a motion code."""
        motion = codes.get("01")
        if motion is None or motion[2] not in ("linear", "cw", "ccw") or ctx.state.symbolic:
            return
        resets = "05" in codes and self.FEED_MODE_RESETS_FEED
        feed = values.get("F", None if resets else ctx.state.feed)
        if isinstance(feed, Expr) or ctx.state.feed_mode == "inverse_time" or ("05" in codes and not resets):
            return
        if not feed:
            raise ProgramError(f"{self.spell('motion', motion[2])} with no feed rate in force (program F first)",
                               ctx.at(block, col_of_word(block, "G", motion[3])), needs="F")

    def _computed_code(self, block: Block, ctx: Context, exprs: dict[str, Any]) -> bool:
        """A G or M code given by an expression: its meaning is known only when the program runs, so
        the block is kept verbatim (the interpreter reads it with the number when it executes)."""
        for letter in ("G", "M"):
            if isinstance(exprs.get(letter), Expr):
                num = next(n for a, n in block.words if a.upper() == letter)
                block.add(NativeCode(self.DIALECT, f"a computed {letter} code ({letter}{num})", block.text or ""))
                return True
        return False

    def _g_code(self, ctx: Context, block: Block, num: str, codes: dict[str, Any], natives: list[str],
                key: str | None = None) -> None:
        """Read G``num`` (``key``: its ``g_key`` when the caller has it) into ``codes`` or ``natives``."""
        if key is None:
            key = g_key(num)
        if key in self.SPECIAL_G and self.special_g_code(ctx, block, num, key, natives):
            return
        refused = self.CODES.refused_g.get(key)
        if refused is not None:
            raise ParseError(refused, ctx.at(block, col_of_word(block, "G", num)))
        entry = self.CODES.g.get(key)
        if entry is None:
            if key in self.CODES.native_g:
                natives.append(key)
                return
            raise ParseError(f"unknown G code G{num}", ctx.at(block, col_of_word(block, "G", num)))
        group = entry[0]
        other = codes.get(group)
        if other is None and group in _MOTION_GROUP:
            other = codes.get(_MOTION_GROUP[group == "01"])
        if other is not None and self.CYCLE_CANCEL_WITH_MOTION and "cycle_cancel" in (entry[1], other[1]):
            if entry[1] == "cycle_cancel":
                return  # the motion or cycle code already read wins
            del codes[other[0]]  # the cancel read before this code gives way to it
            other = codes.get(group)
        if other is not None:
            raise ParseError(f"G codes G{other[3]} and G{num} are both in one modal group",
                             ctx.at(block, col_of_word(block, "G", num)))
        codes[group] = (group, entry[1], entry[2], num)

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        """The family's sections, with the dialect's own reading around them for the blocks ``OWN_CODES``,
        ``OWN_STATE`` and ``OWN_MOTION`` select."""
        own = self._owns(ctx, codes)
        kept = self.before_sections(block, ctx, codes, values, used) if own else None
        super().g_sections(block, ctx, codes, values, used, cycle_block)
        if not own:
            motions = self.OWN_MOTION
            if motions:
                motion = block.sections.get("Motion")
                own = motion is not None and motion.mode in motions  # type: ignore[attr-defined]
        if own:
            self.after_sections(block, ctx, codes, values, used, kept)

    def _owns(self, ctx: Context, codes: dict[str, Any]) -> bool:
        """A G code of the block, or the state, selects the dialect's own reading (``OWN_CODES``, ``OWN_STATE``)."""
        own = self.OWN_CODES
        if own:
            for group, kind, arg, _ in codes.values():
                if group in own or kind in own or isinstance(arg, str) and arg in own:
                    return True
        states = self.OWN_STATE
        if states:
            extra = ctx.state.extra
            for key in states:
                if key in extra:
                    return True
        return False

    def before_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                        used: set[str]) -> dict[str, Any] | None:
        """Read what the dialect reads before the family's sections; what it returns goes to ``after_sections``."""
        return None

    def after_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                       used: set[str], kept: dict[str, Any] | None) -> None:
        """Read what the dialect reads after the family's sections (``kept``: ``before_sections``' answer, None
        where it did not run)."""

    def special_g_code(self, ctx: Context, block: Block, num: str, key: str, natives: list[str]) -> bool:
        """Read G``num`` (``key``, one of ``SPECIAL_G``) the dialect's own way: True when read, False to
        leave it to the code table. The family reads none."""
        return False

    def _path_tolerance(self, codes: dict[str, Any], natives: list[str], raw: dict[str, str]) -> None:
        """``G64 P Q`` (blending with a tolerance) has no neutral meaning: keep it verbatim. A method, not a
        static method: compiled, a static method is called directly and a plugin's override (LinuxCNC reads
        the tolerances) is never reached. Called for a block with a path control code (group 15)."""
        path = codes.get("15")
        if path is not None and path[2] == "cutting" and ("P" in raw or "Q" in raw):
            natives.append("64")

    def _native(self, block: Block, ctx: Context, natives: list[str], raw: dict[str, str]) -> None:
        """Keep a block with a code the IR does not model verbatim, tagged with its meaning."""
        key = natives[0]
        what = f"G{key} ({self.CODES.native_g.get(key, 'path blending with a tolerance')})"
        block.add(NativeCode(self.DIALECT, what, block.text or ""))
        values = block.values
        for up, num in raw.items():
            if not isinstance(values.get(up), Expr):
                values[up] = float(num) if "." in num else int(num)

    def _check_cycle_words(self, block: Block, ctx: Context, values: dict[str, Any], cycle_block: bool) -> None:
        """L counts repeats only in a cycle block; K is refused there, and so is L0. Called for a cycle block
        and for a block with L."""
        if not cycle_block:
            if "L" in values:
                raise ProgramError("L (repeat count) outside a canned cycle",
                                   ctx.at(block, ctx.column_of(block, "L")))
            return
        if "K" in values:
            raise ProgramError(f"K in a drilling cycle: {self.CONTROL} counts repeats with L",
                               ctx.at(block, ctx.column_of(block, "K")))
        repeats = values.get("L", 1)
        if not isinstance(repeats, Expr) and repeats < 1:
            raise ProgramError("a canned cycle cannot repeat zero times (L must be 1 or more)",
                               ctx.at(block, ctx.column_of(block, "L")))

    def _loaded_tool(self, block: Block, ctx: Context, values: dict[str, Any]) -> None:
        """A tool length offset without H applies the offset of the tool in the spindle: the one the last
        tool change loaded (before any: the machine's, which the set-up's ``startTool`` may say)."""
        tool = _spindle_tool(ctx)
        if tool is None:
            raise ProgramError(f"{self.spell('length', 'positive')} without H uses the loaded tool, which is not known "
                               "here: program H",
                               ctx.at(block, ctx.column_of(block, "G")))
        values["H"] = tool

    def _loaded_cutter(self, block: Block, ctx: Context, values: dict[str, Any], before: Any) -> None:
        """Cutter compensation without D takes the radius of the tool in the spindle (``_loaded_tool``): its
        number becomes the register, so every target and the simulation take the same radius. In the block of a
        tool change it is the radius of the tool *before* the change (``before``: what ``_LOADED_KEY`` held): [V]
        rs274 2.9, ``T1 M6`` .. ``G41 M6 T2`` compensates by T1's radius (the tool changes, but G41 reads the
        radius the interpreter held when the block began), where G43 without H takes the new tool's length."""
        loaded = before is not _NONE_LOADED
        tool = before if loaded else ctx.setup.machine.start_tool
        if tool is None or (isinstance(tool, int) and tool == 0 and loaded):
            known = "not known here (no tool change before it, no startTool in the set-up's <Machine>)" \
                if tool is None else "tool 0 (a tool change that empties the spindle: rs274 then keeps the last " \
                "tool's radius)"
            raise ProgramError(f"cutter compensation without D takes the radius of the tool in the spindle, which "
                               f"is {known}: program D", ctx.at(block, ctx.column_of(block, "G")))
        values["D"] = tool

    def _machine_move(self, block: Block, ctx: Context, codes: dict[str, Any]) -> None:
        """Machine coordinates move in the motion mode in force, which must be rapid or linear (the ISO
        reading always rapids); also without axis words (LinuxCNC: "Must use g0 or g1 with g53"; grbl's
        gcode.c checks the motion mode of every G53 block)."""
        mode = codes["01"][2] if "01" in codes else ctx.state.motion
        if ctx.state.extra.get(_STATE_KEY) and "01" not in codes:
            mode = None
        if mode not in ("rapid", "linear"):
            machine = self.spell("machine")
            raise ProgramError(f"{machine} needs {self.spell('motion', 'rapid')} or {self.spell('motion', 'linear')} "
                               "in force", ctx.at(block, col_of_word(block, machine[:1], machine[1:])))
        motion = block.sections.get("Motion")
        if motion is not None:
            motion.mode = mode  # type: ignore[attr-defined]

    def _ngc_dwell(self, block: Block, ctx: Context, values: dict[str, Any], used: set[str], num: str) -> None:
        """Dwell P<seconds> (the ISO reading: P milliseconds or X seconds), made before the shared logic runs."""
        if "P" not in values:
            raise ProgramError(f"{self.spell('dwell')} needs a dwell time P (seconds)", ctx.at(block, col_of_word(block, "G", num)))
        seconds = values["P"]
        if isinstance(seconds, Expr):
            used.add("P")
            block.add(Dwell(seconds))
            return
        seconds = float(seconds)
        if seconds < 0:
            raise ProgramError("a dwell time cannot be negative", ctx.at(block, ctx.column_of(block, "P")))
        used.add("P")
        block.add(Dwell(seconds))

    def unknown_m(self, block: Block, ctx: Context, number: int, num: str) -> str | None:
        """RS274/NGC controls know their M codes: user M codes are kept verbatim, anything else is an error.
        A user M code the set-up's ``<MachineCodes>`` declares is a machine function (None: ``machine_m``),
        simulated by its declared action: the program file it runs is the machine's, as a builder's code is
        (a ``<ForeignCodes>`` mapping writes one, ``postproc.setup.foreign_codes``)."""
        native = self.CODES.native_m.get(number)
        if native is not None:
            return f"M{num} ({native})"
        if number in self.CODES.user_m:
            if any(code.key() == ("M", str(number)) for code in ctx.setup.machine_codes):
                return None
            return f"M{num} (user M code)"
        raise ParseError(f"unknown M code M{num}", ctx.at(block, col_of_word(block, "M", num)))

    def orient(self, block: Block, ctx: Context, num: str, values: dict[str, Any], used: set[str]) -> None:
        """The orient code takes the angle from R (Q is a timeout, P the direction)."""
        angle = values.get("R", ctx.setup.cycles.orient_angle)
        block.add(SpindleOrientation(angle if isinstance(angle, Expr) else float(angle)))
        used.update("RQP")


def _word_value(block: Block, ctx: Context, up: str, num: str, real: frozenset[str], integer: frozenset[str],
                dialect: str) -> float | int:
    """A word's number as the dialect reads its address: ``real`` letters as written, ``integer`` ones whole
    (and not negative where rs274 refuses it), S either. A function, not a method: compiled, a method of a
    class plugins subclass is called through Python for a plugin's instance (~1.4k instructions a word)."""
    if up in real:
        return float(num)
    if up in integer:
        if "." in num:
            raise ParseError(f"address {up} takes a whole number ({up}{num})",
                             ctx.at(block, ctx.column_of(block, up)))
        value = int(num)
        if value < 0 and up in _NOT_NEGATIVE:
            raise ParseError(f"{up}{num}: {_NOT_NEGATIVE[up]} cannot be negative",
                             ctx.at(block, ctx.column_of(block, up)))
        return value
    if up == "S":
        return float(num) if "." in num else int(num)
    raise ParseError(f"address {up} is not used by the {dialect} dialect",
                     ctx.at(block, ctx.column_of(block, up)))


_NONE_LOADED: Final = object()
"""``_LOADED_KEY`` unset: no tool change yet (the set-up's ``startTool`` is in the spindle)."""


def _spindle_tool(ctx: Context) -> Any:
    """The tool in the spindle: the one the last tool change loaded, before any the set-up's
    ``<Machine startTool>`` (None: unknown)."""
    extra = ctx.state.extra
    return extra[_LOADED_KEY] if _LOADED_KEY in extra else ctx.setup.machine.start_tool


def _feed_in_old_units(block: Block, ctx: Context) -> None:
    """The block's F was set in the units in force before it: express it in the block's new units
    (an inverse-time F is no length and stays)."""
    sections = block.sections
    before, after = ctx.state.units, sections["Units"].system  # type: ignore[attr-defined]
    mode = sections.get("FeedMode")
    inverse_time = (mode.mode if mode is not None else ctx.state.feed_mode) == "inverse_time"  # type: ignore[attr-defined]
    if before == after or inverse_time:
        return
    feed = sections["Feed"]
    factor = MM_PER_INCH if after == "mm" else 1.0 / MM_PER_INCH
    value = feed.value  # type: ignore[attr-defined]
    feed.value = Binary("mul", value, Num(factor)) if isinstance(value, Expr) else value * factor  # type: ignore[attr-defined]


def _stops_before_motion(block: Block) -> None:
    """Flag the block's spindle stop and coolant off: RS274/NGC makes them before the block's motion."""
    sections = block.sections
    spindle = sections.get("SpindleControl")
    coolant = sections.get("Coolant")
    stops = spindle is not None and spindle.direction == "stop"  # type: ignore[attr-defined]
    off = coolant is not None and coolant.mode == "off"  # type: ignore[attr-defined]
    if not (stops or off) or not moves(sections):
        return
    if stops:
        spindle.before_motion = True  # type: ignore[union-attr]
    if off:
        coolant.before_motion = True  # type: ignore[union-attr]
