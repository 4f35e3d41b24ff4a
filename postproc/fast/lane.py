"""Chooses a run's fast lane: a speed-only shortcut for canonical blocks, installed on the writer only
where it writes what the writer's general path writes.

The choice is the lane's own, never a plugin's declaration: a shortcut copies the word writer's base
methods, so it is taken only when the writer class uses the base's own method for every step the
shortcut skips (``STRAIGHT_METHODS``, ``COPY_METHODS``) and its section table routes the shortcut's
sections to them (none is a ``STRUCTURE`` or ``SPLIT`` section of the class, no mode the lane writes a
``SPLIT_MOTIONS`` one). A dialect that overrides one of them is written by its general path, whatever the
override does. (``Writer.write`` is not among them: the lane is consulted inside it, so an override that
wraps it keeps the lane, and one that replaces it never consults it.)
"""

from __future__ import annotations

import re
from typing import Final

from ..rs274.writer import WordWriter
from ..output.writer_base import Lane, Writer
from .reading import own_in
from .straight import LANE_MODES, STRAIGHT_KEYS, CopyLane, SourceLane, StraightLane

STRAIGHT_METHODS: Final = ("write_block", "words_block", "generate", "unsplit", "_generate", "section_words", "section_writer",
                           "dispatch_table", "sequence_words", "motion_words", "feed_words", "feed_rate_words",
                           "feed_number", "left_out", "source_number", "number", "length", "position", "_track")
"""What the general path calls to write a straight block of another dialect (``StraightLane``). Not among
them: ``split_block``, offered only a block of a ``SPLIT`` section (none is a straight one) or of a
``SPLIT_MOTIONS`` move (the lane writes no such mode, ``LANE_MODES``), and ``after_block``, which the lane
calls as ``generate`` does (while the writer's ``after_blocks`` is set)."""
COPY_METHODS: Final = ("write_block", "words_block", "normalized", "_track")
"""What the general path calls to write a straight block normalised back to its own dialect (``CopyLane``)."""
SOURCE_METHODS: Final = ("write_block", "words_block")
"""What the general path calls to copy a straight block to its own dialect (``SourceLane``)."""


_BASE: Final = frozenset(WordWriter.__mro__)
"""``WordWriter`` and the layers it is built of (``postproc.rs274.word_numbers``...)."""


def own(cls: type, methods: tuple[str, ...]) -> bool:
    """Whether every one of ``methods`` is the word writer's own for ``cls`` (no dialect's class overrides it)."""
    return own_in(cls, methods, _BASE)


def choose(writer: Writer) -> Lane | None:
    """The shortcut for ``writer``'s run, or None (the general path writes every block)."""
    if not isinstance(writer, WordWriter):
        return None
    cls = type(writer)
    if not (STRAIGHT_KEYS.isdisjoint(cls.STRUCTURE) and STRAIGHT_KEYS.isdisjoint(cls.SPLIT)):
        return None
    copies = (writer.source_dialect == writer.DIALECT and writer.normalize and not writer.renumber
              and writer.leading_zero and not writer.rounding)  # ``normalized`` copies a canonical block
    if copies and own(cls, COPY_METHODS):
        return CopyLane(writer)
    if writer.copy_ok and own(cls, SOURCE_METHODS):
        return SourceLane(writer)
    if writer.source_dialect != writer.DIALECT and own(cls, STRAIGHT_METHODS) \
            and STRAIGHT_KEYS.isdisjoint(cls.TRANSFORMS) and LANE_MODES.isdisjoint(writer.split_motions):
        return StraightLane(writer)
    return None


def passes_below(lane: Lane, rule: object) -> int:
    """The length below which a text ``lane`` writes passes ``rule`` (the target's ``LINE_RULE``) as it is, told
    from the rule's own ``fits`` (no dialect's class overrides it); 0: every text goes to the rule. Only the
    straight and copy lanes write nothing but a canonical block's words (``numbers.CANONICAL_BLOCK``: ASCII
    letters, digits, points, minus signs, single spaces) with the motion code of the target's table and a line
    end (LF, CR LF or CR), so that only the length of such a text can fail a rule (``tests/test_line_pass.py``).
    grbl's rule looked at every character of every block for its real-time ones (~630 instructions a block,
    callgrind); LinuxCNC's at its length (~90)."""
    if not isinstance(lane, (StraightLane, CopyLane)) or rule is None:
        return 0
    if isinstance(lane, StraightLane):
        for spelled in (lane.rapid, lane.linear, lane.cw, lane.ccw):
            if spelled is not None and not _WORD.fullmatch(spelled[0]):
                return 0
    owner = next((c for c in type(rule).__mro__ if "fits" in c.__dict__), None)
    if owner is None:
        return 0
    module = owner.__module__
    if module == "postproc.grbl_family.text":  # (loaded: the rule is made of its class; imported only then)
        from ..grbl_family.text import GrblLines
        if owner is GrblLines and isinstance(rule, GrblLines):
            return rule.buffer_size  # a shorter line passes as it is where it is plain ASCII without a real-time
            # character, which canonical words and a line end are (``GrblLines.fits``)
    elif module == "postproc.output.byte_lines":
        from ..output.byte_lines import ByteLengthLines
        if owner is ByteLengthLines and isinstance(rule, ByteLengthLines):
            return rule.limit + 1  # ASCII: a character a byte (``ByteLengthLines.fits``)
    return 0


_WORD: Final = re.compile(r"[A-Z][0-9.]+")
"""A motion code the straight lane writes into a canonical block's words keeps them plain (``G1``, ``G01``)."""


def install(writer: Writer) -> None:
    """Give ``writer`` its run's fast lane (``Writer.lane``), where one applies, with the length below which its
    texts pass the target's line rule as they are (``Lane.passes_below``)."""
    lane = choose(writer)
    if lane is not None:
        lane.passes_below = passes_below(lane, getattr(writer.target, "LINE_RULE", None))
    writer.lane = lane
