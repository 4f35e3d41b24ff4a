"""Chooses a run's reading lanes: the plain-block lane for its block syntax, the next-hole lane for its
cycle resolver, each installed on the run's context only where it reads what the step's general path reads.

The choice is the lane's own, never a plugin's declaration: a lane copies the family base's methods, so
it is taken only when the step's class uses the base's own method for every step the lane skips
(``BLOCK_METHODS``, ``RESOLVE_METHODS``). A dialect that overrides one of them is read by its general
path, whatever the override does. (The step's ``build`` is not among them: the lane is consulted inside
it, so an override that wraps it keeps the lane, and one that replaces it never consults it.) A pipeline
with two steps of a kind gets no lane of that kind.
"""

from __future__ import annotations

from typing import Final

from ..context import BlockLane, Context, HoleLane
from ..cycles.resolve import CannedCycleResolveSyntax
from ..rs274.block_syntax import WordBlockSyntax
from ..rs274.canonical_line import LineNumbers, line_numbers
from ..rs274.lathe_block_syntax import LatheBlockSyntax
from ..rs274.ngc_block_syntax import NgcWordBlockSyntax
from ..syntaxes.syntax import Pipeline
from .holes import NextHoleLane
from .plain import PlainLane, PlainLatheLane
from .plain_ngc import NgcPlainLane

BLOCK_METHODS: Final = ("g_sections", "m_sections", "finish_words", "_g_code", "cycle_data_letters")
"""What the block syntax's general path calls to read a block the plain-block lane reads (``PlainLane``)."""
NGC_BLOCK_METHODS: Final = ("_check_n_first", "_g_code", "_owns", "g_sections", "_check_feed_mode_code", "m_sections",
                            "finish_words", "cycle_data_letters")
"""What the RS274/NGC block syntax's general path calls to read a block its lane reads (``NgcPlainLane``). Not
among them: the dialect's hooks (``before_sections``, ``after_sections``, ``special_g_code``), which that path
calls only for a block its declarations select, and the lane leaves such a block to it."""
RESOLVE_METHODS: Final = ("_resolve_or_drop", "_resolve", "_letters", "_holes", "_check", "_levels", "install",
                          "expansion")
"""What the cycle resolver calls to resolve a next-hole block from its words (``NextHoleLane``)."""

_WORD_BASE: Final = frozenset(WordBlockSyntax.__mro__)
_LATHE_BASE: Final = frozenset(LatheBlockSyntax.__mro__)
_NGC_BASE: Final = frozenset(NgcWordBlockSyntax.__mro__)
_RESOLVE_BASE: Final = frozenset(CannedCycleResolveSyntax.__mro__)


def own_in(cls: type, methods: tuple[str, ...], base: frozenset[type]) -> bool:
    """Whether every one of ``methods`` is, for ``cls``, defined by a class of ``base`` (a family base and
    the layers it is built of): no class a dialect adds overrides it. (Here, not in ``lane``, which the writer's
    lane needs too: importing ``lane`` imports the word writer, which a toolpath's reading has no use for.)"""
    for name in methods:
        owner = next((c for c in cls.__mro__ if name in c.__dict__), None)
        if owner not in base:
            return False
    return True


def block_lane(syntax: WordBlockSyntax, numbers: LineNumbers | None = None) -> BlockLane | None:
    """The plain-block lane for ``syntax``'s run, or None (its general path reads every block). ``numbers``: the
    run's numbers of the lines its reader's scan leaves unmade (``canonical_line.line_numbers``)."""
    cls = type(syntax)
    if isinstance(syntax, NgcWordBlockSyntax):
        return NgcPlainLane(syntax) if own_in(cls, NGC_BLOCK_METHODS, _NGC_BASE) else None
    if issubclass(cls, LatheBlockSyntax):
        return PlainLatheLane(syntax) if own_in(cls, BLOCK_METHODS, _LATHE_BASE) else None
    return PlainLane(syntax, numbers) if own_in(cls, BLOCK_METHODS, _WORD_BASE) else None


def hole_lane(resolver: CannedCycleResolveSyntax) -> HoleLane | None:
    """The next-hole lane for ``resolver``'s run, or None (it resolves every block from its words)."""
    return NextHoleLane(resolver) if own_in(type(resolver), RESOLVE_METHODS, _RESOLVE_BASE) else None


def install_reading(pipeline: Pipeline, ctx: Context) -> None:
    """Give the run of ``pipeline`` in ``ctx`` its reading lanes (``Context.block_lane``, ``hole_lane``),
    where they apply."""
    syntaxes = [step for step in pipeline.steps if isinstance(step, WordBlockSyntax)]
    resolvers = [step for step in pipeline.steps if isinstance(step, CannedCycleResolveSyntax)]
    ctx.block_lane = block_lane(syntaxes[0], line_numbers(ctx.run_data)) if len(syntaxes) == 1 else None
    ctx.hole_lane = hole_lane(resolvers[0]) if len(resolvers) == 1 else None
