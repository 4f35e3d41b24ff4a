"""The plain-block lane: a CAM program's usual block, ``N.. G1 X.. Y.. F..``, read in one pass.

A speed-only copy of what ``WordBlockSyntax.build`` reads from such a block (``g_sections``,
``finish_words``), kept apart from the classes dialects extend (STYLE.md 11). ``postproc.fast.reading``
installs it for a run only where the block syntax class reads such a block with the family base's own
methods, and ``tests/test_plain_blocks.py`` holds it to the general path on random programs. It answers
False, leaving the block as it found it, at the first word it does not handle (another code, a repeated
address, a number that is neither decimal nor plain digits) or for a block the general path refuses, so
that path reads the block and reports its errors.

A point-less axis or arc number (``X12500``: least input increments, the decimal-point rule) is read here
too, as the general path reads it (``WordBlockSyntax.build``'s divisor, and the point-mix check told in word
order): CAM posts write one now and then, and the general path cost such a block some 27,000 instructions
where the lane takes 5,000 (callgrind, the benchmark's 1 block in 27).
"""

from __future__ import annotations

from typing import Final, cast

from mypy_extensions import i64, mypyc_attr

from ..context import BlockLane, Context
from ..ir.expr import Expr
from ..ir import Block, Feed, Motion
from ..ir.block import MARK_BITS, MARK_MASK
from ..numbers import decimal_value
from ..rs274.block_syntax import AXIS_LETTERS, CENTER_AXIS, WordBlockSyntax
from ..rs274.canonical_line import LineNumbers, scan_marks
from ..rs274.lathe_block_syntax import ONE_AXIS_WORDS, SINGLE_KEY
from ..rs274.point_mix import point_mix
from ..rs274.word_values import increments_divisor

_UPPER: Final = {c: c.upper() for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"}
_UPPER[":"] = "O"  # ':' is ISO's spelling of the program number address (as ``WordBlockSyntax`` reads it)
LETTER_AXIS: Final = 1
LETTER_N: Final = 2
LETTER_F: Final = 3
LETTER_G: Final = 4
LETTER_ARC: Final = 5
LETTER_KIND: Final = bytes(LETTER_AXIS if c in AXIS_LETTERS else LETTER_N if c == "N" else LETTER_F if c == "F"
                           else LETTER_G if c == "G" else LETTER_ARC if c in "IJKR" else 0
                           for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZ")
"""What a plain-block lane does with each letter A-Z (by ``ord(letter) - 65``): one byte read instead of set
tests (both lanes: this one and ``plain_ngc.NgcPlainLane``)."""
_LETTER_KEYS: Final[list[str]] = [chr(65 + i) for i in range(26)]
"""The upper-case letters by ``ord(letter) - 65`` (compiled: a list item, not a one-character slice of a line)."""
MOTION_MODES: Final = frozenset(("rapid", "linear", "cw", "ccw"))
"""The motion modes a plain block may move in."""
_MOTION_KEYS: Final = {"0": "0", "00": "0", "1": "1", "01": "1", "2": "2", "02": "2", "3": "3", "03": "3"}
"""The spellings of G0-G3 the lane reads (their ``g_key``); the table says what each means."""


@mypyc_attr(allow_interpreted_subclasses=True)
class PlainLane(BlockLane):
    """N, maybe one motion code (G0-G3), axis words with decimal points, an arc's centre I/J/K or radius R,
    maybe F; under an active cycle, N and axis words only (the next hole of a row: ``Motion(None)``, the
    cycle resolve step reads the words)."""

    __slots__ = ("syntax", "in_units", "numbers")

    def __init__(self, syntax: WordBlockSyntax, numbers: LineNumbers | None = None) -> None:
        self.syntax = syntax
        """The run's block syntax, whose code table says what G0-G3 mean."""
        self.in_units = syntax.POINTLESS_IN_UNITS
        """A point-less number is in program units (the dialect's declaration, read once)."""
        self.numbers = numbers if numbers is not None else LineNumbers()
        """The run's numbers of the line the reader's scan left unmade last (``canonical_line.line_numbers``:
        the reader's and this lane's), which ``read_marked`` reads a block's numbers from."""

    def read(self, block: Block, ctx: Context, words: list[tuple[str, str]]) -> bool:
        # The words' values are gathered apart (the axes in the motion's dictionary, the rest in locals) and
        # the block's ``values`` made from them once the lane is sure of the block: a copy of the axes'
        # dictionary (compiled, one C call cloning its table) and the few other words, instead of a second
        # insertion per axis word; a block the lane leaves is left untouched.
        axes: dict[str, float | Expr] = {}
        others: dict[str, float | Expr] | None = None  # I/J/K/R and F, where the block has them (few do)
        sequence_value: object = None  # N's value
        mode: str | None = None
        arc_words = False
        upper = block.canonical  # a canonical block's letters are upper-case already (numbers.CANONICAL_BLOCK)
        seen = 0  # the addresses met, one bit per letter (a repeated one leaves the lane)
        bare: dict[str, str] | None = None  # the point-less axis words, by letter (few blocks have one)
        cycle = ctx.state.cycle is not None
        for letter, num in words:
            up = letter if upper else _UPPER[letter]
            index = ord(up) - 65
            if index < 0 or index > 25:
                break
            bit = 1 << index
            if seen & bit:
                break
            seen |= bit
            kind = LETTER_KIND[index]
            if kind == LETTER_AXIS:
                if upper or "." in num:  # canonical: an axis number has its point
                    axes[up] = decimal_value(num)
                else:
                    value = self.pointless(ctx, num)
                    if value is None:
                        break
                    axes[up] = value
                    if bare is None:
                        bare = {}
                    bare[up] = num
            elif kind == LETTER_N and (upper or "." not in num):  # (a canonical N is digits only)
                sequence_value = whole_number(num)
            elif cycle:
                break  # a code, F or a cycle word under an active cycle: the general path
            elif kind == LETTER_F:
                if others is None:
                    others = {}
                others["F"] = decimal_value(num)
            elif kind == LETTER_G and mode is None:
                key = _MOTION_KEYS.get(num)
                entry = self.syntax.table(ctx).g.get(key) if key is not None else None
                if entry is None or entry[1] != "motion" or entry[2] not in MOTION_MODES:
                    break
                mode = str(entry[2])
            elif kind == LETTER_ARC:
                arc = decimal_value(num) if upper or "." in num else self.pointless(ctx, num)
                if arc is None:
                    break
                if others is None:
                    others = {}
                others[up] = arc
                arc_words = True
            else:
                break
        else:
            return self._finish(block, ctx, axes, others, sequence_value, mode, arc_words, bare, cycle)
        return False

    def read_marked(self, block: Block, ctx: Context) -> bool:
        # ``read`` of a canonical line whose words the reader left unmade (``Block.marks``): the same reading,
        # each word read where it stands in the line (no word objects made) and each number as the reader's scan
        # read it (``LineNumbers``: an axis-type word's value, the block number), not a second time. A line that
        # is not the one whose numbers the run holds (a step between the reader and this one read ahead) is
        # scanned again, as the reader scanned it. A G word's number is taken out (a look-up in the code table).
        # Compiled: positions, the letter's index and the addresses met are machine integers; a value is boxed
        # once, as it is stored, under the letter's cached string (``_LETTER_KEYS``, not a one-character slice of
        # the line).
        text = block.spelled()
        numbers = self.numbers
        if numbers.text is not text:
            scan_marks(text, b"", 0, numbers)
            if numbers.text is not text:
                return False  # (never: the line was left unmade by the same scan)
        marks = block.marks
        count = marks & MARK_MASK
        rest = marks >> MARK_BITS
        size: i64 = len(text)
        axes: dict[str, float | Expr] = {}
        others: dict[str, float | Expr] | None = None
        sequence_value: object = None
        mode: str | None = None
        arc_words = False
        seen: i64 = 0
        letters = _LETTER_KEYS
        cycle = ctx.state.cycle is not None
        i: i64 = 0
        at: i64 = rest & MARK_MASK
        while i < count:
            rest = rest >> MARK_BITS
            following: i64 = rest & MARK_MASK if i + 1 < count else size + 1  # the next letter's place
            index: i64 = ord(text[at]) - 65
            if index < 0 or index > 25:
                break
            bit: i64 = 1 << index
            if seen & bit:
                break
            seen |= bit
            kind = LETTER_KIND[index]
            if kind == LETTER_N:
                if i != 0:
                    break  # (the scan reads the first word's block number: another N is the general path's)
                sequence_value = numbers.sequence
            elif kind == LETTER_AXIS:
                axes[letters[index]] = numbers.value(i)  # (a canonical axis number has its point: a value)
            elif cycle:
                break  # a code, F or a cycle word under an active cycle: the general path
            elif kind == LETTER_F or kind == LETTER_ARC:
                if others is None:
                    others = {}
                others[letters[index]] = numbers.value(i)
                if kind == LETTER_ARC:
                    arc_words = True
            elif kind == LETTER_G and mode is None:
                key = _MOTION_KEYS.get(text[at + 1:following - 1])
                entry = self.syntax.table(ctx).g.get(key) if key is not None else None
                if entry is None or entry[1] != "motion" or entry[2] not in MOTION_MODES:
                    break
                mode = str(entry[2])
            else:
                break
            at = following
            i += 1
        else:
            return self._finish(block, ctx, axes, others, sequence_value, mode, arc_words, None, cycle)
        return False

    def _finish(self, block: Block, ctx: Context, axes: dict[str, float | Expr],
                others: dict[str, float | Expr] | None, sequence_value: object, mode: str | None, arc_words: bool,
                bare: dict[str, str] | None, cycle: bool) -> bool:
        """Give a block the lane read whole (its axis words ``axes``, other words ``others``, block number,
        motion code's ``mode``, point-less axis words ``bare``) its sections, or answer False where the general
        path reads it."""
        if cycle:
            fill_values(block.values, axes, sequence_value, others)
            if axes:
                block.sections["Motion"] = Motion(None, axes)
                if bare is None:
                    _saw_pointed(ctx, axes, block.line)
                else:
                    _tell_point_mix(block, ctx, axes, bare, self.in_units)
            return True
        if mode is None and axes:
            mode = ctx.state.motion
            if mode is None:
                return False  # the general path explains the error
        if mode is not None:
            motion = plain_motion(others, axes, mode, arc_words)
            if motion is None:
                return False
            fill_values(block.values, axes, sequence_value, others)
            block.sections["Motion"] = motion
            if axes:
                if bare is None:
                    _saw_pointed(ctx, axes, block.line)
                else:
                    _tell_point_mix(block, ctx, axes, bare, self.in_units)
        elif arc_words:
            return False  # I/J/K/R with no motion: the general path refuses it
        else:
            fill_values(block.values, axes, sequence_value, others)
        if others is not None and "F" in others:
            block.sections["Feed"] = Feed(others["F"])
        return True

    def pointless(self, ctx: Context, num: str) -> float | None:
        """A point-less number's value, as ``WordBlockSyntax.build`` reads it (least input increments of the
        set-up's increment system in the units in force, or program units where the dialect says so); None for
        anything but plain digits after an optional sign (the general path reads, or refuses, that)."""
        size = len(num)
        start = 1 if size > 0 and (num[0] == "-" or num[0] == "+") else 0
        if start >= size:
            return None
        for i in range(start, size):
            c = ord(num[i])
            if c < 48 or c > 57:
                return None
        if self.in_units:
            return float(int(num))
        divisor = increments_divisor(ctx, ctx.state.units)
        return int(num) / divisor if divisor else float(int(num))


def whole_number(num: str) -> int:
    """``int(num)`` of a block number's text: digits only (at most 18, an ``i64``'s) summed here, anything else by
    ``int``. A CAM block's N costs a look-up of its ``Sequence`` less (~130 instructions) than reading the
    number the reader parsed (and boxing it: a new int either way), or a fifth of ``int``'s parse."""
    size: i64 = len(num)
    if size == 0 or size > 18:
        return int(num)
    value: i64 = 0
    i: i64 = 0
    while i < size:
        c: i64 = ord(num[i])
        if c < 48 or c > 57:
            return int(num)
        value = value * 10 + (c - 48)
        i += 1
    return value


def fill_values(values: dict[str, float | int | Expr], axes: dict[str, float | Expr], sequence: object,
                others: dict[str, float | Expr] | None) -> None:
    """Fill a plain block's ``Block.values`` (empty: the lanes read a block the reader left without values): its
    axis words', its block number's and its other words' (in that order: the general path's is the words', and no
    reader of ``values`` depends on it). The axes first, into the empty dictionary: compiled, one C call cloning
    their table, and no second dictionary made and dropped."""
    filled = cast("dict[str, object]", values)
    filled.update(axes)
    if sequence is not None:
        filled["N"] = sequence
    if others is not None:
        filled.update(others)


@mypyc_attr(allow_interpreted_subclasses=True)
class PlainLatheLane(PlainLane):
    """The plain-block lane of the lathe reading (``LatheBlockSyntax``): a block its lathe steps give a
    meaning of their own (a repeat of the single cycle in force, an absolute and an incremental word of one
    axis, an arc centre J off the ZX plane) is left to the general path, which reads or refuses it."""

    __slots__ = ()

    def read_marked(self, block: Block, ctx: Context) -> bool:
        return False  # the lathe's checks look at the words: ``read`` reads the block once they are made

    def read(self, block: Block, ctx: Context, words: list[tuple[str, str]]) -> bool:
        if SINGLE_KEY in ctx.state.extra:
            return False  # a bare X/Z repeats the single cycle: the general path decides
        letters = {_UPPER.get(letter, letter) for letter, _ in words}
        if "J" in letters:
            return False  # an arc centre off the ZX plane: ``LatheBlockSyntax.g_sections`` refuses it
        for absolute, increment in ONE_AXIS_WORDS:
            if absolute in letters and increment in letters:
                return False  # the absolute and the incremental word of one axis: ``g_sections`` refuses it
        return super().read(block, ctx, words)


def plain_motion(others: dict[str, float | Expr] | None, axes: dict[str, float | Expr], mode: str,
                 arc_words: bool) -> Motion | None:
    """The ``Motion`` of a plain block in ``mode`` with its axis words (``axes``) and its other words
    (``others``: I/J/K/R and F, or None where it has none): a straight move, or an arc by its centre I/J/K or its
    radius R; None where the general path refuses the words (both forms of an arc, an arc without a centre,
    I/J/K/R beside a straight move), so that it reports the error. Both lanes (``PlainLane``,
    ``plain_ngc.NgcPlainLane``) build their moves here."""
    center: dict[str, float | Expr] | None = None
    radius: float | Expr | None = None
    if mode == "cw" or mode == "ccw":
        values = others if others is not None else {}
        if "R" in values:
            if "I" in values or "J" in values or "K" in values:
                return None  # both forms of an arc
            radius = values["R"]
        else:
            center = {CENTER_AXIS[k]: values[k] for k in "IJK" if k in values}
            if not center:
                return None  # no centre
    elif arc_words:
        return None  # I/J/K/R beside a straight move
    return Motion(mode, axes, center, radius)


def _tell_point_mix(block: Block, ctx: Context, axes: dict[str, float | Expr], bare: dict[str, str],
                    in_units: bool) -> None:
    """Tell the point-mix check (``postproc.rs274.point_mix``), while it still looks, of the axis words of a block
    with point-less ones (``bare``), in word order, each with or without its decimal point, as the general path
    tells it (which does only under least-increment input: ``point_mix`` is None otherwise, and where the dialect
    reads point-less numbers in program units, ``in_units``)."""
    if ctx.point_mix is None or in_units:
        return
    mix = point_mix(ctx)
    if mix is not None:
        units = ctx.state.units
        for up, value in axes.items():
            num = bare.get(up)
            if num is None:
                mix.saw_pointed(ctx, up, block.line)
            else:
                mix.saw_bare(ctx, block, up, num, cast(float, value), units)


def _saw_pointed(ctx: Context, axes: dict[str, float | Expr], line: int) -> None:
    """Tell the point-mix check (``postproc.rs274.point_mix``), while it still looks, of the axis words
    with a decimal point a plain block has."""
    if ctx.point_mix is not None:
        mix = point_mix(ctx)
        if mix is not None:
            pointed = mix.pointed  # (an axis seen with its point already is all a block tells, once the program's
            for up in axes:  # first moves are read: a look-up, not a call, ~400 instructions a block compiled)
                if up not in pointed:
                    mix.saw_pointed(ctx, up, line)
