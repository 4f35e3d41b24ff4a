"""The fast lane: every speed-only shortcut of a translation, in one place above the family bases.

The classes dialects extend (the word writer, the block syntax, the resolver) each write or read one way;
a shortcut here copies part of that way for the commonest blocks, is chosen per run by the lane itself
where the classes it copies are the base's own (``postproc.fast.lane``), and is held to the general path
by differential property tests (``tests/test_straight_moves.py``). A plugin declares nothing for it.
"""

from __future__ import annotations

from .lane import choose, install

__all__ = ["choose", "install"]
