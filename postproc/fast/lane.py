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

from typing import Final

from ..rs274.writer import WordWriter
from ..output.writer_base import Lane, Writer
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


def own_in(cls: type, methods: tuple[str, ...], base: frozenset[type]) -> bool:
    """Whether every one of ``methods`` is, for ``cls``, defined by a class of ``base`` (a family base and
    the layers it is built of): no class a dialect adds overrides it."""
    for name in methods:
        owner = next((c for c in cls.__mro__ if name in c.__dict__), None)
        if owner not in base:
            return False
    return True


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


def install(writer: Writer) -> None:
    """Give ``writer`` its run's fast lane (``Writer.lane``), where one applies."""
    writer.lane = choose(writer)
