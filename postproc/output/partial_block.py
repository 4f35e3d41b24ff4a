"""``--on-unsupported warn`` at the writer: a block the target cannot fully express loses only the section
the writer refused, with whatever cannot be written without it, and the rest is written.

Dropping a word can send the programmed point somewhere else: ``G53 G0 Z0.`` without ``G53`` is a rapid to
the work zero, ``G55 X10.`` without ``G55`` a move in the previous work system. So a refused section takes
with it the sections of the same block whose meaning depends on it (``DEPENDS_ON``): in those cases the
block's motion, which the warning names with its words. A tool length offset or cutter compensation only
adjusts the tool about the programmed point: without it the motion keeps its programmed point (on a
machine whose tools are measured at the tool change, the same place), the warning says so, and ``verify``
measures where the tool goes without it (the set-up's tool lengths and radii). A refused section that changes how the whole block reads (its units; a block
skip aside: the block runs as with the switch off) leaves the block a comment, as does a block with
nothing left to do.
"""

from __future__ import annotations

from typing import Any, Final

from ..errors import UnsupportedError
from ..ir import Block

MOTION: Final = frozenset(("Motion", "CompoundMotion"))
CYCLE: Final = frozenset(("CannedCycle", "CycleCall"))

DEPENDS_ON: Final[dict[str, frozenset[str]]] = {
    "MachineCoordinates": MOTION,
    "WorkOffset": MOTION | CYCLE,
    "DistanceMode": MOTION | CYCLE,
    "Plane": MOTION | CYCLE,
    "FeedMode": MOTION | CYCLE | {"Feed"},
    "Feed": MOTION | CYCLE,
    "ReturnLevel": CYCLE,
    "SpindleSpeed": frozenset(("SpindleControl",)),
    "ToolSelect": frozenset(("ToolChange",)),
}
"""Refused section -> the sections of its block that mean something else without it (dropped with it)."""

WHOLE_BLOCK: Final = frozenset(("Units", "ProgramStart", "TapeMark", "Sequence"))
"""Refused, these leave the whole block a comment: every number of the block (units), or what the line is
(a program start, a tape mark, a block number). A refused block skip (``/``) is dropped alone: the block
then always runs, as it does with the block-delete switch off (what ``toolpath`` and ``verify`` assume)."""

NOTHING_TO_DO: Final = frozenset(("Sequence", "Comments", "BlockDelete"))
"""A block left with only these does nothing: it is written as a comment instead."""

_LETTERS: Final[dict[str, str]] = {
    "Feed": "F", "SpindleSpeed": "S", "ToolSelect": "T", "ToolLengthOffset": "H", "CutterCompensation": "D",
}
"""The address letters of a section's own words (the G or M code aside)."""

_ADJUSTS: Final[dict[str, str]] = {
    "ToolLengthOffset": "the block's motion moves the programmed point without the tool's length",
    "CutterCompensation": "the block's motion moves the tool's centre along the programmed path",
}
"""Refused sections that only adjust the tool about the programmed point: what the rest then does."""

_WHAT: Final[dict[str, str]] = {
    "Motion": "the block's motion", "CompoundMotion": "the block's motion", "CannedCycle": "its hole cycle",
    "CycleCall": "its cycle call", "Feed": "its feed rate", "SpindleControl": "its spindle start or stop",
    "ToolChange": "its tool change",
}


def write_without_refused(writer: Any, block: Block, err: UnsupportedError,
                          dropped: set[str] | None = None) -> str | None:
    """The block's text without the section ``err`` refused and its dependants (warned), trying again while
    the writer refuses another; None where the block must be a comment instead. ``dropped`` receives the
    keys of the sections left out of the text returned."""
    refused: list[tuple[UnsupportedError, str, list[str]]] = []
    current = block
    for _ in range(len(block.sections)):
        key = err.section
        if key is None or key in WHOLE_BLOCK or key not in current.sections:
            return None
        dependants = sorted(DEPENDS_ON.get(key, frozenset()) & current.sections.keys())
        current = _without(current, {key, *dependants})
        refused.append((err, key, dependants))
        if not current.sections.keys() - NOTHING_TO_DO:
            return None
        try:
            text: str | None = writer.write_block(current)
        except UnsupportedError as again:
            err = again
            continue
        where = writer.ctx.at(block)
        if dropped is not None:
            dropped.update(block.sections.keys() - current.sections.keys())
        for why, key, gone in refused:
            writer.ctx.diagnostics.warn(_message(why, block, key, gone), where)
        trace: str = writer.comment_out(block)  # the source line stays beside what is kept
        return trace + (text or "")
    return None


def _message(err: UnsupportedError, block: Block, key: str, dependants: list[str]) -> str:
    own = _words(block, key)
    text = err.message + "; dropped" + (f" ({own})" if own else "")
    if dependants:
        named = [f"{_words(block, d)} ({_WHAT.get(d, d)})" if _words(block, d) else _WHAT.get(d, d)
                 for d in dependants]
        text += ", with " + " and ".join(named) + ", which cannot be written without it"
    adjusts = _ADJUSTS.get(key)
    if adjusts is not None and any(k in block.sections for k in MOTION):
        text += f" ({adjusts})"
    return text + "; the rest of the block is written"


def _words(block: Block, key: str) -> str:
    """The block's words that belong to section ``key``, as written in the source (its G and M codes
    aside): a motion's axis and arc words, a feed's F, an offset's H or D."""
    section = block.sections.get(key)
    if key in MOTION:
        letters = set(getattr(section, "axes", {}) or {}) | set("IJKR")
    else:
        letters = set(_LETTERS.get(key, ""))
    return " ".join(letter + number for letter, number in block.words if letter.upper() in letters)


def _without(block: Block, keys: set[str]) -> Block:
    """A copy of ``block`` without the sections ``keys`` (to be generated: no source text to copy)."""
    copy = Block(block.line, None, block.eol, block.words)
    copy.values = block.values
    copy.sections = {k: v for k, v in block.sections.items() if k not in keys}
    return copy
