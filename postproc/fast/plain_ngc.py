"""The plain-block lane of the RS274/NGC reading: a CAM program's usual block, ``N.. G1 X.. Y.. F..``, read in one
pass, as ``postproc.fast.plain`` reads it for the Fanuc family.

A speed-only copy of what ``NgcWordBlockSyntax.build`` reads from such a block (the block number first, the
words as real numbers as written, ``_check_feed_mode_code``, the family's ``g_sections`` and ``finish_words``).
Why it pays: the NGC dialects' block syntax classes are interpreted subclasses of the compiled base, so each
of the base's own method calls on a block goes through mypyc's glue, a Python-level call (~1.2k instructions;
LinuxCNC's reading cost ~40k a block, ``verify`` reads every translation to LinuxCNC). ``postproc.fast.reading``
installs it for a run only where the class reads such a block with the base's own methods, and the dialect's
hooks (``before_sections``, ``after_sections``, ``special_g_code``) would not run for it: the lane reads their
declarations (``OWN_CODES``, ``OWN_STATE``, ``OWN_MOTION``, ``SPECIAL_G``) and leaves a block they select to
the general path. ``tests/test_plain_blocks.py`` holds it to the general path on random programs. It answers
False, leaving the block as it found it, at the first word it does not handle or for a block the general path
refuses, so that path reads the block and reports its errors.
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..context import BlockLane, Context
from ..ir.expr import Expr
from ..ir import Block, Feed
from ..numbers import decimal_value
from ..rs274.codes import g_key
from ..rs274.ngc_block_syntax import _STATE_KEY as NO_MOTION_KEY, NgcWordBlockSyntax
from .plain import (LETTER_ARC, LETTER_AXIS, LETTER_F, LETTER_G, LETTER_KIND, LETTER_N, MOTION_MODES,
                    plain_motion, fill_values, whole_number)

_UPPER: Final = {c: c.upper() for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"}
_FEED_MODES: Final = frozenset(("linear", "cw", "ccw"))
_MOTIONS_HELD: Final = 64
"""Spellings of motion codes a run remembers (``NgcPlainLane.motions``): a program writes a few (``G1``, ``G01``);
a hostile one writing thousands costs a look-up each past these, never memory."""
_MOTION_GROUP: Final = "01"
"""The motion codes that need a feed rate in force (``NgcWordBlockSyntax._check_feed_mode_code``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class NgcPlainLane(BlockLane):
    """N (first), maybe one motion code (G0-G3), axis words, an arc's centre I/J/K or radius R, maybe F; outside
    an active canned cycle and while a motion mode is in force."""

    __slots__ = ("syntax", "real", "n_first", "codes", "own_codes", "own_state", "own_motion", "special", "motions")

    def __init__(self, syntax: NgcWordBlockSyntax) -> None:
        self.syntax = syntax
        # the dialect's declarations, read once through the instance (a plugin's class sets them)
        self.real = syntax.REAL_LETTERS
        self.n_first = syntax.N_FIRST
        self.codes = syntax.CODES
        self.own_codes = syntax.OWN_CODES
        self.own_state = syntax.OWN_STATE
        self.own_motion = syntax.OWN_MOTION
        self.special = syntax.SPECIAL_G
        self.motions: dict[str, tuple[str, str]] = {}
        """The motion codes met, by their number as written (``_motion_code``; at most ``_MOTIONS_HELD``)."""

    def read(self, block: Block, ctx: Context, words: list[tuple[str, str]]) -> bool:
        state = ctx.state
        extra = state.extra
        if state.cycle is not None or extra.get(NO_MOTION_KEY, False):
            return False  # cycle words, or axis words after a cycle cancel: the general path (which alone
            # sets the no-motion mark; a motion code read here leaves it unset, as the general path's False)
        own_state = self.own_state
        if own_state:  # (an empty set's loop is an iterator a block: ~320 instructions)
            for key in own_state:
                if key in extra:
                    return False  # the dialect reads the block further itself (``after_sections``)
        real = self.real
        # The words' values gathered apart and the block's ``values`` made once the lane is sure of the block
        # (``postproc.fast.plain``'s ``PlainLane.read`` says why).
        axes: dict[str, float | Expr] = {}
        others: dict[str, float | Expr] | None = None  # I/J/K/R and F, where the block has them
        sequence: object = None  # N's value
        mode: str | None = None
        group = ""  # the motion code's modal group, where the block has one
        arc_words = False
        seen = 0  # the addresses met, one bit per letter (a repeated one leaves the lane)
        first = True
        for letter, num in words:
            up = _UPPER.get(letter)
            if up is None:
                break
            index = ord(up) - 65
            bit = 1 << index
            if seen & bit:
                break
            seen |= bit
            kind = LETTER_KIND[index]
            if kind == LETTER_N:
                if "." in num or self.n_first and not (first and _starts_with_n(block.text or "")):
                    break  # a fractional N, or one the N-first rule looks at: the general path
                sequence = whole_number(num)
            elif kind == LETTER_G and mode is None:
                found = self.motions.get(num)
                if found is None:
                    found = self._motion_code(num)
                    if found is None:
                        break
                    if len(self.motions) < _MOTIONS_HELD:
                        self.motions[num] = found
                group, mode = found
            elif up not in real:
                break
            elif kind == LETTER_AXIS:
                axes[up] = decimal_value(num)  # (``float(num)``, the general path's reading, computed: postproc.numbers)
            elif kind == LETTER_F:
                if others is None:
                    others = {}
                others["F"] = decimal_value(num)
            elif kind == LETTER_ARC:
                if others is None:
                    others = {}
                others[up] = decimal_value(num)
                arc_words = True
            else:
                break
            first = False
        else:
            fed = others is not None and "F" in others
            if group == _MOTION_GROUP and mode in _FEED_MODES and not state.symbolic and state.feed_mode != "inverse_time":
                feed = others["F"] if others is not None and fed else state.feed
                if not isinstance(feed, Expr) and not feed:
                    return False  # no feed rate in force: the general path refuses it
            if mode is None and axes:
                mode = state.motion
                if mode is None:
                    return False  # the general path explains the error
            if mode is not None:
                if mode in self.own_motion:
                    return False  # the dialect reads the block further itself (``after_sections``)
                motion = plain_motion(others, axes, mode, arc_words)
                if motion is None:
                    return False
                block.sections["Motion"] = motion
            elif arc_words:
                return False  # I/J/K/R with no motion: the general path refuses it
            fill_values(block.values, axes, sequence, others)
            if others is not None and fed:
                block.sections["Feed"] = Feed(others["F"])
            return True
        return False


    def _motion_code(self, num: str) -> tuple[str, str] | None:
        """A G word's number as written -> (its modal group, its motion mode) where it is a motion code the lane
        reads (G0-G3 of the dialect's table that the dialect neither reads itself nor refuses); else None.
        Remembered per spelling (``motions``): it depends on the number and the run's fixed declarations only,
        and ``g_key`` is interpreted (~3.4k instructions a call compiled: LinuxCNC writes G1 in every line)."""
        key = g_key(num)
        if key in self.special or key in self.codes.refused_g:
            return None
        entry = self.codes.g.get(key)
        if entry is None or entry[1] != "motion" or entry[2] not in MOTION_MODES:
            return None
        group, what, arg = str(entry[0]), entry[1], entry[2]
        own = self.own_codes
        if group in own or what in own or isinstance(arg, str) and arg in own:
            return None
        return group, str(arg)


def _starts_with_n(text: str) -> bool:
    """The block's text starts with its number (after blanks): the N-first rule holds without looking for
    columns (a block delete ``/`` first is left to the general path)."""
    for ch in text:
        if ch != " " and ch != "\t":
            return ch == "N" or ch == "n"
    return False
