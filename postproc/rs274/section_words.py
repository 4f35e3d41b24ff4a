"""SectionWords: the words of a block's modal and auxiliary sections (units, offsets, spindle, tool,
coolant, program control, settings...), the second layer of ``WordWriter`` (``postproc.rs274.writer``).

Each ``<key>_words`` method writes one section; every code is spelt from the dialect's ``CODES`` table (the
inverse of what its reader reads), so a meaning the dialect has no row for is an ``UnsupportedError``,
never another dialect's spelling.
"""

from __future__ import annotations

from typing import Any, Callable, ClassVar, Final, Mapping

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir.expr import Binary, Expr, Num
from ..ir import Block, Motion, Section
from ..ir.verbatim import STORED_WORK_OFFSET
from ..lowering.machine_functions import RIGID_TAP, foreign_hint, refused_rigid_tap
from ..syntaxes.comment_rule import CommentRule
from ..syntaxes.comments import CommentSyntax
from ..ir.state import MM_PER_INCH
from .codes import CodeTable
from .word_numbers import NumberWriter

UNNAMED_PROGRAM_NUMBER: Final = 1
"""The ``O`` number of a named program when neither the set-up nor the command line gives one."""
MOTION_GROUP: Final = frozenset({"rapid", "linear", "cw", "ccw"})

"""Motion modes written with a code of the motion group (G0-G3)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class SectionWords(NumberWriter):
    """Writes the words of each section but the motion; ``WordWriter`` assembles them into blocks."""

    CODES: ClassVar[CodeTable] = CodeTable(())
    """The dialect's code table: the writer spells each code as the table's first row for its meaning,
    and a meaning with no row is an ``UnsupportedError``."""

    DWELL_WORD: ClassVar[str] = ""
    """Address of the dwell time, e.g. 'X' or 'P' ('': the dialect writes no dwell); its unit is the
    target's ``DWELL_UNIT``."""

    CYCLE_CANCEL_IS_MOTION: ClassVar[bool] = False
    """True where the cycle cancel is one of the motion codes (RS274/NGC: G80 and G0 in one block are a
    modal-group error): a block that writes a motion code leaves the cancel out, the motion code ends
    the cycle by itself."""

    FOREIGN_COMMENTS: ClassVar[CommentSyntax | None] = None
    """The syntax another dialect's comment text is written with (``CommentSyntax.comment``: made safe, never a
    comment the controller acts on, LinuxCNC's ``(MSG,``); None: parentheses become brackets, nothing more."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        foreign = self.FOREIGN_COMMENTS
        self.comment_rule: CommentRule | None = (
            foreign.rule if foreign is not None and source_dialect != self.DIALECT else None)
        """How ``comment`` writes a comment's text: the ``FOREIGN_COMMENTS`` syntax's rule where the source is
        another dialect, chosen once (a comment is written on every expanded hole: no call back into a
        plugin per comment); None: brackets for parentheses."""
        self.numbers_dropped = False
        """A block number above ``MAX_BLOCK_NUMBER`` was dropped (warned once a run)."""
        self.codes = self.table()
        """The code table written (a dialect with one per machine type picks it from the context)."""
        self.named_numbered = False
        """A named program's start was written with ``UNNAMED_PROGRAM_NUMBER`` (a second one is a comment)."""
        mist = ctx.setup.controller.mist_coolant
        self.mist_coolant = (target is None or target.MIST_COOLANT) if mist is None else mist
        """Mist coolant may be written: the target runs it in every build, or the set-up says this one does."""

    def table(self) -> CodeTable:
        """The code table to write with; the dialect's ``CODES`` unless it has one per machine type."""
        return self.CODES

    def comment(self, text: str) -> str:
        rule = self.comment_rule
        if rule is not None:
            return rule.comment(text)
        return "(" + text.replace("(", "[").replace(")", "]") + ")"

    def comment_line(self, text: str) -> str:
        return self.comment(text) + "\n"

    def comments_words(self, s: Any, block: Block) -> list[str]:
        return [self.comment(t) for t in s.texts]

    def program_start(self, s: Any, block: Block) -> str:
        """``O`` and the program's number; a named program (ISG/Fagor ``%name``) takes the number the set-up
        or ``--program-number`` gives, else ``O0001`` with a warning, and its name follows as a comment (a
        comment on the ``O`` line is how Fanuc shows a program's name in its directory [K]). A later named
        start, which the source runs through, is its name as a comment."""
        number = s.number
        if number is None and self.named_numbered:
            # another program start in the flow (an ISG file with a second %name runs on through it): a
            # second O0001 would be a second program with the same number, which Fanuc refuses
            return self.comment(str(s.name))
        if number is None:
            self.named_numbered = True
            number = UNNAMED_PROGRAM_NUMBER
            self.ctx.diagnostics.warn(
                f"the program {s.name!r} has no number in the {self.DIALECT} dialect: written as "
                f"O{number:04d} (give one with --program-number or <Output programNumber>)", self.ctx.at(block))
        text = f"O{int(number):04d}"
        return text + " " + self.comment(str(s.name)) if s.name else text

    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        return ["/" if s.level == 1 else f"/{s.level}"]

    def sequence_words(self, s: Any, block: Block) -> list[str]:
        """``N<number>``, or nothing for a number the controller refuses (``Writer.MAX_BLOCK_NUMBER``): the block
        runs the same without its label (a label, it moves nothing), where a refused line would stop the program."""
        limit = self.MAX_BLOCK_NUMBER
        if limit and s.number > limit:
            if not self.numbers_dropped:
                self.numbers_dropped = True
                self.ctx.diagnostics.warn(
                    f"block number N{s.number} is above {limit}, the largest the {self.DIALECT} controller takes: "
                    f"dropped (here and on any later such block; renumber with --renumber to keep them)",
                    self.ctx.at(block))
            return []
        return [f"N{s.number}"]

    def code(self, kind: str, arg: object, what: str, block: Block) -> str:
        """The dialect's spelling of ``(kind, arg)``; an ``UnsupportedError`` naming ``what`` without one."""
        code = self.codes.spell(kind, arg)
        if code is None:
            self.unsupported(what, block)
        return code

    def _code(self, kind: str, arg: object, what: str, block: Block) -> list[str]:
        return [self.code(kind, arg, what, block)]

    def plane_words(self, s: Any, block: Block) -> list[str]:
        return self._code("plane", s.plane, f"the {s.plane} plane", block)

    def units_words(self, s: Any, block: Block) -> list[str]:
        self.units_before = self.modal.units
        if s.system != self.modal.units and self.carry:
            factor = MM_PER_INCH if s.system == "mm" else 1.0 / MM_PER_INCH
            self.carry = {axis: error * factor for axis, error in self.carry.items()}
        self.modal.set_units(s.system)  # the block's numbers are written in its units
        return self._code("units", s.system, f"{s.system} units", block)

    def distance_mode_words(self, s: Any, block: Block) -> list[str]:
        self.modal.distance = s.mode
        return self._code("distance", s.mode, f"{s.mode} distance mode", block)

    def work_offset_words(self, s: Any, block: Block) -> list[str]:
        return self._code("offset", s.index, f"work offset {s.index}", block)

    def feed_mode_words(self, s: Any, block: Block) -> list[str]:
        self.modal.feed_mode = s.mode
        return self._code("feed_mode", s.mode, f"feed mode {s.mode}", block)

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        return self._code("return", s.level, f"return to the {s.level} level", block)

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        if s.mode != "off" and not self.capable("CUTTER_COMPENSATION"):
            self.unsupported(f"cutter radius compensation ({s.mode})", block)
        words = self._code("cutter", s.mode, f"cutter compensation {s.mode}", block)
        if s.register is not None:
            words.append("D" + self.register(s.register, block))
        return words

    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        if s.mode == "dynamic":  # the length itself in the block (grbl, LinuxCNC ``G43.1 Z..``)
            code = self._code("length", "dynamic", "a dynamic tool length offset (a length given in the program, "
                              "not a register of the tool table)", block)
            return code + ["Z" + self.length(s.length, block, "Z")]
        if s.mode != "cancel" and not self.capable("TOOL_LENGTH_OFFSET"):
            self.unsupported("a tool length offset from a table", block)
        words = self._code("length", s.mode, f"tool length offset {s.mode}", block)
        if s.register is not None:
            words.append("H" + self.register(s.register, block))
        return words

    WRITES_PATH_TOLERANCE: ClassVar[bool] = False
    """The dialect writes a cutting mode's blending tolerances (LinuxCNC's ``P``/``Q``); one that does not
    warns where a program gave them, as the tolerance is left to the machine's own parameters."""

    PATH_CONTROL_LACK: ClassVar[str] = ""
    """Why the dialect's code table has no modal path control code where it has none (a sentence with its
    source, added to the refusal); empty: none said."""

    def path_control_words(self, s: Any, block: Block) -> list[str]:
        """The mode's code; the exact path, where the table has no code for it, as the exact stop (Fanuc's G61
        [K]): the same programmed points reached, the machine also stopping at each block end
        (``PathControl``)."""
        if s.one_shot:
            return self._code("path_once", s.mode, "a one-shot exact stop", block)
        self.note_unwritten_tolerance(s, block)
        lack = self.PATH_CONTROL_LACK
        mode = s.mode
        if mode == "exact_path" and self.codes.spell("path", mode) is None:
            mode = "exact_stop"
        return self._code("path", mode, f"path control {s.mode}" + (f" ({lack})" if lack else ""), block)

    def note_unwritten_tolerance(self, s: Any, block: Block) -> None:
        """Warn where a program's blending tolerances are not written (``WRITES_PATH_TOLERANCE``)."""
        if not self.WRITES_PATH_TOLERANCE and (s.tolerance is not None or s.naive is not None):
            given = ", ".join(f"{name} {value:g}" for name, value in (("path", s.tolerance), ("naive-CAM", s.naive))
                              if value is not None)
            self.ctx.diagnostics.warn(f"the blending tolerance ({given}) is not written: {self.DIALECT}'s cutting "
                                      "mode blends as the machine's own parameters say", self.ctx.at(block))

    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid", "linear"))
    """Motion modes a block in machine coordinates may move in (RS274/NGC: G0 or G1 in force)."""
    MACHINE_MOVE_INCREMENTAL_KNOWN: ClassVar[bool] = False
    """What the controller does with a machine-coordinate move's words under G91 is known (grbl: machine
    positions [V]); otherwise such a move is refused, as its own reader keeps it verbatim."""

    def machine_coordinates_words(self, s: Any, block: Block) -> list[str]:
        """Machine coordinates qualify the block's move; without one they do nothing, and RS274/NGC refuses
        them unless G0 or G1 is in force, so they are not written."""
        motion = block.sections.get("Motion")
        if motion is None or not getattr(motion, "axes", None):
            return []  # no move to qualify (``G01 G53``): it does nothing
        if getattr(motion, "mode", None) not in self.MACHINE_MOVES:
            self.unsupported(f"a {motion.mode} move in machine coordinates (its machine-coordinate code "  # type: ignore[attr-defined]
                             f"moves only {' or '.join(sorted(self.MACHINE_MOVES))})", block)
        if not self.MACHINE_MOVE_INCREMENTAL_KNOWN:
            distance = block.sections.get("DistanceMode")
            mode = getattr(distance, "mode", None) or getattr(getattr(self, "modal", None), "distance", None)
            if mode == "incremental":
                self.unsupported("a move in machine coordinates in incremental distance mode (what the controller "
                                 "makes of its words there is not known [?]: program absolute distance in the block)",
                                 block)
        return self._code("machine", None, "motion in machine coordinates", block)

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        motion = block.sections.get("Motion")
        if self.CYCLE_CANCEL_IS_MOTION and isinstance(motion, Motion) and motion.mode in MOTION_GROUP:
            return []  # the block's motion code cancels the cycle
        return self._code("cycle_cancel", None, "a canned-cycle cancel", block)

    def dwell_words(self, s: Any, block: Block) -> list[str]:
        code = self.code("dwell", None, "a dwell", block)
        if not self.DWELL_WORD:
            self.unsupported("a dwell", block)
        if isinstance(s.seconds, Expr):
            if self.target is not None and self.target.DWELL_UNIT == "milliseconds":
                self.unsupported("a computed dwell time in milliseconds", block)
            return [code, self.DWELL_WORD + self.expression(s.seconds, block)]
        if self.target is not None and self.target.DWELL_UNIT == "milliseconds":
            return [code, f"{self.DWELL_WORD}{round(s.seconds * 1000)}"]
        return [code, self.DWELL_WORD + self.seconds(s.seconds)]

    def feed_words(self, s: Any, block: Block) -> list[str]:
        if "Units" in block.sections:
            return self.feed_beside_units(s, block)
        return self.feed_rate_words(s, block)

    def feed_beside_units(self, s: Any, block: Block) -> list[str]:
        """The feed rate of a block that also changes units, which the neutral block gives in its new units;
        a ``FEED_BEFORE_UNITS`` target reads it in the units before the block, so it is spelled in those (an
        inverse-time F is no length)."""
        units = block.sections["Units"]
        if (not self.feed_before_units or units.system == self.units_before  # type: ignore[attr-defined]
                or self.modal.feed_mode == "inverse_time"):
            return self.feed_rate_words(s, block)
        modal = self.modal
        after, modal.units = modal.units, self.units_before  # spelled in the units it is read in
        factor = MM_PER_INCH if after == "inch" else 1.0 / MM_PER_INCH
        try:
            if isinstance(s.value, Expr):  # F#1 under G20: F[#1*25.4], the same rate in the units before
                modal.feed = None  # known only when the program runs
                return ["F" + self.expression(Binary("mul", s.value, Num(factor)), block)]
            modal.feed = s.value
            return ["F" + self.feed_number(s.value * factor, block)]
        finally:
            modal.units = after

    def feed_rate_words(self, s: Any, block: Block) -> list[str]:
        """``F`` and the feed rate, in the units in force."""
        value = s.value
        if isinstance(value, Expr):
            self.modal.feed = None  # known only when the program runs
            return ["F" + self.expression(value, block)]
        self.modal.feed = value
        return ["F" + self.feed_number(value, block)]

    def spindle_mode_words(self, s: Any, block: Block) -> list[str]:
        """Constant surface speed or rpm; a control without the choice runs rpm only, so rpm needs no word."""
        code = self.codes.spell("spindle_mode", s.mode)
        if code is None and s.mode == "rpm":
            return []
        return self._code("spindle_mode", s.mode, "constant surface speed", block)

    def spindle_speed_words(self, s: Any, block: Block) -> list[str]:
        rpm = s.rpm
        if isinstance(rpm, Expr):
            return ["S" + self.expression(rpm, block)]
        return ["S" + self.speed(rpm)]

    def tool_select_words(self, s: Any, block: Block) -> list[str]:
        return ["T" + self.whole(s.number, block)]

    def tool_change_words(self, s: Any, block: Block) -> list[str]:
        if not self.capable("TOOL_CHANGER"):
            self.unsupported("a tool change (no tool changer)", block)
        return self._code("tool_change", None, "a tool change", block)

    def spindle_control_words(self, s: Any, block: Block) -> list[str]:
        return self._code("spindle", s.direction, f"spindle {s.direction}", block)

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        """M19 orients to the angle the machine's parameters hold (the set-up's ``orientAngle``);
        any other angle cannot be written with it."""
        code = self.code("orient", None, "an oriented spindle stop", block)
        if isinstance(s.angle, Expr):  # known when the program runs: the flattened program is checked then
            self.unsupported(f"an oriented spindle stop at a computed angle ({code} orients to the set-up's "
                             f"{self.ctx.setup.cycles.orient_angle:g} deg)", block)
        if abs(s.angle - self.ctx.setup.cycles.orient_angle) > 1e-9:
            self.unsupported(f"an oriented spindle stop at {s.angle:g} deg ({code} orients to the set-up's "
                             f"{self.ctx.setup.cycles.orient_angle:g} deg)", block)
        return [code]

    def coolant_words(self, s: Any, block: Block) -> list[str]:
        if s.mode == "mist" and not self.mist_coolant:
            self.unsupported(f"mist coolant: {self.DIALECT} runs it only in a build that has it (say so with "
                             "<Controller mistCoolant=\"true\"/> in the set-up)", block)
        return self._code("coolant", s.mode, f"coolant {s.mode}", block)

    def program_control_words(self, s: Any, block: Block) -> list[str]:
        return self._code("program", s.kind, f"program {s.kind}", block)

    WORK_OFFSET_SETTING: ClassVar[str] = ""
    """How the dialect sets a work offset from the program (e.g. 'G10 L2', then P and the axis values,
    absolute); '' when it has no such spelling."""

    WORK_OFFSET_COUNT: ClassVar[int] = 0
    """Work systems that spelling numbers P1..P<count> (P1 = the first work system)."""

    SETTING_AXES: ClassVar[frozenset[str]] = frozenset("XYZABCUVW")
    """Axes a work offset setting may name."""

    SETTING_ADDS_IN_INCREMENTAL: ClassVar[bool] = False
    """The dialect's work offset setting adds to the offset in incremental mode (Fanuc's G10 under G91):
    an absolute setting cannot be written while the program is incremental."""

    TOOL_DATA_SETTINGS: ClassVar[Mapping[str, tuple[str, int, str]]] = {}
    """How the dialect writes an offset register from the program, by neutral table ('tool_length' ->
    ('G10 L10', the highest register, the value's letter 'R')), then P and the value, absolute; empty when
    it has no such spelling."""

    TOOL_TABLE_LACK: ClassVar[str] = ""
    """Why a tool or cutter offset setting of another family is not written for the dialect where its controller
    can write its tool table from a program (what, with its source, and what is not known); empty: the
    generic reason, no such table."""

    WORK_OFFSET_VARIABLE: ClassVar[str] = ""
    """How the dialect sets one axis of a work offset from the program by assigning a variable, a format
    of ``index`` (1 = the first work system), ``axis`` and ``value`` (ISG ``V.G.NP[{index}].V.{axis}={value}``);
    '' when it has none. Such a controller writes the table's entry and takes it at the work system's next
    selection (``STORED_WORK_OFFSET``): setting the active system, the selection is written again after it
    (``work_offset_assignments``). Its dialect lists ``DataSetting`` in ``SPLIT`` and hands the block to
    ``work_offset_assignments``."""

    def data_setting_words(self, s: Any, block: Block) -> list[str]:
        """A G10 data setting: as written for a controller of its family; else, where exact, the target's
        absolute work offset or offset register setting; anything else has no equivalent here."""
        family = self.target.family() if self.target is not None else self.DIALECT
        if s.family == family:
            return [s.text]
        if s.table in self.TOOL_DATA_SETTINGS:
            return self._register_setting(s, block)
        why = self.work_offset_problem(s, self.WORK_OFFSET_SETTING, self.WORK_OFFSET_COUNT, False)
        if why:
            self.unsupported(f"{s.describe()}: {why}", block)
        return [*self.WORK_OFFSET_SETTING.split(), f"P{s.index}",
                *(axis + self.length(value, block, axis) for axis, value in s.values.items())]

    def work_offset_problem(self, s: Any, spelling: str, count: int, stored: bool) -> str:
        """Why a work offset setting cannot be written with the dialect's ``spelling`` for work systems
        1-``count``; '' when it can. ``stored``: the spelling writes the table, taken at the system's next
        selection (``STORED_WORK_OFFSET``), as the source's may; a setting taken at once is the same setting
        where that system is not the active one (``postproc.lowering.stored_offsets`` moves one that is to the
        next selection)."""
        table = s.table
        if table == STORED_WORK_OFFSET and (stored or s.index != self.modal.work_offset):
            table = "work_offset"
        if table == STORED_WORK_OFFSET and spelling:
            return ("the source's controller takes it at the work system's next selection, the target at once "
                    "(select the work system again right after the setting)")
        if table != "work_offset" or not spelling:
            if table.startswith(("tool_length", "cutter_offset")) and self.TOOL_TABLE_LACK:
                return self.TOOL_TABLE_LACK
            return "no such table can be set from a program"
        if s.incremental:
            return "it sets offsets absolutely only (the source adds to the offset in incremental mode)"
        if self.SETTING_ADDS_IN_INCREMENTAL and self.modal.distance == "incremental":
            return "in incremental mode its setting adds to the offset (program absolute mode first)"
        if not 1 <= s.index <= count:
            p = "P" if spelling == self.WORK_OFFSET_SETTING else ""
            return (f"its work systems are {p}1-{p}{count}" if s.index else
                    "P0 here is not the offset common to all work systems")
        if not set(s.values) <= self.SETTING_AXES:
            return f"it sets axes {''.join(sorted(self.SETTING_AXES))} only"
        return ""

    def work_offset_assignments(self, block: Block, part: Callable[[Block, dict[str, Section]], str]) -> str | None:
        """A work offset setting in the dialect's variables (``WORK_OFFSET_VARIABLE``), on a line of its own
        after the rest of its block (written by ``part``: its settings, a selection among them, act first
        [K: rs274 order of execution, G10 after the work system's selection]), then, where the source's
        setting acts at once on the active system (``G10 L2``), that system's selection again (the controller
        takes the entry there); one the source also takes at the next selection is only written. None: the
        setting is the dialect's own family's, written as it was with the rest of the block."""
        sections = block.sections
        s: Any = sections["DataSetting"]
        family = self.target.family() if self.target is not None else self.DIALECT
        if s.family == family:
            return None
        rest = {k: v for k, v in sections.items() if k != "DataSetting"}
        before = part(block, rest) if rest else ""
        if before and not before.endswith("\n"):
            before += "\n"
        try:
            why = self.work_offset_problem(s, self.WORK_OFFSET_VARIABLE, self.WORK_OFFSET_COUNT, True)
            if why:
                self.unsupported(f"{s.describe()}: {why}", block)
            index = int(s.index)
            words = [self.WORK_OFFSET_VARIABLE.format(index=index, axis=axis, value=self.length(value, block, axis))
                     for axis, value in s.values.items()]
            text = before + " ".join(words) + "\n"
            if index == self.modal.work_offset and s.table != STORED_WORK_OFFSET:  # the source's acts at once
                text += self.code("offset", index, f"work system {index}", block) + "\n"
        except UnsupportedError as err:
            if err.section is None:
                err.section = "DataSetting"  # --on-unsupported warn drops only the setting
            raise
        eol = block.eol or "\n"
        return text[:-1] + eol if eol != "\n" else text

    TOOL_DATA_IN_TABLE: ClassVar[bool] = False
    """The controller sets only a register its tool table already holds (LinuxCNC: a tool the set-up's
    ``<Tools>`` does not list is refused)."""

    def _register_setting(self, s: Any, block: Block) -> list[str]:
        """An offset register's value (``postproc.lowering.tool_entries`` makes them from a tool table entry)."""
        spelling, highest, letter = self.TOOL_DATA_SETTINGS[s.table]
        why = ""
        if self.TOOL_DATA_IN_TABLE and str(s.index) not in self.ctx.setup.tools:
            why = (f"it sets only a tool its table holds, and the set-up's <Tools> has no tool {s.index} (add "
                   f"<Tool number=\"{s.index}\" .../>)")
        elif s.incremental:
            why = "it sets offsets absolutely only (the source adds to the offset in incremental mode)"
        elif self.SETTING_ADDS_IN_INCREMENTAL and self.modal.distance == "incremental":
            why = "in incremental mode its setting adds to the offset (program absolute mode first)"
        elif not 1 <= s.index <= highest:
            why = f"its offset registers are P1-P{highest}"
        elif set(s.values) != {"R"}:
            why = "it sets one value per register (R)"
        if why:
            self.unsupported(f"{s.describe()}: {why}", block)
        return [*spelling.split(), f"P{s.index}", letter + self.length(s.values["R"], block, letter)]

    def machine_function_words(self, s: Any, block: Block) -> list[str]:
        """A machine-specific code as written, for a controller of its family; elsewhere it has no
        equivalent (``postproc.lowering.machine_functions`` comments it out under ``--on-unsupported warn``)."""
        family = self.target.family() if self.target is not None else self.DIALECT
        if s.family != family and s.action == RIGID_TAP:
            raise UnsupportedError(refused_rigid_tap(s, self.DIALECT), self.ctx.at(block))
        if s.family != family:
            raise UnsupportedError(f"{s.describe()}, a machine-specific code of the {s.family} family, has no "
                                   f"equivalent in {self.DIALECT}{foreign_hint(s)}", self.ctx.at(block))
        return [s.text]

    def frame_change_words(self, s: Any, block: Block) -> list[str]:
        """A frame command as written, back to its own dialect (``postproc.frames.lowering`` evaluates it
        for every other target)."""
        if s.family != (self.target.family() if self.target is not None else self.DIALECT):
            self.unsupported(s.describe(), block)
        return [s.text]

    def native_code_words(self, s: Any, block: Block) -> list[str]:
        if s.dialect != self.DIALECT:
            raise UnsupportedError(f"{s.what} from {s.dialect} has no equivalent in {self.DIALECT}",
                                   self.ctx.at(block))
        return [s.text]
