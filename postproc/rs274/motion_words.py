"""MotionWords: a move's words and a native cycle's, the third layer of ``WordWriter``
(``postproc.rs274.writer``).

A move is its motion code, its axis words (a canonical source number copied as written where that is the
text the writer would spell, ``source_number``), an arc's centre from the written start or its radius; a
cycle's words are written by their role where the target's letters differ from the source's.
"""

from __future__ import annotations

import math

from typing import Any, ClassVar, Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..cycle_words import CycleWords
from ..cycles.section import WORD_ORDER
from ..cycles.semantics import PECK, SHIFT
from ..dialect import Dialect
from ..ir.expr import Expr
from ..ir import Block, Motion
from ..numbers import as_written
from ..ir.state import PLANE_AXES
from .section_words import SectionWords
from .word_numbers import _position

MOTION_KIND: Final = {"home": "home", "home2": "home"}
"""Motion modes the table spells under another kind than "motion" (reference returns)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class MotionWords(SectionWords):
    """Writes a block's motion and canned-cycle words; ``WordWriter`` assembles them into blocks."""

    BARE_FEED_MOTION_NEEDS_FEED: ClassVar[bool] = False
    """True where a feed motion code with no axis words is refused while no feed rate is in force
    (RS274/NGC: rs274 "Cannot do g1 with zero feed rate", grbl error 22): such a code only sets the mode,
    and every later move writes its own motion code, so it is left out (a block left with nothing to
    say keeps its source line as a comment)."""

    DRIVEN_AXES: ClassVar[frozenset[str] | None] = None
    """The axes the controller drives, where it drives fewer than the programs it is given may move (grbl:
    X, Y, Z): a move of another is an ``UnsupportedError`` naming it. None: every axis is written."""

    ZERO_RADIUS_ARC: ClassVar[str] = ""
    """How the controller refuses an arc whose centre is its start ('': it runs it, doing nothing)."""
    MIN_ARC_RADIUS: ClassVar[tuple[float, float]] = (0.0, 0.0)
    """The radius (mm, inch) at or below which the controller refuses a centre-form arc as of zero radius
    (``ZERO_RADIUS_ARC``); (0, 0): only a centre at the start."""
    FULL_CIRCLE_HELIX: ClassVar[bool] = True
    """An arc whose end point names neither axis of its plane (a helical full circle, which the lowering
    could not close) runs; False: the controller refuses it (grbl)."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.motion_codes: dict[str, str] = {}
        """Motion mode -> its code, spelled once (``CodeTable.spell`` is a Python call; an expansion
        writes a code per move)."""
        cls = type(self)
        self._driven_axes: frozenset[str] | None = cls.DRIVEN_AXES
        self._full_circle_helix: bool = cls.FULL_CIRCLE_HELIX
        self._zero_radius_arc: str = cls.ZERO_RADIUS_ARC
        """The class's ``DRIVEN_AXES``, ``FULL_CIRCLE_HELIX`` and ``ZERO_RADIUS_ARC``, read once: compiled, a
        class attribute a plugin's (interpreted) class may override is a look-up by name, three a move
        (~900 instructions a line of an expanded cycle)."""

    def left_out(self, s: Motion, block: Block) -> bool:
        """A bare feed motion code the target refuses with no feed rate in force
        (``BARE_FEED_MOTION_NEEDS_FEED``): it only sets the mode, so it is not written. The rate in force
        is the block's own F when it has one (``G01 F0``, which rs274 refuses as ``G1 F0``)."""
        if not (self.BARE_FEED_MOTION_NEEDS_FEED and not s.axes and s.mode in ("linear", "cw", "ccw")):
            return False
        feed = block.sections.get("Feed")
        rate = self.modal.feed if feed is None else feed.value  # type: ignore[attr-defined]
        return isinstance(rate, (int, float)) and rate == 0 or rate is None

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        driven = self._driven_axes
        if driven is not None:
            for axis in s.axes:
                if axis not in driven:
                    self.unsupported(f"motion of axis {axis} ({self.DIALECT} drives {_listed(driven)})", block)
        if not self._full_circle_helix and (s.mode == "cw" or s.mode == "ccw"):
            plane = block.sections.get("Plane")
            first, second, _ = PLANE_AXES[plane.plane if plane is not None else self.modal.plane]  # type: ignore[attr-defined]
            if first not in s.axes and second not in s.axes:
                self.unsupported("a helical full circle with no end point in its plane, in absolute mode", block)
        if s.mode in MOTION_KIND:
            self.check_reference_return(s, block)
            if not s.axes:
                return []  # a return naming no axis moves none (Fanuc); a bare code would move every axis (LinuxCNC)
        elif self._zero_radius_arc and (s.mode == "cw" or s.mode == "ccw") and s.radius is None \
                and s.center is not None and tiny_arc(s.center, self.MIN_ARC_RADIUS[self.modal.units == "inch"]):
            self.unsupported(f"an arc of zero radius (a controller that runs it does nothing; {self.ZERO_RADIUS_ARC})"
                             if tiny_arc(s.center, 0.0) else
                             f"an arc of zero radius by the controller's measure (its radius is at most "
                             f"{self.MIN_ARC_RADIUS[self.modal.units == 'inch']} {self.modal.units}; {self.ZERO_RADIUS_ARC})",
                             block)
        if s.mode is None:
            self.unsupported("a canned-cycle repetition without its cycle", block)
        if not s.axes and self.left_out(s, block):
            return []
        code = self.motion_codes.get(s.mode)
        if code is None:
            code = self.codes.spell(MOTION_KIND.get(s.mode, "motion"), s.mode)
            if code is None:
                self.unsupported(f"{s.mode} motion", block)
            self.motion_codes[s.mode] = code
        words = [code]
        start = dict(self.carry) if s.center is not None else None
        incremental = _incremental(self, block)
        as_written = block.canonical and self.source_numbers
        for axis, value in s.axes.items():
            if type(value) is float:
                text = self.source_number(block, axis, value, incremental) if as_written else None
                words.append(axis + (text if text is not None else _position(self, axis, value, incremental)))
            elif isinstance(value, Expr):
                words.append(axis + self.expression(value, block))
                if not incremental:
                    self.carry.pop(axis, None)  # written as the program wrote it
            else:
                words.append(axis + _position(self, axis, value, incremental))
        if s.mode in MOTION_KIND:
            for axis in s.axes:
                self.carry.pop(axis, None)  # both programs end at the reference point
        if s.center is not None:
            for axis, letter in (("X", "I"), ("Y", "J"), ("Z", "K")):
                if axis in s.center:
                    offset = s.center[axis]
                    exact = offset if isinstance(offset, Expr) else offset + start.get(axis, 0.0)  # type: ignore[union-attr]
                    words.append(letter + self.length(exact, block, letter))  # from the written start to the exact centre
        if s.radius is not None:
            words.append("R" + self.length(s.radius, block, "R"))
        return words

    def check_reference_return(self, s: Motion, block: Block) -> None:
        """Refuse a reference return (G28/G30) the controller refuses in the state it is in (the base: none)."""

    def source_number(self, block: Block, axis: str, value: float, incremental: bool) -> str | None:
        """The number of a canonical block's ``axis`` word as the source wrote it, when that is the text
        ``position`` writes, else None. It is when the value is the one the word reads as (no step changed
        it; a float compare, cheaper than spelling), nothing is carried on the axis, and the number has no
        more places than this writer writes exactly (``postproc.numbers.as_written``, property-tested in
        ``tests/test_fast_numbers.py``). It saves spelling a number, most of a CAM block's writing."""
        if incremental and axis in self.carry:
            return None
        for letter, text in block.words:
            if letter == axis:
                if not as_written(text, value, self.exact_mm if self.modal.units == "mm" else self.exact_inch) \
                        or float(text) != value:
                    return None
                if self.carry:
                    self.carry.pop(axis, None)  # written exactly: nothing left to carry
                return text
        return None

    def _incremental(self, s: Motion, block: Block) -> bool:
        """True when the motion's axis words are increments (machine coordinates are always absolute)."""
        return _incremental(self, block)

    def _rounded_axes(self, block: Block) -> dict[str, bool]:
        """Axis letters of a normalised block's motion whose numbers go through ``position`` (letter ->
        incremental); an expression or a cycle's words keep their text."""
        motion = block.sections.get("Motion")
        if not isinstance(motion, Motion) or motion.mode is None or motion.mode in MOTION_KIND:
            return {}
        incremental = _incremental(self, block)
        return {a: incremental for a, v in motion.axes.items() if type(v) is float}

    def exact_axes(self, block: Block) -> None:
        """A block copied with its exact numbers: absolute axis words leave nothing to carry (callers test
        ``self.carry`` first: on the hot path there is usually nothing carried)."""
        if self.carry:
            for axis, incremental in self._rounded_axes(block).items():
                if not incremental:
                    self.carry.pop(axis, None)

    def canned_cycle_words(self, s: Any, block: Block) -> list[str]:
        """A native cycle: its code when the block programs it, then its words as programmed.
        G98/G99 and F come from the block's own ReturnLevel and Feed sections."""
        words: list[str] = []
        if s.call:
            words.extend(self._code("cycle", s.kind, f"the {s.kind.replace('_', ' ')} cycle", block))
        source, target = self.ctx.cycle_words, self.target_cycle_words()
        if source is not None and target is not None and not source.same_letters(target):
            return words + self.cycle_role_words(s, block, source, target)
        for letter, value in s.words.items():
            words.append(letter + (str(value) if isinstance(value, int) else self.length(value, block, letter)))
        return words

    def target_cycle_words(self) -> CycleWords | None:
        """The letters this writer's cycles take (the target dialect's; one whose letters depend on the
        set-up builds them here)."""
        return self.target.CYCLE_WORDS if self.target is not None else None

    def cycle_role_words(self, s: Any, block: Block, source: CycleWords, target: CycleWords,
                         dwell: bool = True) -> list[str]:
        """The words of a cycle read with other letters (Fagor ``Z I K`` <-> Fanuc ``R Z P``), each
        written by its role: the plane's two axes as they are, the reference level, the hole bottom, the
        peck or shift, the dwell (from its seconds, in the target's unit; left out when ``dwell`` is
        False) and the repeat count. Both dialects measure the level from the initial level and the
        bottom from the level under incremental distances, so a word keeps its value."""
        first, second, normal = PLANE_AXES[s.plane]
        out: dict[str, str] = {}
        repeat = source.repeat_letters(self.ctx.setup.input.repeat_address)
        target_repeat = target.repeat_letters(self.ctx.setup.input.repeat_address)
        for letter, value in s.words.items():
            if letter in (first, second):
                out[letter] = self.length(value, block, letter)
            elif letter == source.level:
                out[target.level] = self.length(value, block, target.level)
            elif letter == source.bottom_letter(s.plane, normal):
                bottom = target.bottom_letter(s.plane, normal)
                out[bottom] = self.length(value, block, bottom)
            elif letter == source.dwell:
                if dwell:
                    out[target.dwell] = self.cycle_dwell(s.dwell, target, block)
            elif letter in repeat:
                if target_repeat:
                    out[target_repeat[0]] = str(int(value))
                elif value != 1:
                    self.unsupported(f"a cycle repeat count {letter}{value} (no repeat count in "
                                     f"{self.DIALECT})", block)
            elif letter == source.peck and s.kind in PECK and target.peck:
                out[target.peck] = self.length(value, block, target.peck)
            elif letter == source.shift and s.kind in SHIFT and target.shift:
                out[target.shift] = self.length(value, block, target.shift)
            else:
                self.unsupported(f"the cycle word {letter} (no {self.DIALECT} word has its role)", block)
        order = {c: i for i, c in enumerate(WORD_ORDER)}
        return [letter + text for letter, text in sorted(out.items(), key=lambda kv: order.get(kv[0], 99))]

    def cycle_dwell(self, seconds: float | None, target: CycleWords, block: Block) -> str:
        """A cycle's dwell in the target's unit: whole milliseconds (Fanuc semantics), seconds (RS274)
        or the unit its cycle words name; a time that unit cannot hold exactly is refused."""
        value = seconds or 0.0
        unit = target.dwell_unit
        if unit is None:
            unit = 0.001 if self.target is not None and self.target.CYCLE_SEMANTICS == "fanuc" else 1.0
        count = value / unit
        if unit == 0.001:
            if abs(count - round(count)) > 1e-6:
                self.unsupported(f"a dwell of {value:g} s (whole milliseconds only)", block)
            return str(round(count))
        return self.number(round(count, 9))


def _incremental(w: MotionWords, block: Block) -> bool:
    """``MotionWords._incremental``: True when a motion's axis words are increments (machine coordinates
    are always absolute)."""
    return w.modal.distance == "incremental" and "MachineCoordinates" not in block.sections


def _listed(axes: frozenset[str]) -> str:
    """``X, Y and Z``: the axes in their usual order, for a message."""
    letters = [axis for axis in "XYZABCUVW" if axis in axes] + sorted(axes - frozenset("XYZABCUVW"))
    return letters[0] if len(letters) == 1 else ", ".join(letters[:-1]) + " and " + letters[-1]


def tiny_arc(center: dict[str, float | Expr], limit: float) -> bool:
    """An arc whose centre offsets put its centre at its start, or within ``limit`` of it (a hair over, for the
    controller's own sums of the offsets: rs274 found 20.001 - 20.0 below 0.001)."""
    squares = 0.0
    for offset in center.values():
        if type(offset) is not float:
            return False
        squares += offset * offset
    return squares == 0.0 or math.sqrt(squares) <= limit * (1.0 + 1e-6)


