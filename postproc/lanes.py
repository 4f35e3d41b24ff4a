"""What a reading step offers a run's speed-only shortcut (``postproc.fast``), as the step sees it.

A step that reads one way (the block syntax, the cycle resolver) asks the run's lane first, if the run
installed one (``Context.block_lane``, ``Context.hole_lane``), and reads the block itself when the lane
answers no. The lane decides where it applies; the step knows only these two interfaces, and compiled
each is a direct method call on every block.
"""

from __future__ import annotations

import abc
from typing import TYPE_CHECKING

from mypy_extensions import mypyc_attr

from .ir import Block

if TYPE_CHECKING:
    from .context import Context


@mypyc_attr(allow_interpreted_subclasses=True)
class BlockLane(abc.ABC):
    """Reads the commonest blocks of a word block syntax, as its general path reads them."""

    __slots__ = ()

    @abc.abstractmethod
    def read(self, block: Block, ctx: Context, words: list[tuple[str, str]]) -> bool:
        """Give ``block`` its sections and return True, or return False leaving it as it was (the step
        then reads it)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class HoleLane(abc.ABC):
    """Resolves a block that moves an active hole cycle to its next hole, as the cycle resolver does."""

    __slots__ = ()

    @abc.abstractmethod
    def repeat(self, block: Block, ctx: Context) -> bool:
        """Resolve ``block`` and return True, or return False leaving it as it was (the resolver then
        resolves it from its words and calls ``resolved``)."""

    @abc.abstractmethod
    def resolved(self, block: Block, ctx: Context) -> None:
        """The resolver resolved ``block`` from its words (after ``repeat`` said False)."""
