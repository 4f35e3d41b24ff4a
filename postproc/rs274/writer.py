"""WordWriter: writes blocks as address words, for the RS274 family (Fanuc, grbl, LinuxCNC, ...).

A block that is unchanged and read from the same dialect is copied byte for byte. Otherwise the
block is generated from its sections: each section key dispatches through ``TRANSFORMS`` first, then a
``<key>_words`` method, and otherwise fails loudly with an ``UnsupportedError`` naming the construct
and its line (sqlglot's generator order). Every code is spelt from the dialect's ``CODES`` table (the
inverse of what its reader reads); the base has no table of its own, so a meaning the dialect has no
row for is an ``UnsupportedError``, never another dialect's spelling.

This module assembles blocks (and an expansion's lines) from words; the words come from the layers
below it, one job each: ``word_numbers`` (numbers), ``section_words`` (every section but the motion),
``motion_words`` (moves and native cycles). A dialect subclasses ``WordWriter`` and overrides any of them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, ClassVar, Final, Iterable, TextIO

from mypy_extensions import mypyc_attr

from ..block_rules import per_rev_problem
from ..context import Context
from ..interp.control import ASSIGN, CONTROL
from ..dialect import Dialect
from ..errors import ProgramError, UnsupportedError
from ..ir.event_order import after_motion
from ..ir.expr import Expr
from ..ir import Block, CompoundMotion, Dwell, Feed, Motion, Section, one_line
from ..numbers import MAX_PLACES, canonical_number
from ..output.block_references import names_block_numbers
from ..ir.state import changes_nothing
from .motion_words import MotionWords
from .word_numbers import _position

if TYPE_CHECKING:
    from ..output.block_renumbering import Renumbering

SECTION_ORDER = (
    "BlockDelete", "Sequence", "Assign", "Control", "MachineCoordinates", "PathControl", "Plane", "XProgramming", "Units", "DistanceMode",
    "DataSetting", "WorkOffset", "FeedMode", "SpindleMode", "CutterCompensation", "ToolLengthOffset", "ReturnLevel",
    "CycleCancel", "Dwell", "CoordinateSet", "FrameChange", "Motion", "RigidTap", "CannedCycle", "HolePattern", "LatheCycle", "Feed", "SpindleClamp",
    "SpindleSpeed", "ToolSelect", "ToolChange", "SpindleControl", "SpindleOrientation", "Coolant", "MachineFunction",
    "ProgramControl", "NativeCode", "Comments",
)
"""Word order of a generated block; sections that only annotate are skipped by ``IGNORED``."""
_RANK: Final = {key: rank for rank, key in enumerate(SECTION_ORDER)}
"""Section key -> its place in ``SECTION_ORDER`` (a generated block sorts only the sections it has)."""
_UNWRITTEN: Final = frozenset(("ProgramStart", "TapeMark", "Label"))
"""Sections outside ``SECTION_ORDER`` that are not refused: written apart (a program start, a tape mark) or
meaning nothing in a straight program (a label)."""


_STAYS_WITH_MOTION: Final = frozenset(("Motion", "CompoundMotion", "CannedCycle", "CycleCall", "MachineCoordinates", "Feed",
                                "Comments", "BlockDelete"))
"""What stays on the motion's line when a block is split around its dwell (``WordWriter.around_dwell``)."""
SectionWriter = Callable[[Any, Any, Block], list[str]]
"""Writes one section's words: ``(writer, section, block) -> words``."""


@mypyc_attr(allow_interpreted_subclasses=True)
class MoveLane:
    """A speed-only shortcut a run installs on its word writer (``postproc.fast.expansion_moves``): ``write``
    writes an expansion's items as ``compound`` writes them (``write_items``: ``move_line`` of each move less
    the axes ``_left_out`` leaves out, ``item_line`` of any other item). An object, not a function: ``compound``
    calls it natively."""

    def write(self, items: list[Section], block: Block, lines: list[str]) -> None:
        raise NotImplementedError


@mypyc_attr(allow_interpreted_subclasses=True)
class WordWriter(MotionWords):
    """Writes blocks as address words, spelling every code from the dialect's ``CODES`` table."""

    IGNORED: ClassVar[frozenset[str]] = frozenset()
    """Sections that annotate a block and produce no words of their own."""

    TRANSFORMS: ClassVar[dict[str, SectionWriter]] = {}

    STRUCTURE: ClassVar[frozenset[str]] = frozenset()
    """Sections that make a block part of the program's structure for the dialect (a subprogram's start or
    end, a tape mark it does not read, an assignment that needs a line of its own): ``write_block`` gives
    such a block to ``structure_block``."""
    SPLIT: ClassVar[frozenset[str]] = frozenset()
    """Sections that may make the dialect write a block as more than one line in an order of its own
    (LinuxCNC: M19 after the block's other actions): ``generate`` offers such a block to ``split_block``."""
    SPLIT_MOTIONS: ClassVar[frozenset[str]] = frozenset()
    """Motion modes ``generate`` offers to ``split_block`` likewise (ISG and Fagor: a reference return, a
    move to the set-up's home written in lines of its own)."""
    PER_REV_NEEDS_SPEED: ClassVar[str] = ""
    """What the controller cannot express when a feed move in feed per revolution meets no spindle speed
    (rs274 refuses it: "Cannot feed with zero spindle speed in feed per rev mode"), in the dialect's words;
    '': it runs it."""
    BLANK_AS_TRACE: ClassVar[bool] = False
    """A block whose sections all write nothing on this controller (grbl does without G80, G98/G99, G64)
    leaves its source line as a comment (``generate``), or nothing when it has no source line."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        out = ctx.setup.output
        renumber = out.renumber_start if out.block_numbers == "keep" else 0
        """``blockNumbers`` other than keep numbers the written lines (``postproc.output.line_format``) instead."""
        self.normalize = out.normalize or bool(renumber) or self.rounding
        """Renumbering and decimals per address rewrite the words, so they imply normalising."""
        self.renumber = renumber
        self.renumbering: Renumbering | None = None
        """The first pass of a renumbering run (``write``): the number each block gets, its references'."""
        self.copy_ok = source_dialect == self.DIALECT and not self.normalize and not self.renumber
        """A block of the dialect itself is copied byte for byte."""
        self.section_writers = self.dispatch_table()
        """Section key -> its writing function: this class's dispatch table (``section_writer``), shared by
        every run that writes this dialect."""
        self.blank_as_trace = self.BLANK_AS_TRACE  # (a field: read for every generated block)
        self.split_motions: frozenset[str] = self.SPLIT_MOTIONS  # (likewise)
        self.after_blocks = False
        """Set by a dialect while it follows what its written blocks do beyond the modal state (Fagor: from
        a cycle written with its dwell until the move that cancels the cycle): ``generate``, and the fast
        lane for a straight block, then call ``after_block``."""
        self.expanding = False
        """True while an expansion is written (``compound``): a writer that drops what its controller lacks
        from a block may not drop it from a cycle's motion."""
        self.move_lane: MoveLane | None = None
        """A speed-only shortcut the run installed (``postproc.fast.expansion_moves``): ``compound`` offers it
        each move of an expansion first."""

    def write(self, blocks: Iterable[Block], out: TextIO) -> None:
        """Write every block; a renumbering run first numbers the whole program (``Renumbering``: its
        references are written with their targets' new numbers), and is checked against that after."""
        if not self.renumber or self.source_dialect != self.DIALECT:  # (between two: ``LineFormat`` numbers)
            super().write(blocks, out)
            return
        from ..output.block_renumbering import Renumbering, takes_number
        listed = list(blocks)
        self.renumbering = Renumbering(listed, self.renumber, self.ctx.setup.output, takes_number)
        super().write(listed, out)
        for error in self.renumbering.check(self.ctx.at):
            self.ctx.diagnostics.error(error)

    def renumbering_pass(self) -> "Renumbering":
        renumbering = self.renumbering
        if renumbering is None:  # (``normalized`` called without ``write``: a numbering of no references)
            from ..output.block_renumbering import Renumbering, takes_number
            renumbering = self.renumbering = Renumbering([], self.renumber, self.ctx.setup.output, takes_number)
        return renumbering

    def native_block_reference(self, block: Block) -> str | None:
        """What in a block kept in the dialect's own words (``NativeCode``) names a block number, which a
        renumbering cannot rewrite (None: nothing; the base knows of none)."""
        return None

    def write_block(self, block: Block) -> str | None:
        """The text of a block: a block with a ``STRUCTURE`` section as ``structure_block`` writes it, any
        other as ``words_block`` does."""
        sections = block.sections
        if self.PER_REV_NEEDS_SPEED and (self.modal.feed_mode == "per_rev" or "FeedMode" in sections):
            self.refuse_feed_without_speed(block)
        if not self.STRUCTURE.isdisjoint(sections):
            return self.structure_block(block)
        return self.words_block(block)

    def refuse_feed_without_speed(self, block: Block) -> None:
        """A feed move (G1, G2, G3, even one that only selects the mode) in feed per revolution while the
        spindle speed is zero, as it is until an S (``PER_REV_NEEDS_SPEED``): the block's own S and feed
        mode come first."""
        sections = block.sections
        motion = sections.get("Motion")
        if not isinstance(motion, Motion) or motion.mode not in ("linear", "cw", "ccw"):
            return
        mode = sections.get("FeedMode")
        if (self.modal.feed_mode if mode is None else mode.mode) != "per_rev":  # type: ignore[attr-defined]
            return
        control = sections.get("SpindleControl")
        turning = self.modal.spindle if control is None or after_motion("SpindleControl", control) \
            else control.direction  # type: ignore[attr-defined]
        speed = sections.get("SpindleSpeed")
        rpm = self.modal.spindle_rpm if speed is None else speed.rpm  # type: ignore[attr-defined]
        if motion.axes and per_rev_problem(turning, rpm) is not None:
            return  # refused when read (``block_rules.per_rev_problem``): stopped, or at S0
        if rpm is None or (isinstance(rpm, (int, float)) and rpm == 0):
            self.unsupported(self.PER_REV_NEEDS_SPEED, block)

    def structure_block(self, block: Block) -> str | None:
        """A block with a ``STRUCTURE`` section: the dialect's own handling of its program's structure (the
        base has none and writes it as any other block)."""
        return self.words_block(block)

    def words_block(self, block: Block) -> str | None:
        """A block copied from the dialect itself, normalised back to it, or generated from its sections."""
        sections = block.sections
        if self.rounding or self.whole_speed:
            self.at_block = block  # where a rounding warning points
        if block.text is not None and self.copy_ok:
            if not changes_nothing(sections):
                self.modal.apply(sections)
            return block.text + block.eol
        if self.normalize and block.text is not None and self.source_dialect == self.DIALECT \
                and (block.words or "NativeCode" not in sections):  # (a verbatim line of no words: as written)
            if not changes_nothing(sections):
                self.modal.apply(sections)
            return self.normalized(block) + (block.eol or "\n")
        return self.generate(block)

    def _track(self, sections: dict[str, Section]) -> None:
        if not changes_nothing(sections):
            self.modal.apply(sections)

    def normalized(self, block: Block) -> str:
        """Rewrite a block from its words: explicit decimal points, optional renumbering."""
        values = block.values
        sections = block.sections
        if "TapeMark" in sections:
            return "%" + (getattr(sections["TapeMark"], "title", None) or "")
        text = block.text
        if (text is not None and not self.renumber and self.leading_zero and not self.rounding
                and "Comments" not in sections and "BlockDelete" not in sections
                and block.canonical):
            if self.carry:
                self.exact_axes(block)
            return text  # already normal: upper-case words, single spaces, explicit exact numbers
        axes = self._rounded_axes(block)
        if self.carry:
            self.exact_axes(block)  # a canonical absolute word is exact; a rounded one sets its carry again
        parts: list[str] = []
        skip = sections.get("BlockDelete")
        if skip is not None:
            parts.append("/" if skip.level == 1 else f"/{skip.level}")  # type: ignore[attr-defined]
        renumber = self.renumber
        source_block = block
        if renumber:
            native = self.native_block_reference(block)
            if native is not None:
                raise ProgramError(f"--renumber cannot rewrite the block number {native} names (the line is kept as "
                                   f"written): its target would change", self.ctx.at(block))
            if names_block_numbers(block):  # every reference written with its target's new number (or refused)
                from .lathe_words import profile_letters
                block = self.renumbering_pass().rewritten(block, self.ctx.word_at, profile_letters)
                values = block.values
                sections = block.sections
        # A number as written that is already explicit and exact keeps its text (and skips a float round trip):
        # digits the user wrote are never rounded away by normalising. ``canonical_number`` is called
        # directly: a bound method of a plugin's (interpreted) writer was a Python call a word (~2k instructions).
        leading_zero = self.leading_zero
        number = self.number
        places = (self.mm_places if self.modal.units == "mm" else self.inch_places) if self.rounding else None
        for letter, num in block.words:
            up = _UPPER[letter]
            if up == "N" and renumber:
                continue
            value = values.get(up)
            own = places is not None and up in places
            if isinstance(value, float) and up in axes and (axes[up] and up in self.carry or own
                                                            or not canonical_number(num, MAX_PLACES, leading_zero)):
                parts.append(up + _position(self, up, value, axes[up]))
            elif type(value) is float and (own or not canonical_number(num, MAX_PLACES, leading_zero)):
                parts.append(up + (self.speed(value) if up == "S" and own
                                   else self.feed_number(value, block) if up == "F" else number(value, up)))
            else:  # a canonical number, or an expression, keeps its text
                parts.append(up + num)
        if renumber and block.words and "ProgramStart" not in sections:
            parts.insert(1 if skip is not None else 0, f"N{self.take_number(source_block)}")
        if ASSIGN in sections or CONTROL in sections:
            at = 1 if skip is not None else 0
            if len(parts) > at and parts[at][:1] == "N":
                at += 1
            parts[at:at] = self.statements(block)
        comments = sections.get("Comments")
        if comments is not None:
            parts.extend(self.comment(t) for t in comments.texts)  # type: ignore[attr-defined]
        return " ".join(parts)

    def take_number(self, block: Block) -> int:
        """The number a renumbering run writes on ``block`` (``Renumbering.take``)."""
        try:
            return self.renumbering_pass().take(block, self.MAX_BLOCK_NUMBER, self.DIALECT, self.ctx.at)
        except ProgramError:
            self.renumber = 0  # (refused once: the run has failed, the later blocks are not numbered)
            raise

    def generate(self, block: Block) -> str:
        """Generate a block (and any lines a compound motion adds) from its sections; with
        ``BLANK_AS_TRACE``, a block of source text whose sections write nothing is its source as a comment.
        A block with a ``SPLIT`` section or a move in a ``SPLIT_MOTIONS`` mode is the dialect's
        ``split_block`` where that writes it; any other is ``unsplit``, then ``after_block`` where the
        dialect follows its blocks (``after_blocks``)."""
        sections = block.sections
        split_motions = self.split_motions
        if not self.SPLIT.isdisjoint(sections) or split_motions and _moves_in(sections, split_motions):
            split = self.split_block(block)
            if split is not None:
                return split
        text = WordWriter.unsplit(self, block)  # (a direct call, not a dispatch)
        if self.after_blocks:
            self.after_block(block)
        return text

    def unsplit(self, block: Block) -> str:
        """The block as ``generate`` writes it when no ``split_block`` does: its words on one line (and any
        lines a compound motion adds). A dialect's ``split_block`` writes a part with it."""
        text = WordWriter._generate(self, block)  # (a direct call, not a dispatch)
        if self.blank_as_trace and (not text or text.isspace()) and block.sections:
            if block.text is None:
                return ""  # a generated part whose only words the controller does without
            return self.comment(block.text.strip()) + (block.eol or "\n")  # a trace of the source line
        return text

    def split_block(self, block: Block) -> str | None:
        """A block with a ``SPLIT`` section (or a ``SPLIT_MOTIONS`` move) as lines in the dialect's order, or
        None: it is one line (the base splits nothing)."""
        return None

    def after_block(self, block: Block) -> None:
        """What the dialect follows of a block ``generate`` wrote, while ``after_blocks`` is set (the base
        follows nothing)."""

    def _generate(self, block: Block) -> str:
        sections = block.sections
        compound = sections.get("CompoundMotion")
        if compound is not None:
            return self.compound(block, compound)  # type: ignore[arg-type]
        if "TapeMark" in sections:
            title = getattr(sections["TapeMark"], "title", None)  # a target that keeps it (``LEADER_TITLE``)
            return "%" + (title or "") + (block.eol or "\n")
        motion = sections.get("Motion")
        if "Dwell" in sections and motion is not None and self.DWELL_WORD in getattr(motion, "axes", ()):
            # the dwell's word is also an axis of the move (Fanuc G04 X): the dwell on a line of its own
            return self.around_dwell(block, ("Dwell",))
        words: list[str] = []
        rank = _RANK
        present: list[str] = []
        last = -1
        ordered = True
        for key in sections:  # the block's few sections, not every key of SECTION_ORDER
            at = rank.get(key, -1)
            if at >= 0:
                present.append(key)
                if at < last:
                    ordered = False
                last = at
        if not ordered:
            present.sort(key=rank.__getitem__)
        current = ""
        try:
            for key in present:  # a direct call: compiled, it dispatches to a subclass's override natively
                current = key
                words.extend(self.section_words(key, sections[key], block))
            if len(present) != len(sections):
                for key in sections:
                    # A named label (ISG [NAME]) is only a jump target: a program that jumps is run
                    # (flattened), its labels dropped; in a straight program a label does nothing.
                    if key not in rank and key not in self.IGNORED and key not in _UNWRITTEN:
                        current = key
                        self.unsupported(f"{key}", block)
        except UnsupportedError as err:
            if err.section is None:
                err.section = current  # which section: --on-unsupported warn drops it (postproc.output.partial_block)
            raise
        start = sections.get("ProgramStart")
        if start is not None:
            if "BlockDelete" in sections:  # found by make fuzz: ISG "/ % NAME" was written "%_N_NAME_MPF /",
                # "O0001 (NAME) /", "(NAME) /": a slash after the header, which no controller reads as a skip
                skipped = UnsupportedError("a program header under block delete ('/'): the header names the "
                                           "program, which the block delete switch cannot skip")
                skipped.section = "BlockDelete"
                raise skipped
            words.insert(0, self.program_start(start, block))
        self._track(sections)
        text = " ".join([w for w in words if w])
        if not text and sections and self.BARE_FEED_MOTION_NEEDS_FEED and block.text is not None:
            text = self.comment(block.text.strip())  # every word left out: the source line as a trace
        return text + (block.eol or "\n")

    def around_dwell(self, block: Block, with_dwell: tuple[str, ...]) -> str:
        """A block whose dwell must stand on a line of its own (with ``with_dwell``), written as up to
        three lines in the block's order of events (``postproc.ir.event_order``): what acts before the dwell
        (settings, tool, spindle start, coolant on), the dwell, then the motion and what ends the block.
        A block skip goes on every line."""
        sections = block.sections
        skip = sections.get("BlockDelete")
        before = {k: v for k, v in sections.items()
                  if k not in with_dwell and k not in _STAYS_WITH_MOTION and not after_motion(k, v)}
        lines = ({k: v for k, v in sections.items() if k in with_dwell},
                 {k: v for k, v in sections.items() if k not in with_dwell and k not in before})
        text = ""
        for i, part in enumerate((before, *lines)):
            if not part or part.keys() <= {"BlockDelete"}:
                continue
            if skip is not None:
                part["BlockDelete"] = skip
            line = Block(block.line, None, block.eol if i == 2 else "\n")
            line.sections = part
            text += self.generate(line)
        return text

    def section_words(self, key: str, section: Section, block: Block) -> list[str]:
        if key == ASSIGN or key == CONTROL:
            return self.statement_words(section, block)
        write = self.section_writers.get(key)
        if write is None:
            write = self.section_writer(key)
            if write is None:
                self.unsupported(key, block)
        return write(self, section, block)

    @classmethod
    def dispatch_table(cls) -> dict[str, SectionWriter | None]:
        """This class's own section table (a subclass gets its own: it may override a method)."""
        table: dict[str, SectionWriter | None] | None = vars(cls).get("_section_writers")
        if table is None:
            table = {}
            setattr(cls, "_section_writers", table)
        return table

    @classmethod
    def section_writer(cls, key: str) -> SectionWriter | None:
        """The function that writes section ``key`` for this writer class (``TRANSFORMS`` first, then a
        ``<key>_words`` method), found once per class and key and kept in the class's own table."""
        table = cls.dispatch_table()
        if key not in table:
            found = cls.TRANSFORMS.get(key)
            table[key] = found if found is not None else getattr(cls, f"{_snake(key)}_words", None)
        write: SectionWriter | None = table[key]
        return write

    def statements(self, block: Block) -> list[str]:
        """The words of a block's assignment and control statement (the reader keeps them out of
        ``block.words``: the sections hold them)."""
        words: list[str] = []
        for key in (ASSIGN, CONTROL):
            section = block.sections.get(key)
            if section is not None:
                words.extend(self.statement_words(section, block))
        return words

    def statement_words(self, section: Section, block: Block) -> list[str]:
        """An assignment or control statement (``#1=2.``, ``WHILE [..] DO1``, a call) in the dialect's
        spelling; a dialect with variables and control flow overrides this. The base has none."""
        self.unsupported(_statement_name(section), block)

    def compound(self, block: Block, compound: CompoundMotion) -> str:
        """Write an expansion: the block's words that act before its motion (``postproc.ir.event_order``:
        modal settings, tool change, spindle start, coolant on), a comment naming the source, each item,
        then the words that act after it (spindle stop, coolant off, program stop or end). ``expanding``
        is True meanwhile."""
        was = self.expanding
        self.expanding = True
        try:
            return WordWriter._compound(self, block, compound)  # (a direct call, not a dispatch)
        finally:
            self.expanding = was

    def _compound(self, block: Block, compound: CompoundMotion) -> str:
        lines: list[str] = []
        head: dict[str, Section] = {}
        tail: dict[str, Section] = {}
        for key, section in block.sections.items():  # a hole of a row has none besides its motion
            if key != "CompoundMotion" and key != "CannedCycle" and key != "Comments":
                (tail if after_motion(key, section) else head)[key] = section
        note = self.comment_line(f"{compound.term} from line {block.line}: {self.source_text(block)}")
        if len(head) == 1 and "Sequence" in head:
            note = " ".join(self.sequence_words(head["Sequence"], block) + [note])  # (no word: a dropped number)
        elif head:
            first = Block(block.line, None, "\n")
            first.sections = head
            lines.append(self.generate(first))
        lines.append(note)
        was_incremental = self.modal.distance == "incremental"
        moves = self.move_lane
        if moves is None:
            write_items(self, compound.items, block, lines)
        else:
            moves.write(compound.items, block, lines)
        if was_incremental:
            lines.append(self.code("distance", "incremental", "incremental distance mode", block) + "\n")
            self.modal.distance = "incremental"
        comments = block.sections.get("Comments")
        if comments is not None:
            tail["Comments"] = comments
        if tail:
            then = Block(block.line, None, "\n")
            then.sections = tail
            lines.append(self.generate(then))
        text = "".join(lines)
        if block.eol != "\n" and text.endswith("\n"):
            text = text[:-1] + block.eol
        return text

    def item_line(self, item: Section, block: Block) -> str:
        """The line of an expansion's item that is not a move (a feed, a dwell, a spindle action, a stop), as
        ``compound`` writes it; a move is ``move_line``'s."""
        if isinstance(item, Motion):
            return self.move_line(item, block)
        words = self.section_words(item.KEY, item, block)
        self._track({item.KEY: item})
        return " ".join(words) + "\n"

    def move_line(self, item: Motion, block: Block) -> str:
        """The line of an expansion's move (absolute, in program units): the absolute distance mode's code
        first where another is in force, then the move's words (``motion_words``)."""
        words: list[str] = []
        if self.modal.distance != "absolute":
            words.append(self.code("distance", "absolute", "absolute distance mode", block))
            self.modal.distance = "absolute"
        words.extend(self.motion_words(item, block))
        return " ".join(words) + "\n"

    def source_text(self, block: Block) -> str:
        return _source_text(block)


def write_items(writer: WordWriter, items: list[Section], block: Block, lines: list[str]) -> None:
    """The lines of an expansion's items, as ``compound`` writes them (appended to ``lines``): each move as
    ``move_line`` writes it less the axes ``_left_out`` leaves out, any other item as ``item_line`` does."""
    before: dict[str, float | Expr] | None = None
    """The axes of the straight move written last, while the tool stands there: the next straight move
    leaves out the axes it does not change (``_left_out``)."""
    for item in items:
        if isinstance(item, Motion):
            lines.append(writer.move_line(item if before is None else _left_out(item, before), block))
            before = item.axes if _is_straight(item) else None
        else:
            lines.append(writer.item_line(item, block))
            if not isinstance(item, _STANDING):
                before = None


_STANDING: Final = (Feed, Dwell)
"""Items of an expansion the tool stands still for, between two moves (``compound``)."""
_UPPER: Final = {c: c.upper() for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz:"}


_STATEMENTS: Final = {
    "Assign": "variable assignments", "Goto": "GOTO jumps", "GotoLabel": "jumps to named labels", "IfThen": "conditional assignments",
    "If": "IF conditions", "ElseIf": "IF conditions", "Else": "IF conditions", "EndIf": "IF conditions",
    "While": "WHILE loops", "EndWhile": "WHILE loops", "Do": "DO loops", "DoWhile": "DO loops",
    "Repeat": "REPEAT loops", "EndRepeat": "REPEAT loops", "Break": "loop breaks", "Continue": "loop continues",
    "SubStart": "subprogram definitions", "SubEnd": "subprogram definitions", "Return": "subprogram returns",
    "Call": "subprogram calls", "ModalCall": "modal macro calls", "ModalCallCancel": "modal macro calls",
}
"""How messages name each statement ("the grbl dialect cannot express WHILE loops")."""


def _statement_name(section: Section) -> str:
    name = type(section).__name__
    return _STATEMENTS.get(name, name)


def _snake(key: str) -> str:
    """``SpindleControl`` -> ``spindle_control`` (the method name of a section key), computed once per key:
    every section of every generated block asks."""
    name = _SNAKE.get(key)
    if name is None:
        out = []
        for i, ch in enumerate(key):
            if ch.isupper() and i:
                out.append("_")
            out.append(ch.lower())
        name = _SNAKE[key] = "".join(out)
    return name


_SNAKE: Final[dict[str, str]] = {}


def _source_text(block: Block) -> str:
    """``source_text`` of the base: the block as read, on one line."""
    if block.text is not None:
        return one_line(block.text).strip()
    parts: list[str] = []  # (one join of the pieces: a word's letter and number joined first cost ~1,000 more a hole)
    for letter, num in block.words:
        if parts:
            parts.append(" ")
        parts.append(letter)
        parts.append(num)
    return "".join(parts)


def _moves_in(sections: dict[str, Section], modes: frozenset[str]) -> bool:
    """Whether a block's move is in one of ``modes``."""
    motion = sections.get("Motion")
    return isinstance(motion, Motion) and motion.mode in modes


def _is_straight(item: Motion) -> bool:
    return (item.mode == "rapid" or item.mode == "linear") and item.center is None and item.radius is None


def _left_out(item: Motion, before: dict[str, float | Expr]) -> Motion:
    """A straight move of an expansion without the axes whose number is the one the tool stands at
    (``before``: the move written just before it); written absolute, those words would not move it.
    The expansion-move lane (``postproc.fast.expansion_moves``) leaves out the same axes."""
    if not _is_straight(item):
        return item
    axes: dict[str, float | Expr] = {}
    for axis, value in item.axes.items():
        was = before.get(axis)
        if not (type(value) is float and type(was) is float and was == value):
            axes[axis] = value
    return item if len(axes) == len(item.axes) else Motion(item.mode, axes)
