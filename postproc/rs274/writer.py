"""WordWriter: writes blocks as address words, for the RS274 family (Fanuc, grbl, LinuxCNC, ...).

A block that is unchanged and read from the same dialect is copied byte for byte. Otherwise the
block is generated from its sections: each section key dispatches through ``TRANSFORMS`` first, then a
``<key>_words`` method, and otherwise fails loudly with an ``UnsupportedError`` naming the construct
and its line (sqlglot's generator order). Every code is spelt from the dialect's ``CODES`` table (the
inverse of what its reader reads); the base has no table of its own, so a meaning the dialect has no
row for is an ``UnsupportedError``, never another dialect's spelling.
"""

from __future__ import annotations

import math
from typing import Any, Callable, ClassVar, NoReturn, Final

from mypy_extensions import mypyc_attr

from ..control import ASSIGN, CONTROL
from ..errors import ProgramError, UnsupportedError
from ..event_order import after_motion
from ..machine_functions import RIGID_TAP, refused_rigid_tap
from ..expr import Expr
from .codes import CodeTable
from .expressions import ExprSpelling, spell_word_value
from ..ir import Block, CompoundMotion, Dwell, Feed, Motion, Section, Sequence, one_line
from ..numbers import (
    DecimalTexts, EXACT, EXACT_INCH, MAX_PLACES, SHORT_RANGE, as_written, canonical_number, format_decimal, shortcut_places,
)
from ..state import MM_PER_INCH, PLANE_AXES, ModalState, changes_nothing
from ..context import Context
from ..cycle_words import CycleWords
from ..cycles.section import WORD_ORDER
from ..cycles.semantics import PECK, SHIFT
from ..dialect import Dialect, Writer


SECTION_ORDER = (
    "BlockDelete", "Sequence", "Assign", "Control", "MachineCoordinates", "PathControl", "Plane", "Units", "DistanceMode",
    "DataSetting", "WorkOffset", "FeedMode", "SpindleMode", "CutterCompensation", "ToolLengthOffset", "ReturnLevel",
    "CycleCancel", "Dwell", "CoordinateSet", "FrameChange", "Motion", "CannedCycle", "HolePattern", "LatheCycle", "Feed", "SpindleClamp",
    "SpindleSpeed", "ToolSelect", "ToolChange", "SpindleControl", "SpindleOrientation", "Coolant", "MachineFunction",
    "ProgramControl", "NativeCode", "Comments",
)
"""Word order of a generated block; sections that only annotate are skipped by ``IGNORED``."""
STRAIGHT_METHODS: Final = ("write_block", "generate", "section_words", "sequence_words", "motion_words", "feed_words", "left_out")
"""The methods whose work ``WordWriter.straight_move`` does for a straight move (``STRAIGHT_OVERRIDES``)."""
COPY_METHODS: Final = ("write_block", "normalized")
"""The methods whose work ``straight_move`` does for a straight block normalised back to its own dialect."""
_STRAIGHT_KEYS: Final = frozenset(("Sequence", "Motion", "Feed"))
"""A block of only these sections (a move, its block number and feed rate) is a straight block."""
_RANK: Final = {key: rank for rank, key in enumerate(SECTION_ORDER)}
"""Section key -> its place in ``SECTION_ORDER`` (a generated block sorts only the sections it has)."""
_UNWRITTEN: Final = frozenset(("ProgramStart", "TapeMark", "Label"))
"""Sections outside ``SECTION_ORDER`` that are not refused: written apart (a program start, a tape mark) or
meaning nothing in a straight program (a label)."""
UNNAMED_PROGRAM_NUMBER: Final = 1
"""The ``O`` number of a named program when neither the set-up nor the command line gives one."""


_CENTER_LETTER: Final = {"X": "I", "Y": "J", "Z": "K"}


def _copied(number: str, value: object, read: object, most: int, every: bool) -> bool:
    """Whether a canonical word's ``number`` (which reads as ``read``) is how a writer exact to ``most``
    places writes ``value`` (``straight_move``; ``every``: ``most`` covers every canonical number)."""
    if type(value) is not float:
        return False
    return read == value and (-SHORT_RANGE < value < SHORT_RANGE if every else as_written(number, value, most))


def _plain_arc(axes: dict[str, float | Expr], center: dict[str, float | Expr] | None, plane: str) -> bool:
    """An arc ``straight_move`` writes: its centre is not its start (``generate`` refuses a zero-radius
    arc where the controller does) and its end point names an axis of its plane (a full circle in
    the plane, or a helix with no end point in it, is left to ``generate`` and the writers' checks). Its
    centre's words are matched in its order, which the block syntax builds as ``generate`` writes them:
    I, J, K."""
    if center is not None:
        zero = True
        for offset in center.values():
            if type(offset) is not float or offset != 0.0:
                zero = False
        if zero:
            return False
    first, second, _ = PLANE_AXES[plane]
    return first in axes or second in axes


_STAYS_WITH_MOTION: Final = frozenset(("Motion", "CompoundMotion", "CannedCycle", "CycleCall", "MachineCoordinates", "Feed",
                                "Comments", "BlockDelete"))
"""What stays on the motion's line when a block is split around its dwell (``WordWriter.around_dwell``)."""
SectionWriter = Callable[[Any, Any, Block], list[str]]
"""Writes one section's words: ``(writer, section, block) -> words``."""


@mypyc_attr(allow_interpreted_subclasses=True)
class WordWriter(Writer):
    """Writes blocks as address words, spelling every code from the dialect's ``CODES`` table."""

    DIALECT: ClassVar[str] = ""
    CODES: ClassVar[CodeTable] = CodeTable(())
    """The dialect's code table: the writer spells each code as the table's first row for its meaning,
    and a meaning with no row is an ``UnsupportedError``."""
    DWELL_WORD: ClassVar[str] = ""
    """Address of the dwell time, e.g. 'X' or 'P' ('': the dialect writes no dwell); its unit is the
    target's ``DWELL_UNIT``."""
    IGNORED: ClassVar[frozenset[str]] = frozenset()
    """Sections that annotate a block and produce no words of their own."""
    TRANSFORMS: ClassVar[dict[str, SectionWriter]] = {}
    CYCLE_CANCEL_IS_MOTION: ClassVar[bool] = False
    """True where the cycle cancel is one of the motion codes (RS274/NGC: G80 and G0 in one block are a
    modal-group error): a block that writes a motion code leaves the cancel out, the motion code ends
    the cycle by itself."""
    BARE_FEED_MOTION_NEEDS_FEED: ClassVar[bool] = False
    """True where a feed motion code with no axis words is refused while no feed rate is in force
    (RS274/NGC: rs274 "Cannot do g1 with zero feed rate", grbl error 22): such a code only sets the mode,
    and every later move writes its own motion code, so it is left out (a block left with nothing to
    say keeps its source line as a comment)."""
    SPELLING: ClassVar[ExprSpelling | None] = None
    """How the dialect writes an expression in a word (``X[#1*2.]``); None: it has no expressions, and a
    computed word is an ``UnsupportedError`` naming it."""
    STRAIGHT_OVERRIDES: ClassVar[frozenset[str]] = frozenset()
    """Of ``STRAIGHT_METHODS``, those this class overrides that write a straight move (``straight_move``: a
    rapid or feed move of numbers, maybe a block number and a feed rate, nothing else) exactly as this base
    does. Any other override turns the straight path off for the class, so a plugin that overrides one
    and says nothing is never bypassed. ``tests/test_straight_moves.py`` checks both paths agree."""
    STRAIGHT_ARC_OVERRIDES: ClassVar[frozenset[str]] = frozenset()
    """Of the overrides ``STRAIGHT_OVERRIDES`` declares, those that also write an arc exactly as this base
    does: a clockwise or counter-clockwise move of numbers with its centre I/J/K or radius R, whose centre
    is not its start and whose end point names an axis of its plane (``straight_move`` leaves a degenerate
    arc to ``generate``, where writers refuse what their controller refuses). A class that overrides one
    of ``STRAIGHT_METHODS`` and does not list it here writes arcs through ``generate``."""
    BLANK_AS_TRACE: ClassVar[bool] = False
    """A block whose sections all write nothing on this controller (grbl does without G80, G98/G99, G64)
    leaves its source line as a comment (``generate``), or nothing when it has no source line."""
    STRAIGHT_AXES: ClassVar[frozenset[str]] = frozenset("XYZABCUVW")
    """The axes a straight move may have to take the straight path: a class whose ``motion_words`` refuses
    some (grbl drives X, Y and Z) names those it writes, so that a move of another still meets the refusal."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        out = ctx.setup.output
        renumber = out.renumber_start if out.block_numbers == "keep" else 0
        """``blockNumbers`` other than keep numbers the written lines (``postproc.line_format``) instead."""
        self.mm_places = out.address_places(False)
        self.inch_places = out.address_places(True)
        """``<Output addressDecimals>``: address -> places it is rounded to (mm, inch programs)."""
        self.rounding = bool(self.mm_places or self.inch_places)
        self.rounded_warned: set[str] = set()
        self.named_numbered = False
        """A named program's start was written with ``UNNAMED_PROGRAM_NUMBER`` (a second one is a comment)."""
        self.at_block: Block | None = None
        self.normalize = out.normalize or bool(renumber) or self.rounding
        """Renumbering and decimals per address rewrite the words, so they imply normalising."""
        self.renumber = renumber
        self.renumber_step = out.renumber_step
        self.leading_zero = out.leading_zero
        self.decimals = out.decimals
        self.inch_decimals = out.inch_decimals
        self.exact_mm = shortcut_places(self.decimals, EXACT)
        self.exact_inch = shortcut_places(self.inch_decimals, EXACT_INCH)
        """The most places a number is written with as it is, without rounding (``decimal_text``): decided
        once per run for each unit, not per number."""
        self.mm_texts = DecimalTexts(self.exact_mm, self.leading_zero)
        self.inch_texts = DecimalTexts(self.exact_inch, self.leading_zero)
        """``decimal_text`` in each unit system, remembered per value (``DecimalTexts``)."""
        self.copy_ok = source_dialect == self.DIALECT and not self.normalize and not self.renumber
        self.source_numbers = self.leading_zero and not self.rounding
        """A canonical block's axis numbers may be written as the source wrote them (``source_number``):
        canonical numbers have their leading zero, and no address is rounded to places of its own."""
        self.codes = self.table()
        """The code table written (a dialect with one per machine type picks it from the context)."""
        self.motion_codes: dict[str, str] = {}
        """Motion mode -> its code, spelled once (``CodeTable.spell`` is a Python call; an expansion
        writes a code per move)."""
        self.section_writers = self.dispatch_table()
        """Section key -> its writing function: this class's dispatch table (``section_writer``), shared by
        every run that writes this dialect."""
        self.modal = ModalState()
        self.straight_copy = (source_dialect == self.DIALECT and self.normalize and not self.renumber
                              and self.leading_zero and not self.rounding and self.straight_path(COPY_METHODS))
        """A straight block normalised back to its own dialect is its source line (``straight_move``)."""
        self.straight = self.straight_copy or (source_dialect != self.DIALECT and self.straight_path())
        """Straight moves of a canonical source block take ``straight_move`` (the class allows it; from the
        dialect itself a block is copied or normalised, never generated)."""
        self.straight_axes = self.STRAIGHT_AXES
        self.straight_items = self.straight_path()
        """The class writes a straight move as the base does: an expansion's rapid and feed moves are
        written by the base's ``motion_words`` directly (``item_line``)."""
        self.base_item_moves = self.straight_items and self.straight_path(("item_line",))
        """And an expansion's move as the base's ``item_line`` does (``compound`` calls it directly: a
        plugin's writer would dispatch each item through Python)."""
        self.base_notes = self.straight_path(("comment", "comment_line", "source_text"), "")
        """The class writes comments and source text as the base does: an expansion's note naming its source
        is spelled here (``_note``) without a dispatch through Python per block."""
        self.straight_codes = {mode: self.codes.spell("motion", mode) for mode in ("rapid", "linear")}
        """The motion codes a straight move is written with, spelled once."""
        arcs = not self.straight_copy and self.straight and self.straight_path((), "STRAIGHT_ARC_OVERRIDES")
        self.arc_codes = {mode: code for mode in ("cw", "ccw") for code in [self.codes.spell("motion", mode)]
                          if arcs and code is not None}
        """The arc codes a straight arc is written with (none: arcs take ``generate``)."""
        self.straight_codes_now = True
        self.blank_as_trace = self.BLANK_AS_TRACE  # (a field: read for every generated block)
        self.expanding = False
        """True while an expansion is written (``compound``): a writer that drops what its controller lacks
        from a block may not drop it from a cycle's motion."""
        """A block that programs its motion code may take ``straight_move`` (a writer that must see the
        program's first blocks itself turns it on once it has)."""
        """What the written program has in force so far (units, distance mode, feed, plane, spindle...)."""
        self.carry: dict[str, float] = {}
        """Axis -> where the source program is minus where the written one is (program units): what
        rounding left behind, added to the next incremental word so the sum of increments stays exact."""

    def table(self) -> CodeTable:
        """The code table to write with; the dialect's ``CODES`` unless it has one per machine type."""
        return self.CODES

    # -- numbers -----------------------------------------------------------------------------------
    def number(self, value: float, letter: str = "") -> str:
        """A length or feed with an explicit decimal point, trailing zeros dropped ('10.', '0.5').

        Rounds to the output decimals, but never silently: a value that would move by more than
        half a micrometre (or 0.00002 in) keeps up to ``MAX_PLACES`` places instead. An address
        ``letter`` with places of its own (``<Output addressDecimals>``) is rounded to them.
        """
        mm = self.modal.units == "mm"
        if self.rounding and letter:
            places = (self.mm_places if mm else self.inch_places).get(letter)
            if places is not None:
                return self.rounded(value, letter, places, mm)
        text = (self.mm_texts if mm else self.inch_texts).text(value)
        if text is not None:
            return text
        return format_decimal(value, self.decimals if mm else self.inch_decimals, self.leading_zero,
                              EXACT if mm else EXACT_INCH)

    def rounded(self, value: float, letter: str, places: int, mm: bool) -> str:
        """``value`` rounded to the ``places`` the set-up gives ``letter``; the first value of each
        address that rounding moves is a warning (the written program then deviates from the source
        by up to half a unit of the last place)."""
        text = format_decimal(value, places, self.leading_zero, math.inf)
        if letter not in self.rounded_warned and abs(float(text) - value) > (EXACT if mm else EXACT_INCH):
            self.rounded_warned.add(letter)
            unit = _ROUNDED_UNITS.get(letter) or ("mm" if mm else "in")
            if letter == "F":
                unit += "/min" if self.modal.feed_mode != "per_rev" else "/rev"
            shown = text[:-1] if letter == "S" and text.endswith(".") else text
            self.ctx.diagnostics.warn(
                f"<Output {'addressDecimals' if mm else 'inchAddressDecimals'}>: {letter} is rounded to {places} "
                f"places ({value:.6g} written {letter}{shown}); this and later {letter} words may differ from the "
                f"source by up to {0.5 * 10.0 ** -places:g} {unit}",
                self.ctx.at(self.at_block) if self.at_block is not None else None)
        return text

    @staticmethod
    def integer(value: float | int) -> str:
        return str(int(value))

    def expression(self, expr: Expr, block: Block, what: str = "a computed word") -> str:
        """A word value that is an expression, in the dialect's ``SPELLING`` (``#1``, ``[#1*2.]``)."""
        if self.SPELLING is None:
            self.unsupported(f"{what} (no variables or expressions)", block)
        try:
            return spell_word_value(expr, self.SPELLING)
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

    def length(self, value: float | Expr, block: Block, letter: str = "") -> str:
        """A length, feed or other real word value: a number, or an expression kept symbolically."""
        if isinstance(value, Expr):
            return self.expression(value, block)
        return self.number(value, letter)

    def whole(self, value: float | int | Expr, block: Block) -> str:
        """An integer word value (T, P, L...): a number, or an expression kept symbolically."""
        if isinstance(value, Expr):
            return self.expression(value, block)
        return str(int(value))

    # -- blocks ------------------------------------------------------------------------------------
    def write_block(self, block: Block) -> str | None:
        sections = block.sections
        if self.rounding:
            self.at_block = block  # where a rounding warning points
        if block.text is not None and self.copy_ok:
            if not changes_nothing(sections):
                self.modal.apply(sections)
            return block.text + block.eol
        if self.normalize and block.text is not None and self.source_dialect == self.DIALECT:
            if not changes_nothing(sections):
                self.modal.apply(sections)
            return self.normalized(block) + (block.eol or "\n")
        return self.generate(block)

    @classmethod
    def straight_path(cls, methods: tuple[str, ...] = (), declared: str = "STRAIGHT_OVERRIDES") -> bool:
        """Whether this class may write straight moves with ``straight_move``: every method of ``methods``
        (default ``STRAIGHT_METHODS``: those a generated block passes) is the base's, or the class that
        defines it lists it in its own ``declared`` set (``STRAIGHT_OVERRIDES``; ``STRAIGHT_ARC_OVERRIDES``
        for arcs; '' for none: only the base's own methods count); a subclass that overrides it again says
        so again: a declaration is not inherited by a new override."""
        for name in methods or STRAIGHT_METHODS:
            owner = next(c for c in cls.__mro__ if name in c.__dict__)
            if owner is not WordWriter and name not in owner.__dict__.get(declared, ()):
                return False
        return True

    def straight_move(self, block: Block) -> str | None:
        """A CAM program's usual block, ``N.. G1 X.. Y.. Z.. F..``, written without ``generate``'s section
        dispatch: the text ``generate`` writes, or None (``generate`` then writes it) unless the block is
        a rapid or feed move of numbers the source wrote in canonical spelling (``block.canonical``), with
        at most a block number and a feed rate besides, its words in that order, each number the value
        it reads as and one this writer writes as written (``source_number``), and nothing carried. The
        line is then the source line with the motion code after its block number. Of the modal state
        such a block changes only the feed rate (``ModalState.apply``). Most of a CAM block's writing
        is dispatch and spelling; this is a few comparisons. Normalised back to its own dialect
        (``straight_copy``), a canonical block of a move, a block number and a feed rate is its source
        line, as ``normalized`` writes it."""
        sections = block.sections
        text = block.text
        if self.straight_copy:
            if text is None:
                return None
            for key in sections:  # (one pass: of the straight keys only the feed rate is modal)
                if key not in _STRAIGHT_KEYS:
                    return None
            # what ``write_block`` does to a canonical block it normalises: its source line, exact
            if "Feed" in sections:
                self.modal.apply(sections)
            if self.carry:
                self._exact_axes(block)
            return text + (block.eol or "\n")
        motion = sections.get("Motion")
        if not isinstance(motion, Motion) or text is None or self.carry or not self.source_numbers:
            return None
        mode = motion.mode
        axes = motion.axes
        if mode is None or not axes:
            return None
        center = motion.center
        radius = motion.radius
        arc = 0
        if center is None and radius is None:
            code = self.straight_codes.get(mode)
        else:
            code = self.arc_codes.get(mode)
            if code is None or not _plain_arc(axes, center, self.modal.plane):
                return None
            arc = len(center) if center is not None else 1
        if code is None:
            return None
        sequence = sections.get("Sequence")
        feed = sections.get("Feed")
        besides = (sequence is not None) + (feed is not None)
        words = block.words
        at = 0
        head = 0
        values = block.values  # what the words read as (a reader's, untouched since: ``Block.values``)
        if sequence is not None:
            if not isinstance(sequence, Sequence):
                return None
            letter, number = words[0]
            if letter != "N" or values.get("N") != sequence.number or number[0] == "0" and len(number) > 1:
                return None  # (N010 is written N10)
            at = 1
            head = len(number) + 1
        coded = at < len(words) and words[at][0] == "G"  # the block's own motion code: it is rewritten
        if len(sections) != 1 + besides or len(words) != len(axes) + besides + arc + coded:
            return None
        written = 0
        if coded:
            if not self.straight_codes_now:
                return None
            written = len(words[at][1]) + 1
            at += 1
        most = self.exact_mm if self.modal.units == "mm" else self.exact_inch
        every = most >= MAX_PLACES  # every canonical number has at most MAX_PLACES: as_written is the range
        driven = self.straight_axes
        for axis, value in axes.items():
            letter, number = words[at]
            at += 1
            if letter != axis or letter not in driven or type(value) is not float or not (
                    -SHORT_RANGE < value < SHORT_RANGE if every else as_written(number, value, most)) \
                    or values.get(letter) != value:  # the number the word reads as: no step changed it
                return None
        if arc:
            if center is not None:
                for axis, value in center.items():
                    letter, number = words[at]
                    at += 1
                    if letter != _CENTER_LETTER[axis] or not _copied(number, value, values.get(letter), most, every):
                        return None
            else:
                letter, number = words[at]
                at += 1
                if letter != "R" or not _copied(number, radius, values.get(letter), most, every):
                    return None
        if feed is not None:
            if not isinstance(feed, Feed):
                return None
            rate = feed.value
            letter, number = words[at]
            if letter != "F" or type(rate) is not float or not (
                    -SHORT_RANGE < rate < SHORT_RANGE if every else as_written(number, rate, most)) \
                    or values.get(letter) != rate:
                return None
            self.modal.feed = rate
        eol = block.eol or "\n"
        if coded:
            start = head + 1 if head else 0
            return f"{text[:start]}{code}{text[start + written:]}{eol}"
        if head:
            return f"{text[:head]} {code}{text[head:]}{eol}"
        return f"{code} {text}{eol}"

    def _track(self, sections: dict[str, Section]) -> None:
        if not changes_nothing(sections):
            self.modal.apply(sections)

    def normalized(self, block: Block) -> str:
        """Rewrite a block from its words: explicit decimal points, optional renumbering."""
        values = block.values
        sections = block.sections
        if "TapeMark" in sections:
            return "%"
        text = block.text
        if (text is not None and not self.renumber and self.leading_zero and not self.rounding
                and "Comments" not in sections and "BlockDelete" not in sections
                and block.canonical):
            if self.carry:
                self._exact_axes(block)
            return text  # already normal: upper-case words, single spaces, explicit exact numbers
        axes = self._rounded_axes(block)
        if self.carry:
            self._exact_axes(block)  # a canonical absolute word is exact; a rounded one sets its carry again
        parts: list[str] = []
        skip = sections.get("BlockDelete")
        if skip is not None:
            parts.append("/" if skip.level == 1 else f"/{skip.level}")  # type: ignore[attr-defined]
        renumber = self.renumber
        if renumber:
            control = sections.get(CONTROL)
            if control is not None and getattr(control, "target", None) is not None:
                raise ProgramError("--renumber cannot renumber a program that jumps to block numbers (GOTO, "
                                   "a return to a block number): the numbers it names would change",
                                   self.ctx.at(block))
        canonical = self._canonical
        number = self.number
        places = (self.mm_places if self.modal.units == "mm" else self.inch_places) if self.rounding else None
        for letter, num in block.words:
            up = _UPPER[letter]
            if up == "N" and renumber:
                continue
            value = values.get(up)
            own = places is not None and up in places
            if isinstance(value, float) and up in axes and (axes[up] and up in self.carry or own or not canonical(num)):
                parts.append(up + _position(self, up, value, axes[up]))
            elif type(value) is float and (own or not canonical(num)):  # an expression keeps its text
                parts.append(up + (self.speed(value) if up == "S" and own
                                   else self.feed_number(value, block) if up == "F" else number(value, up)))
            else:
                parts.append(up + num)
        if renumber and block.words and "ProgramStart" not in sections:
            parts.insert(1 if skip is not None else 0, f"N{renumber}")
            self.renumber = renumber + self.renumber_step
        if ASSIGN in sections or CONTROL in sections:
            at = 1 if skip is not None else 0
            if len(parts) > at and parts[at][:1] == "N":
                at += 1
            parts[at:at] = self.statements(block)
        comments = sections.get("Comments")
        if comments is not None:
            parts.extend(self.comment(t) for t in comments.texts)  # type: ignore[attr-defined]
        return " ".join(parts)

    def _canonical(self, num: str) -> bool:
        """True when a number as written is already explicit and exact: keep its text (and skip a float
        round trip). Digits the user wrote are never rounded away by normalising."""
        return canonical_number(num, MAX_PLACES, self.leading_zero)

    def generate(self, block: Block) -> str:
        """Generate a block (and any lines a compound motion adds) from its sections; with
        ``BLANK_AS_TRACE``, a block of source text whose sections write nothing is its source as a comment."""
        text = WordWriter._generate(self, block)  # (a direct call, not a dispatch)
        if self.blank_as_trace and (not text or text.isspace()) and block.sections:
            if block.text is None:
                return ""  # a generated part whose only words the controller does without
            return self.comment(block.text.strip()) + (block.eol or "\n")  # a trace of the source line
        return text

    def _generate(self, block: Block) -> str:
        sections = block.sections
        compound = sections.get("CompoundMotion")
        if compound is not None:
            return self.compound(block, compound)  # type: ignore[arg-type]
        if "TapeMark" in sections:
            return "%" + (block.eol or "\n")
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
                err.section = current  # which section: --on-unsupported warn drops it (postproc.partial_block)
            raise
        start = sections.get("ProgramStart")
        if start is not None:
            words.insert(0, self.program_start(start, block))
        self._track(sections)
        text = " ".join([w for w in words if w])
        if not text and sections and self.BARE_FEED_MOTION_NEEDS_FEED and block.text is not None:
            text = self.comment(block.text.strip())  # every word left out: the source line as a trace
        return text + (block.eol or "\n")

    def around_dwell(self, block: Block, with_dwell: tuple[str, ...]) -> str:
        """A block whose dwell must stand on a line of its own (with ``with_dwell``), written as up to
        three lines in the block's order of events (``postproc.event_order``): what acts before the dwell
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

    def unsupported(self, what: str, block: Block) -> NoReturn:
        raise UnsupportedError(f"the {self.DIALECT} dialect cannot express {what}",
                               self.ctx.at(block))

    # -- compound motion ---------------------------------------------------------------------------
    def compound(self, block: Block, compound: CompoundMotion) -> str:
        """Write an expansion: the block's words that act before its motion (``postproc.event_order``:
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
        if self.base_notes:
            note = _note(f"{compound.term} from line {block.line}: {_source_text(block)}")
        else:
            note = self.comment_line(f"{compound.term} from line {block.line}: {self.source_text(block)}")
        if len(head) == 1 and "Sequence" in head:
            note = " ".join(self.sequence_words(head["Sequence"], block)) + " " + note
        elif head:
            first = Block(block.line, None, "\n")
            first.sections = head
            lines.append(self.generate(first))
        lines.append(note)
        was_incremental = self.modal.distance == "incremental"
        base_moves = self.base_item_moves
        before: dict[str, float | Expr] | None = None
        """The axes of the straight move written last, while the tool stands there: the next straight move
        leaves out the axes it does not change (``_left_out``)."""
        for item in compound.items:
            if isinstance(item, Motion):
                line = _straight_item_line(self, item, before) \
                    if base_moves and self.modal.distance == "absolute" else None
                if line is None:
                    moved = item if before is None else _left_out(item, before)
                    line = WordWriter.item_line(self, moved, block) if base_moves else self.item_line(moved, block)
                before = item.axes if _is_straight(item) else None
                lines.append(line)
            else:
                lines.append(self.item_line(item, block))
                if not isinstance(item, _STANDING):
                    before = None
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
        words: list[str] = []
        if isinstance(item, Motion):
            if self.modal.distance != "absolute":
                words.append(self.code("distance", "absolute", "absolute distance mode", block))
                self.modal.distance = "absolute"
            else:
                line = _straight_item_line(self, item, None)
                if line is not None:
                    return line
            code = self.straight_codes.get(item.mode) if self.straight_items and item.mode is not None else None
            if code is not None and item.center is None and item.radius is None \
                    and _keys_within(item.axes, self.straight_axes):
                # a rapid or feed move of an expansion: the class's ``motion_words`` writes it as the base
                # does (``STRAIGHT_OVERRIDES``), so the base's is called without the override's dispatch
                words.extend(WordWriter.motion_words(self, item, block))
            else:
                words.extend(self.motion_words(item, block))
        else:
            words.extend(self.section_words(item.KEY, item, block))
            self._track({item.KEY: item})
        return " ".join(words) + "\n"

    def source_text(self, block: Block) -> str:
        return _source_text(block)

    # -- section words -----------------------------------------------------------------------------
    def comment(self, text: str) -> str:
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
        if s.mode != "cancel" and not self.capable("TOOL_LENGTH_OFFSET"):
            self.unsupported("a tool length offset from a table", block)
        words = self._code("length", s.mode, f"tool length offset {s.mode}", block)
        if s.register is not None:
            words.append("H" + self.register(s.register, block))
        return words

    def register(self, value: int | Expr, block: Block) -> str:
        """An offset register (D, H): two digits at least, or a computed number."""
        if isinstance(value, Expr):
            return self.expression(value, block)
        return f"{int(value):02d}"

    def path_control_words(self, s: Any, block: Block) -> list[str]:
        if s.one_shot:
            return self._code("path_once", s.mode, "a one-shot exact stop", block)
        return self._code("path", s.mode, f"path control {s.mode}", block)

    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid", "linear"))
    """Motion modes a block in machine coordinates may move in (RS274/NGC: G0 or G1 in force)."""

    def machine_coordinates_words(self, s: Any, block: Block) -> list[str]:
        """Machine coordinates qualify the block's move; without one they do nothing, and RS274/NGC refuses
        them unless G0 or G1 is in force, so they are not written."""
        motion = block.sections.get("Motion")
        if motion is None or not getattr(motion, "axes", None):
            return []  # no move to qualify (``G01 G53``): it does nothing
        if getattr(motion, "mode", None) not in self.MACHINE_MOVES:
            self.unsupported(f"a {motion.mode} move in machine coordinates (its machine-coordinate code "  # type: ignore[attr-defined]
                             f"moves only {' or '.join(sorted(self.MACHINE_MOVES))})", block)
        return self._code("machine", None, "motion in machine coordinates", block)

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        motion = block.sections.get("Motion")
        if self.CYCLE_CANCEL_IS_MOTION and isinstance(motion, Motion) and motion.mode in _MOTION_GROUP:
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

    def seconds(self, value: float) -> str:
        return format_decimal(value, 3, self.leading_zero)

    def left_out(self, s: Motion, block: Block) -> bool:
        """A bare feed motion code the target refuses with no feed rate in force
        (``BARE_FEED_MOTION_NEEDS_FEED``): it only sets the mode, so it is not written. The rate in force
        is the block's own F when it has one (``G01 F0``, which rs274 refuses as ``G1 F0``)."""
        if not (self.BARE_FEED_MOTION_NEEDS_FEED and not s.axes and s.mode in ("linear", "cw", "ccw")):
            return False
        feed = block.sections.get("Feed")
        rate = self.modal.feed if feed is None else feed.value  # type: ignore[attr-defined]
        return isinstance(rate, (int, float)) and rate == 0 or rate is None

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        if s.mode is None:
            self.unsupported("a canned-cycle repetition without its cycle", block)
        if not s.axes and self.left_out(s, block):
            return []
        code = self.motion_codes.get(s.mode)
        if code is None:
            code = self.codes.spell(_MOTION_KIND.get(s.mode, "motion"), s.mode)
            if code is None:
                self.unsupported(f"{s.mode} motion", block)
            self.motion_codes[s.mode] = code
        words = [code]
        start = dict(self.carry) if s.center is not None else None
        incremental = _incremental(self, block)
        as_written = block.canonical and self.source_numbers
        for axis, value in s.axes.items():
            if type(value) is float:
                text = self.source_number(block, axis, value, incremental) if as_written else None
                words.append(axis + (text if text is not None else _position(self, axis, value, incremental)))
            elif isinstance(value, Expr):
                words.append(axis + self.expression(value, block))
                if not incremental:
                    self.carry.pop(axis, None)  # written as the program wrote it
            else:
                words.append(axis + _position(self, axis, value, incremental))
        if s.mode in _MOTION_KIND:
            for axis in s.axes:
                self.carry.pop(axis, None)  # both programs end at the reference point
        if s.center is not None:
            for axis, letter in (("X", "I"), ("Y", "J"), ("Z", "K")):
                if axis in s.center:
                    offset = s.center[axis]
                    exact = offset if isinstance(offset, Expr) else offset + start.get(axis, 0.0)  # type: ignore[union-attr]
                    words.append(letter + self.length(exact, block, letter))  # from the written start to the exact centre
        if s.radius is not None:
            words.append("R" + self.length(s.radius, block, "R"))
        return words

    def source_number(self, block: Block, axis: str, value: float, incremental: bool) -> str | None:
        """The number of a canonical block's ``axis`` word as the source wrote it, when that is the text
        ``position`` writes, else None. It is when the value is the one the word reads as (no step changed
        it; a float compare, cheaper than spelling), nothing is carried on the axis, and the number has no
        more places than this writer writes exactly (``postproc.numbers.as_written``, property-tested in
        ``tests/test_fast_numbers.py``). It saves spelling a number, most of a CAM block's writing."""
        if incremental and axis in self.carry:
            return None
        for letter, text in block.words:
            if letter == axis:
                if not as_written(text, value, self.exact_mm if self.modal.units == "mm" else self.exact_inch) \
                        or float(text) != value:
                    return None
                if self.carry:
                    self.carry.pop(axis, None)  # written exactly: nothing left to carry
                return text
        return None

    def position(self, axis: str, value: float, incremental: bool) -> str:
        """An axis word's number. Rounding never accumulates: in incremental mode the increment written is
        the one that brings the written position nearest the source's (what earlier words rounded away
        is carried), so each written position is within the output resolution of the exact one."""
        return _position(self, axis, value, incremental)

    def _incremental(self, s: Motion, block: Block) -> bool:
        """True when the motion's axis words are increments (machine coordinates are always absolute)."""
        return _incremental(self, block)

    def _rounded_axes(self, block: Block) -> dict[str, bool]:
        """Axis letters of a normalised block's motion whose numbers go through ``position`` (letter ->
        incremental); an expression or a cycle's words keep their text."""
        motion = block.sections.get("Motion")
        if not isinstance(motion, Motion) or motion.mode is None or motion.mode in _MOTION_KIND:
            return {}
        incremental = _incremental(self, block)
        return {a: incremental for a, v in motion.axes.items() if type(v) is float}

    def _exact_axes(self, block: Block) -> None:
        """A block copied with its exact numbers: absolute axis words leave nothing to carry (callers test
        ``self.carry`` first: on the hot path there is usually nothing carried)."""
        if self.carry:
            for axis, incremental in self._rounded_axes(block).items():
                if not incremental:
                    self.carry.pop(axis, None)

    def canned_cycle_words(self, s: Any, block: Block) -> list[str]:
        """A native cycle: its code when the block programs it, then its words as programmed.
        G98/G99 and F come from the block's own ReturnLevel and Feed sections."""
        words: list[str] = []
        if s.call:
            words.extend(self._code("cycle", s.kind, f"the {s.kind.replace('_', ' ')} cycle", block))
        source, target = self.ctx.cycle_words, self.target_cycle_words()
        if source is not None and target is not None and not source.same_letters(target):
            return words + self.cycle_role_words(s, block, source, target)
        for letter, value in s.words.items():
            words.append(letter + (str(value) if isinstance(value, int) else self.length(value, block, letter)))
        return words

    def target_cycle_words(self) -> CycleWords | None:
        """The letters this writer's cycles take (the target dialect's; one whose letters depend on the
        set-up builds them here)."""
        return self.target.CYCLE_WORDS if self.target is not None else None

    def cycle_role_words(self, s: Any, block: Block, source: CycleWords, target: CycleWords,
                         dwell: bool = True) -> list[str]:
        """The words of a cycle read with other letters (Fagor ``Z I K`` <-> Fanuc ``R Z P``), each
        written by its role: the plane's two axes as they are, the reference level, the hole bottom, the
        peck or shift, the dwell (from its seconds, in the target's unit; left out when ``dwell`` is
        False) and the repeat count. Both dialects measure the level from the initial level and the
        bottom from the level under incremental distances, so a word keeps its value."""
        first, second, normal = PLANE_AXES[s.plane]
        out: dict[str, str] = {}
        repeat = source.repeat_letters(self.ctx.setup.input.repeat_address)
        target_repeat = target.repeat_letters(self.ctx.setup.input.repeat_address)
        for letter, value in s.words.items():
            if letter in (first, second):
                out[letter] = self.length(value, block, letter)
            elif letter == source.level:
                out[target.level] = self.length(value, block, target.level)
            elif letter == source.bottom_letter(s.plane, normal):
                bottom = target.bottom_letter(s.plane, normal)
                out[bottom] = self.length(value, block, bottom)
            elif letter == source.dwell:
                if dwell:
                    out[target.dwell] = self.cycle_dwell(s.dwell, target, block)
            elif letter in repeat:
                if target_repeat:
                    out[target_repeat[0]] = str(int(value))
                elif value != 1:
                    self.unsupported(f"a cycle repeat count {letter}{value} (no repeat count in "
                                     f"{self.DIALECT})", block)
            elif letter == source.peck and s.kind in PECK and target.peck:
                out[target.peck] = self.length(value, block, target.peck)
            elif letter == source.shift and s.kind in SHIFT and target.shift:
                out[target.shift] = self.length(value, block, target.shift)
            else:
                self.unsupported(f"the cycle word {letter} (no {self.DIALECT} word has its role)", block)
        order = {c: i for i, c in enumerate(WORD_ORDER)}
        return [letter + text for letter, text in sorted(out.items(), key=lambda kv: order.get(kv[0], 99))]

    def cycle_dwell(self, seconds: float | None, target: CycleWords, block: Block) -> str:
        """A cycle's dwell in the target's unit: whole milliseconds (Fanuc semantics), seconds (RS274)
        or the unit its cycle words name; a time that unit cannot hold exactly is refused."""
        value = seconds or 0.0
        unit = target.dwell_unit
        if unit is None:
            unit = 0.001 if self.target is not None and self.target.CYCLE_SEMANTICS == "fanuc" else 1.0
        count = value / unit
        if unit == 0.001:
            if abs(count - round(count)) > 1e-6:
                self.unsupported(f"a dwell of {value:g} s (whole milliseconds only)", block)
            return str(round(count))
        return self.number(round(count, 9))

    def feed_words(self, s: Any, block: Block) -> list[str]:
        value = s.value
        if isinstance(value, Expr):
            self.modal.feed = None  # known only when the program runs
            return ["F" + self.expression(value, block)]
        self.modal.feed = value
        return ["F" + self.feed_number(value, block)]

    def feed_number(self, value: float, block: Block) -> str:
        """A feed rate's number; one so small that the written number is 0 is refused: the controller
        would read a zero feed rate, which it refuses for every feed move (``block_rules.ZERO_FEED``)."""
        text = self.number(value, "F")
        if value and float(text) == 0.0:
            raise ProgramError(f"feed rate F{value:g} is written F{text} at the output's resolution: a zero feed "
                               "rate, which the controller refuses for a feed move",
                               self.ctx.at(block, self.ctx.column_of(block, "F")))
        return text

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

    def speed(self, rpm: float) -> str:
        """A spindle speed: a whole number without a point, else a decimal; ``S0`` places round it to a
        whole number."""
        if self.rounding:
            text = self.number(float(rpm), "S")
            if text.endswith("."):
                return text[:-1] or "0"
            return text
        return str(int(rpm)) if float(rpm).is_integer() else self.number(rpm)

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

    def data_setting_words(self, s: Any, block: Block) -> list[str]:
        """A G10 data setting: as written for a controller of its family; else, where exact, the target's
        absolute work offset setting; anything else has no equivalent here."""
        family = self.target.family() if self.target is not None else self.DIALECT
        if s.family == family:
            return [s.text]
        why = ""
        if s.table != "work_offset" or not self.WORK_OFFSET_SETTING:
            why = "no such table can be set from a program"
        elif s.incremental:
            why = "it sets offsets absolutely only (the source adds to the offset in incremental mode)"
        elif self.SETTING_ADDS_IN_INCREMENTAL and self.modal.distance == "incremental":
            why = "in incremental mode its setting adds to the offset (program absolute mode first)"
        elif not 1 <= s.index <= self.WORK_OFFSET_COUNT:
            why = (f"its work systems are P1-P{self.WORK_OFFSET_COUNT}" if s.index else
                   "P0 here is not the offset common to all work systems")
        elif not set(s.values) <= self.SETTING_AXES:
            why = f"it sets axes {''.join(sorted(self.SETTING_AXES))} only"
        if why:
            self.unsupported(f"{s.describe()}: {why}", block)
        return [*self.WORK_OFFSET_SETTING.split(), f"P{s.index}",
                *(axis + self.length(value, block, axis) for axis, value in s.values.items())]

    def machine_function_words(self, s: Any, block: Block) -> list[str]:
        """A machine-specific code as written, for a controller of its family; elsewhere it has no
        equivalent (``postproc.machine_functions`` comments it out under ``--on-unsupported warn``)."""
        family = self.target.family() if self.target is not None else self.DIALECT
        if s.family != family and s.action == RIGID_TAP:
            raise UnsupportedError(refused_rigid_tap(s, self.DIALECT), self.ctx.at(block))
        if s.family != family:
            raise UnsupportedError(f"{s.describe()}, a machine-specific code of the {s.family} family, has no "
                                   f"equivalent in {self.DIALECT}", self.ctx.at(block))
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


_ROUNDED_UNITS: Final = {"S": "rpm", "A": "deg", "B": "deg", "C": "deg", "F": ""}
"""Units a rounding warning names where they are not the program's length unit ('' for F: the length
unit per minute or revolution)."""
_STANDING: Final = (Feed, Dwell)
"""Items of an expansion the tool stands still for, between two moves (``compound``)."""
_MOTION_KIND: Final = {"home": "home", "home2": "home"}
_MOTION_GROUP: Final = frozenset({"rapid", "linear", "cw", "ccw"})
"""Motion modes written with a code of the motion group (G0-G3)."""
"""Motion modes the table spells under another kind than "motion" (reference returns)."""
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


def _position(w: WordWriter, axis: str, value: float, incremental: bool) -> str:
    """``WordWriter.position``: a module function, so that a plugin's (interpreted) writer does not
    dispatch through Python for each number (no subclass overrides it)."""
    carry = w.carry
    want = value + carry.get(axis, 0.0) if incremental and carry else value
    if not w.rounding:
        text = (w.mm_texts if w.modal.units == "mm" else w.inch_texts).text(want)
        if text is not None:  # written exactly: nothing to carry
            if carry:
                carry.pop(axis, None)
            return text
    text = w.number(want, axis)
    error = want - float(text)
    if error:
        carry[axis] = error
    elif carry:
        carry.pop(axis, None)
    return text


def _straight_item_line(w: WordWriter, item: Motion, before: dict[str, float | Expr] | None) -> str | None:
    """An expansion's rapid or feed move as ``motion_words`` spells it, when it is a straight move of the
    writer's (``straight_codes``) and every axis is a number of a driven axis (else None, and nothing
    written that a second spelling would not write the same). The distance mode is absolute here (the
    caller checks): each number is the position's (``_position``, which leaves to carry what depends on
    the value only), which is the text ``source_number`` would copy from a canonical source block
    (``as_written``). An axis whose number is the one of ``before`` (the move written just before, the
    tool still there) is left out: absolute, it would write the same text to the same place. The line
    is built in one piece (a string per axis and a join cost more than the numbers' look-ups)."""
    mode = item.mode
    if not w.straight_items or mode is None or item.center is not None or item.radius is not None:
        return None
    code = w.straight_codes.get(mode)  # rapid or linear
    axes = item.axes
    if code is None or not axes:
        return None
    driven = w.straight_axes
    count = 0  # up to three words in locals (a list and its appends cost more than the numbers' look-ups)
    first = second = third = ""
    for axis, value in axes.items():
        if type(value) is not float or axis not in driven:
            return None
        if before is not None:
            was = before.get(axis)
            if type(was) is float and was == value:
                continue
        word = axis + _position(w, axis, value, False)
        if count == 0:
            first = word
        elif count == 1:
            second = word
        elif count == 2:
            third = word
        else:
            return None  # more than three axes: ``motion_words`` spells them
        count += 1
    if count == 1:
        return f"{code} {first}\n"
    if count == 3:
        return f"{code} {first} {second} {third}\n"
    if count == 2:
        return f"{code} {first} {second}\n"
    return code + "\n"


def _note(text: str) -> str:
    """``comment_line`` of the base: a comment on a line of its own."""
    return "(" + text.replace("(", "[").replace(")", "]") + ")\n"


def _source_text(block: Block) -> str:
    """``source_text`` of the base: the block as read, on one line."""
    if block.text is not None:
        return one_line(block.text).strip()
    return " ".join(letter + num for letter, num in block.words)


def _is_straight(item: Motion) -> bool:
    return (item.mode == "rapid" or item.mode == "linear") and item.center is None and item.radius is None


def _left_out(item: Motion, before: dict[str, float | Expr]) -> Motion:
    """A straight move of an expansion without the axes whose number is the one the tool stands at
    (``before``: the move written just before it); written absolute, those words would not move it.
    ``_straight_item_line`` leaves out the same axes."""
    if not _is_straight(item):
        return item
    axes: dict[str, float | Expr] = {}
    for axis, value in item.axes.items():
        was = before.get(axis)
        if not (type(value) is float and type(was) is float and was == value):
            axes[axis] = value
    return item if len(axes) == len(item.axes) else Motion(item.mode, axes)


def _incremental(w: WordWriter, block: Block) -> bool:
    """``WordWriter._incremental``: True when a motion's axis words are increments (machine coordinates
    are always absolute)."""
    return w.modal.distance == "incremental" and "MachineCoordinates" not in block.sections


def _keys_within(mapping: dict[str, Any], keys: frozenset[str]) -> bool:
    """``keys.issuperset(mapping)`` as a compiled loop over the mapping's few keys (the set method is a
    bound-method call that builds an iterator; an expansion asks it once per move)."""
    for key in mapping:
        if key not in keys:
            return False
    return True
