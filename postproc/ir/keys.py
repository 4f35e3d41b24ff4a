"""The one test every per-block step makes first: is this block only a move (and its block number)? And the
test built on it, ``watches_none``: does the block hold none of the sections a step follows?

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


def watches_none(sections: dict[str, Section], watched: frozenset[str]) -> bool:
    """No key of the block is in ``watched`` (which names neither ``Motion`` nor ``Sequence``: a step that follows
    moves asks ``only_move`` itself): the commonest block by ``only_move``, any other by a loop over its few keys
    (compiled, ``watched.isdisjoint(sections)`` is a bound method call, ~600-800 instructions a block). The
    lowering steps that pass most blocks through untouched ask it first, each with its own set."""
    if only_move(sections):
        return True
    for key in sections:
        if key in watched:
            return False
    return True
