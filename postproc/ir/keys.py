"""The one test every per-block step makes first: is this block only a move (and its block number)?

Most blocks of a CAM program are ``N.. X.. Y.. Z..``: sections ``Sequence`` and ``Motion`` and nothing else.
A lowering step that watches other sections asked each block by a loop over its keys against a set of
its own (compiled, ~570 instructions for two keys: a dictionary iteration and a set look-up a key); this
asks by the block's size and two dictionary look-ups (~200), and a step falls back to its own loop only for
the other blocks. Compiled (``pyproject.toml``): called natively by every compiled step.
"""

from __future__ import annotations

from .section import Section


def only_move(sections: dict[str, Section]) -> bool:
    """The block holds a ``Motion`` section and at most a ``Sequence`` (block number) besides: a step that
    watches neither key has nothing to look for in it but the move."""
    size = len(sections)
    if size == 2:
        return "Motion" in sections and "Sequence" in sections
    return size == 1 and "Motion" in sections
