"""The straight lane: a CAM program's usual block, ``N.. G1 X.. Y.. Z.. F..``, written without the word
writer's section dispatch.

A speed-only copy of what ``WordWriter.write_block`` writes for such a block, kept apart from the classes
dialects extend (STYLE.md 11). ``postproc.fast.lane`` installs it for a run only where the writer class
writes such a block with the base's own methods, and ``tests/test_straight_moves.py`` holds it to the
general path on random programs. It answers None for any block it is not sure of; the general path then
writes it.
"""

from __future__ import annotations

from typing import Final, cast

from mypy_extensions import i64, mypyc_attr

from ..ir.expr import Expr
from ..ir import Block, Feed, Motion, Section, Sequence
from ..ir.block import MARK_BITS, MARK_MASK
from ..numbers import MAX_PLACES, SHORT_RANGE, as_written, canonical_number
from ..output.line_feeds import Batch
from ..output.writer_base import Lane
from ..rs274.canonical_line import LineNumbers, line_numbers
from ..rs274.motion_words import tiny_arc
from ..rs274.writer import WordWriter
from ..ir.state import PLANE_AXES

LANE_MODES: Final = frozenset(("rapid", "linear", "cw", "ccw"))
"""The motion modes the straight lane writes."""
STRAIGHT_KEYS: Final = frozenset(("Sequence", "Motion", "Feed"))
"""A block of only these sections (a move, its block number and feed rate) is a straight block."""
_CENTER_LETTER: Final = {"X": "I", "Y": "J", "Z": "K"}


def straight_keys(sections: dict[str, Section]) -> int:
    """1 where a block's keys are among ``STRAIGHT_KEYS`` with a feed rate, 0 without, -1 where it has another.
    The block number and the move are looked up, the feed rate only where the count leaves room for it: a CAM
    block's ``N.. X.. Y..`` is two look-ups (~115 instructions each compiled), where the three names cost three,
    and a pass over the keys compared with them ~380 (``dict`` iteration, callgrind)."""
    size = len(sections)
    known = ("Sequence" in sections) + ("Motion" in sections)
    if size == known:
        return 0
    if size == known + 1 and "Feed" in sections:
        return 1
    return -1


def _copied(text: str, start: i64, end: i64, value: object, read: object, most: int, every: bool) -> bool:
    """Whether a canonical word's number (``text[start:end]``, which reads as ``read``) is how a writer exact to
    ``most`` places writes ``value`` (``every``: ``most`` covers every canonical number)."""
    if type(value) is not float:
        return False
    return read == value and (-SHORT_RANGE < value < SHORT_RANGE if every else as_written(text[start:end], value,
                                                                                            most))


def _word_end(text: str, at: i64, size: i64, marks: i64) -> i64:
    """Where the word of a canonical line that starts at ``at`` ends: the next space, or the line's end; -1 where
    no word starts there (the line has ended). ``marks``: where the line's letters stand (``Block.marks``; 0: not
    known), so the word ends a character before the next letter (its words are joined by single spaces), read
    with no character of the line looked at: the loop over them cost ~125 instructions a word compiled (~630 a
    CAM block, callgrind), where ``str.find`` cost ~200."""
    if at >= size:
        return -1
    if marks:
        count = marks & MARK_MASK
        rest = marks >> MARK_BITS
        while count > 0:
            place = rest & MARK_MASK
            if place > at:
                return place - 1
            rest = rest >> MARK_BITS
            count -= 1
        return size
    end = at + 1
    while end < size and ord(text[end]) != 32:
        end += 1
    return end


_MOST_DIGITS: Final = 18
"""The most digits of a block number the lane reads (an ``i64``'s; a longer one is the general path's)."""
_TENS: Final[list[int]] = [10 ** k for k in range(_MOST_DIGITS)]
"""``_TENS[k]``: the least number of ``k + 1`` digits with no leading zero (0 has one digit)."""


def _digits(text: str, start: i64, end: i64) -> i64:
    """The whole number ``text[start:end]`` spells with digits only (no sign, at most ``_MOST_DIGITS`` of them), or
    -1 (none, another character, more digits): a block number's, read from the line itself."""
    if start >= end or end - start > _MOST_DIGITS:
        return -1
    value: i64 = 0
    while start < end:
        code = ord(text[start])
        if code < 48 or code > 57:
            return -1
        value = value * 10 + (code - 48)
        start += 1
    return value


def _reads_as(value: float, letter: str, values: dict[str, float | int | Expr], held: LineNumbers | None,
              index: i64) -> bool:
    """Whether a word of a block's line (its ``letter``, the ``index``-th word of the line) reads as ``value``: the
    reader's value of it, from the run's ``LineNumbers`` where they hold the line (``held``: an unboxed number by
    the word's place), else from the block's ``values`` (a look-up by letter, ~130 instructions compiled)."""
    if held is not None:
        return held.value(index) == value
    read = values.get(letter)  # (Both floats: compiled, compared unboxed, where ``is`` boxed ``value`` anew and the
    return type(read) is float and read == value  # objects were compared: ~190 instructions a word.)


def _whole(text: str, start: i64, end: i64) -> bool:
    """Whether ``text[start:end]`` is a whole number without a point (``-`` and digits): how a program writes a
    number that counts least input increments (``Y42829``), which the general path spells from its value."""
    if start < end and ord(text[start]) == 45:  # '-'
        start += 1
    if start >= end:
        return False
    while start < end:
        code = ord(text[start])
        if code < 48 or code > 57:
            return False
        start += 1
    return True


def _spelt(text: str, start: i64, end: i64, canonical: bool) -> bool:
    """Whether a word's number (``text[start:end]``) is in the writer's spelling where its block is not canonical
    (``canonical``: the reader said every word is): explicit point, leading zero, no trailing zero."""
    return canonical or canonical_number(text[start:end], MAX_PLACES, True)


def _plain_arc(axes: dict[str, float | Expr], center: dict[str, float | Expr] | None, plane: str) -> bool:
    """An arc the lane writes: its centre is not its start (the general path refuses a zero-radius arc
    where the controller does) and its end point names an axis of its plane (a full circle in the plane,
    or a helix with no end point in it, is left to the general path and the writers' checks). Its centre's
    words are matched in its order, which the block syntax builds as the general path writes them: I, J, K."""
    if center is not None:
        zero = True
        for offset in center.values():
            if type(offset) is not float or offset != 0.0:
                zero = False
        if zero:
            return False
    first, second, _ = PLANE_AXES[plane]
    return first in axes or second in axes


@mypyc_attr(allow_interpreted_subclasses=True)
class CopyLane(Lane):
    """A straight block normalised back to its own dialect is its source line, as ``normalized`` writes
    a canonical block (installed where the writer copies canonical numbers: leading zeros, no rounding,
    no renumbering)."""

    def __init__(self, writer: WordWriter) -> None:
        super().__init__()
        self.writer = writer
        self.per_rev_checked = bool(writer.PER_REV_NEEDS_SPEED)
        """The general path checks the spindle speed of a move in feed per revolution: such a move is left
        to it (read once: a class attribute of an interpreted class is a look-up by name)."""

    def write(self, block: Block) -> str | None:
        """The block's source line, or None."""
        sections = block.sections
        text = block.text
        if text is None or not block.canonical:
            return None
        fed = straight_keys(sections)  # (of the straight keys only the feed rate is modal)
        if fed < 0:
            return None
        writer = self.writer
        if self.per_rev_checked and writer.modal.feed_mode == "per_rev":
            return None
        if fed:
            writer.modal.apply(sections)
        if writer.carry:
            writer.exact_axes(block)
        return text + (block.eol or "\n")


@mypyc_attr(allow_interpreted_subclasses=True)
class SourceLane(Lane):
    """A straight block copied to its own dialect, not normalised, is its source line and end of line, as
    ``words_block`` copies a block (installed where the writer copies its dialect's blocks: ``copy_ok``),
    canonical or not (its words are not read). It puts them into the output itself (``put``), as two pieces."""

    def __init__(self, writer: WordWriter) -> None:
        super().__init__()
        self.writer = writer
        self.per_rev_checked = bool(writer.PER_REV_NEEDS_SPEED)
        """As ``CopyLane.per_rev_checked``."""
        self.points = bool(writer.rounding or writer.whole_speed)
        """``words_block`` keeps the block a rounding warning points at."""
        self.puts = True

    def write(self, block: Block) -> str | None:
        """The block's source line, or None."""
        text = self.copied(block)
        return None if text is None else text + block.eol

    def put(self, block: Block, out: Batch, below: int) -> bool:
        """``write``'s answer as its two pieces, the source line and its end of line (``Batch.write_line``); a
        blank line is left to the writer (False), which checks it, as is a text ``below`` or longer (where not 0)."""
        text = block.text
        if text is None or not block.canonical and (not text or text.isspace()):  # (a canonical line has a word)
            return False
        eol = block.eol
        if below and len(text) + len(eol) >= below or self.copied(block) is None:
            return False
        out.write_line(text, eol)
        return True

    def copied(self, block: Block) -> str | None:
        """The source line of a straight block, the writer's state brought past it as ``words_block`` brings it
        (the feed rate, the block a warning points at); None: not a straight block (nothing changed)."""
        sections = block.sections
        text = block.text
        if text is None:
            return None
        fed = straight_keys(sections)
        if fed < 0:
            return None
        writer = self.writer
        if self.per_rev_checked and writer.modal.feed_mode == "per_rev":
            return None
        if self.points:
            writer.at_block = block
        if fed:
            writer.modal.apply(sections)
        return text


@mypyc_attr(allow_interpreted_subclasses=True)
class StraightLane(Lane):
    """A block of another dialect that is a rapid, feed or arc move of numbers, maybe with a block number and
    a feed rate, its words in that order, each number the value it reads as and one the writer writes as
    written (``WordWriter.source_number``), with nothing carried: its source line with the writer's motion
    code after its block number. In a block that is not canonical, a number must be in the writer's spelling,
    or be an axis word's whole number (no point), which is spelt from its value as ``_position`` spells it. Of
    the modal state such a block changes only the feed rate (``ModalState.apply``)."""

    def __init__(self, writer: WordWriter) -> None:
        super().__init__()
        self.writer = writer
        codes = writer.codes
        spelled: dict[str, tuple[str, str]] = {}
        for mode in LANE_MODES:
            code = codes.spell("motion", mode)
            if code is not None:
                spelled[mode] = (code, f" {code} ")
        self.rapid = spelled.get("rapid")
        """The rapid move's code, spelled once, and the code between spaces (as it goes after a block number);
        None: the table has none. Likewise the feed and arc moves': four fields, not a dictionary (compared
        with the mode, not looked up: ~100 instructions a block)."""
        self.linear = spelled.get("linear")
        self.cw = spelled.get("cw")
        self.ccw = spelled.get("ccw")
        self.driven: frozenset[str] | None = writer.DRIVEN_AXES
        """The axes the target drives (None: any the source programs, as ``motion_words`` writes them): a
        move of another is left to the general path, which refuses it."""
        self.drives_xyz = self.driven is not None and {"X", "Y", "Z"} <= self.driven
        """The target drives X, Y and Z: a word of one of them needs no look in ``driven`` (three string
        comparisons, where a look in a set cost ~75 instructions a word compiled: grbl, grblHAL)."""
        self.per_rev_checked = bool(writer.PER_REV_NEEDS_SPEED)
        """As ``CopyLane.per_rev_checked``."""
        self.max_number = writer.MAX_BLOCK_NUMBER
        """A block number above it (when not 0) is the general path's to drop (``sequence_words``)."""
        self.puts = True
        self.numbers: LineNumbers = line_numbers(writer.ctx.run_data)
        """The run's numbers of the line its reader's scan left unmade last (``canonical_line.LineNumbers``, the one
        the reader fills): where they are still the block's line's (compared by identity: no step read ahead), a
        word's value is read from them by its place instead of looked up in ``Block.values`` (~130 instructions a
        word compiled). Both are the reader's reading of the word's text, the one it holds and the general path
        writes from (``source_number``)."""
        self.expansions: Lane | None = None
        """The lane of a block whose motion is an expansion (``postproc.fast.expansion_moves.ExpansionBlocks``,
        installed with the expansion-move lane where it applies): a block of no ``Motion`` is offered to it."""

    def write(self, block: Block) -> str | None:
        """The block's text, or None."""
        return self._written(block, None, 0)

    def put(self, block: Block, out: Batch, below: int) -> bool:
        """``write``'s answer for a move as its two pieces, its line and its end of line (``Batch.write_line``: no
        string joined for the block, ~270 instructions compiled); a text ``below`` or longer (where not 0) is left
        to ``write`` (the line rule looks at it), as is a block of no ``Motion`` (an expansion's)."""
        return self._written(block, out, below) is not None

    def _written(self, block: Block, out: Batch | None, below: int) -> str | None:
        """``write``'s text (``out`` None), or the line without its end put into ``out`` where the text is shorter
        than ``below`` (0: any length); None: nothing written, nothing changed."""
        writer = self.writer
        sections = block.sections
        found = cast("dict[str, object]", sections)
        """The sections as objects: compiled, a look-up typed ``Section`` checked its answer against the base class,
        a call of ``PyType_IsSubtype`` for each of the three (an ``isinstance`` of the section's own class below
        is a compare of types)."""
        text = block.text
        motion = found.get("Motion")
        if motion is None:
            expansions = self.expansions
            if expansions is None or out is not None:
                return None
            self.plain = False  # (its lines go to the line rule: ``Lane.plain``)
            return expansions.write(block)
        self.plain = True
        if not isinstance(motion, Motion) or text is None or writer.carry or not writer.source_numbers:
            return None
        # A block that is not canonical (a number without a point, ``Y42829``) is read the same way, its words where
        # they stand; each number it copies is checked for the writer's spelling (``_spelt``), and an axis word's
        # whole number is spelt from its value as the general path spells it (``_position``: nothing carried, no
        # rounding, the writer's table of exact texts). ~3.5% of the blocks of the CAM benchmark program, which the
        # general path wrote at ~14 times the lane's cost (perf: 7.5% of a translation to LinuxCNC).
        canonical = block.canonical
        if self.per_rev_checked and writer.modal.feed_mode == "per_rev":
            return None
        mode = motion.mode
        axes = motion.axes
        if mode is None or not axes:
            return None
        center = motion.center
        radius = motion.radius
        arc = 0
        if mode == "linear" or mode == "rapid":
            if center is not None or radius is not None:
                return None
            spelled = self.linear if mode == "linear" else self.rapid
        elif mode == "cw" or mode == "ccw":
            if center is None and radius is None or not _plain_arc(axes, center, writer.modal.plane) \
                    or center is not None and tiny_arc(center, writer.MIN_ARC_RADIUS[writer.modal.units == "inch"]):
                return None
            arc = len(center) if center is not None else 1
            spelled = self.cw if mode == "cw" else self.ccw
        else:
            return None
        if spelled is None:
            return None
        code, spaced = spelled
        # The Motion and at most a block number and a feed rate: no look-up for what the count rules out.
        count = len(sections)
        sequence = feed = None
        if count > 1:
            sequence = found.get("Sequence")
            if sequence is None or count > 2:
                feed = found.get("Feed")
        besides = (sequence is not None) + (feed is not None)
        # The words are read where they stand in the line: a canonical block's text is its words joined by single
        # spaces (``Block.canonical``), so a block whose words the reader left unmade (``Block.marks``) is written
        # without making them. ``at``: where the next word's letter stands; ``ends``: where that word ends.
        size: i64 = len(text)
        at: i64 = 0
        head: i64 = 0
        marks: i64 = 0  # where the words' letters stand in a canonical line whose words the reader left unmade, its
        if canonical and block.spelled() is text:  # text unchanged since (``Block.marks``): each word's end is read
            marks = block.marks  # from them (``_word_end``)
        values = block.values  # what the words read as (a reader's, untouched since: ``Block.values``)
        numbers = self.numbers
        held = numbers if marks and numbers.text is text else None  # (the reader's numbers of this very line)
        index: i64 = 0  # the place in the line of the word at ``at``
        if sequence is not None:
            if not isinstance(sequence, Sequence):
                return None
            end = _word_end(text, 0, size, marks)
            number = sequence.number
            if end < 2 or end > _MOST_DIGITS + 1 or number < 0 or end > 2 and number < _TENS[end - 2] \
                    or self.max_number and number > self.max_number:
                return None  # (N010 is written N10; a number the target refuses is dropped by the general path)
            read_number: int = -1
            if held is not None:
                read_number = held.sequence  # (the first word's number where that word is an N of digits, else -1)
            elif text[0] == "N":
                read_number = _digits(text, 1, end)
            if read_number != number:
                return None
            # (``N`` and the line's digits are what ``sequence_words`` writes of the number, told from the reader's
            # numbers where they hold the line, else from the digits; a number of fewer digits than the word has a
            # leading zero: a look-up of the reader's value in ``values`` cost ~130 instructions compiled. Each
            # choice in one type: a conditional expression of an ``int`` and an ``i64`` boxed both.)
            at = end + 1
            head = end
            index = 1
        coded = at < size and text[at] == "G"  # the block's own motion code: it is rewritten
        if count != 1 + besides:
            return None
        written: i64 = 0
        if coded:
            end = _word_end(text, at, size, marks)
            written = end - at
            at = end + 1
            index += 1
        most = writer.exact_mm if writer.modal.units == "mm" else writer.exact_inch
        every = most >= MAX_PLACES  # every canonical number has at most MAX_PLACES: as_written is the range
        driven = self.driven
        xyz = self.drives_xyz
        pieces: list[str] | None = None  # (a block that is not canonical: the line rebuilt, its whole numbers spelt)
        copied: i64 = 0  # where the text not yet in ``pieces`` starts
        for axis, value in axes.items():
            end = _word_end(text, at, size, marks)
            if end < 0:
                return None
            letter = text[at]
            if letter != axis or driven is not None and not (xyz and 88 <= ord(letter) <= 90) \
                    and letter not in driven or type(value) is not float:  # (88-90: X, Y, Z; one code, not three tests)
                return None
            reading: float = value  # (unboxed once: compiled, each use of ``value`` as a float unboxed it again)
            if not canonical and not canonical_number(text[at + 1:end], MAX_PLACES, True):
                if not _whole(text, at + 1, end):
                    return None
                spelt = (writer.mm_texts if writer.modal.units == "mm" else writer.inch_texts).text(reading)
                if spelt is None:
                    return None  # (rounded: the general path carries what rounding left)
                if pieces is None:
                    pieces = []
                pieces.append(text[copied:at + 1])
                pieces.append(spelt)
                copied = end
                at = end + 1
                index += 1
                continue
            if not (-SHORT_RANGE < reading < SHORT_RANGE if every else as_written(text[at + 1:end], reading, most)):
                return None
            if not _reads_as(reading, letter, values, held, index):
                return None  # (the number the word reads as: no step changed it)
            at = end + 1
            index += 1
        if arc:
            if center is not None:
                for axis, value in center.items():
                    end = _word_end(text, at, size, marks)
                    if end < 0:
                        return None
                    letter = text[at]
                    if letter != _CENTER_LETTER[axis] or not _copied(text, at + 1, end, value, values.get(letter),
                                                                     most, every) \
                            or not _spelt(text, at + 1, end, canonical):
                        return None
                    at = end + 1
                    index += 1
            else:
                end = _word_end(text, at, size, marks)
                if end < 0:
                    return None
                letter = text[at]
                if letter != "R" or not _copied(text, at + 1, end, radius, values.get(letter), most, every) \
                        or not _spelt(text, at + 1, end, canonical):
                    return None
                at = end + 1
                index += 1
        rate = 0.0
        if feed is not None:
            if not isinstance(feed, Feed):
                return None
            end = _word_end(text, at, size, marks)
            fed = feed.value
            if end < 0 or text[at] != "F" or type(fed) is not float or not _spelt(text, at + 1, end, canonical):
                return None
            rate = fed
            if not (-SHORT_RANGE < rate < SHORT_RANGE if every else as_written(text[at + 1:end], rate, most)):
                return None
            if not _reads_as(rate, "F", values, held, index):
                return None
            at = end + 1
        if at != size + 1:
            return None  # a word the sections do not account for (every word read: the line's end is passed)
        if pieces is not None:  # (the block number and motion code stand before the first number: ``head`` holds)
            pieces.append(text[copied:])
            text = "".join(pieces)
        eol = block.eol or "\n"
        start = head + 1 if head else 0
        if out is None:  # (the end of line in the one string made)
            if coded:
                line = f"{text[:start]}{code}{text[start + written:]}{eol}"
            elif head:  # the first space of a canonical block is the one after its block number
                line = text.replace(" ", spaced, 1) + eol  # (one copy: two slices and a join cost ~450 more)
            else:
                line = f"{code} {text}{eol}"
        else:
            if coded:
                line = f"{text[:start]}{code}{text[start + written:]}"
            elif head:
                line = text.replace(" ", spaced, 1)  # (one copy: two slices cost more, ~175 instructions each)
            else:
                line = f"{code} {text}"
            if below and len(line) + len(eol) >= below:
                return None
        if feed is not None:
            writer.modal.feed = rate
        if writer.after_blocks:
            writer.after_block(block)  # as ``generate`` (after the block's words: none fails from here)
        if out is not None:
            out.write_line(line, eol)
        return line
