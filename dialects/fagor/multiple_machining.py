"""Fagor multiple machining G160-G165: the words of a pattern block -> a neutral ``HolePattern``.

The Fagor block syntax routes a block programming G160-G165 here (``multiple_machining``); this module
reads the pattern's words, refuses every combination the reference does not define with a located
error, and has the core resolve the pattern against the active cycle (``resolve_hole_pattern``).
``pattern_words`` is the inverse, for a writer that regenerates a pattern block.

What the words mean (DIALECTS.md §2.3 and the 8070 manual page of G163, seed 004):

* G160 line ``A X I K``: A the line's angle, X its length, I the step, K the number of points (point 1
  included); exactly two of X, I, K.
* G161 parallelogram perimeter, G162 grid ``A B X I K Y J D``: A the first side's angle, B the angle
  between the sides (90 when absent); X/I/K length, step and count of the first side, Y/J/D of the
  second (exactly two of each three).
* G163 full circle ``X Y I|K C F``: X Y the distance from the first point to the centre; I the angular
  step (its sign the direction for C0/C1) or K the number of points (counter-clockwise), not both; the
  steps must make exactly 360 degrees; C how the tool moves between points (0 rapid, 1 feed, 2
  clockwise arc, 3 counter-clockwise arc; an arc turns its own way whatever the sign of I), F the feed
  of those moves, required for C1-C3 and refused with C0.
* G164 arc: as G163 plus B, the arc's angle (positive, less than a turn), which the steps must make.
* P Q R S T U V: numbers of points not to machine (point 1, machined by the cycle's block, cannot be
  skipped).

Kept verbatim (``NativeCode``), because the reference leaves them open [?]: G165 (the chord pattern: its
words are unverified) and ranges of skipped points (the reference says ranges exist, not how they are
written: a fractional point number such as ``P2.005`` is not guessed at). Such a block round-trips to
Fagor byte for byte and is refused with a located error by every other target and by the simulator
(``toolpath``, ``verify``), as is a pattern with computed words where the program is not run.
Refused with a located error: negative lengths or steps along a side, and any pattern outside the G17
plane (which axes X and Y name in G18/G19 is not documented).
The F of G163/G164 is the feed between points only: the cycle keeps its own feed.
"""

from __future__ import annotations

import math
from typing import Callable

from postproc.context import Context
from postproc.errors import ProgramError, UnsupportedError
from postproc.ir.expr import Expr
from postproc.ir import Block, NativeCode
from postproc.patterns import HolePattern, resolve_hole_pattern
from postproc.ir.state import PLANE_AXES

CODES = {160: "line", 161: "parallelogram", 162: "grid", 163: "circle", 164: "arc", 165: "chord"}
"""Fagor's multiple machining codes and the neutral pattern kind each programs."""
CODE_OF_KIND = {kind: code for code, kind in CODES.items()}
SKIP_LETTERS = "PQRSTUV"
"""The letters that name points not to machine."""
LETTERS = {
    "line": "AXIK",
    "parallelogram": "ABXIKYJD",
    "grid": "ABXIKYJD",
    "circle": "XYIKCF",
    "arc": "XYBIKCF",
}
"""The words each pattern takes besides the skipped points."""
MOVES = ("rapid", "linear", "cw", "ccw")
"""C0-C3: how the tool moves between the points of G163/G164."""
WHOLE = 1e-6
"""How close a count must come to a whole number (steps that do not divide a length or a turn)."""


def multiple_machining(block: Block, ctx: Context, code: str, num: str) -> None:
    """Read the pattern ``code`` ("G160" .. "G165", written ``num``) programmed in ``block`` and resolve
    it: the block gets a ``HolePattern`` and the ``CompoundMotion`` of the active cycle at every
    machined point. The Fagor block syntax calls this instead of its word rules, so the words are read
    here from ``block.words`` (a computed one's value is in ``block.values``). G165 and skipped ranges
    are kept verbatim (see the module docstring). Raises a located ``ProgramError`` for a combination
    the controller or the reference does not define."""
    name = code
    at_code = ctx.at(block, ctx.column_of(block, "G", num) if block.text else 1)
    kind = CODES.get(int(code[1:]))
    if kind is None:
        raise ProgramError(f"{name} is not a multiple machining code (G160-G164)", at_code)
    if kind == "chord":
        _verbatim(block, ctx, f"{name} (multiple machining along a chord, whose words the reference leaves "
                              "unverified)")
        return

    def fail(message: str, letter: str | None = None) -> ProgramError:
        if letter is not None and letter in values:
            return ProgramError(message, ctx.at(block, ctx.column_of(block, letter)))
        return ProgramError(message, at_code)

    values: dict[str, float] = {}
    computed = False
    allowed = LETTERS[kind] + SKIP_LETTERS
    for letter, text in block.words:
        up = letter.upper()
        if up == "N" or (up == "G" and text == num):
            continue
        if up == "G":
            raise ProgramError(f"{name} takes no other G code (G{text}): program it in a block of its own",
                               ctx.at(block, ctx.column_of(block, "G", text)))
        if up not in allowed:
            raise ProgramError(f"{name} takes no {up} word (its words: {' '.join(allowed)})",
                               ctx.at(block, ctx.column_of(block, letter, text)))
        if up in values:
            raise ProgramError(f"{name} has {up} twice", ctx.at(block, ctx.column_of(block, letter, nth=2)))
        value = block.values.get(up)
        if isinstance(value, Expr):
            computed = True
            values[up] = 0.0
            continue
        try:
            values[up] = float(text)
        except ValueError:
            raise ProgramError(f"{name} {up}{text} is not a number", ctx.at(block, ctx.column_of(block, letter)))
    if computed:
        _verbatim(block, ctx, f"{name} with computed words")
        return
    ranges = [letter for letter in SKIP_LETTERS if letter in values and not float(values[letter]).is_integer()]
    if ranges:
        _verbatim(block, ctx, f"{name} {ranges[0]}{values[ranges[0]]:g}: a range of points to skip (its notation "
                              "is unverified)")
        return
    plane_section = block.sections.get("Plane")
    plane = getattr(plane_section, "plane", ctx.state.plane)
    if plane != "XY":
        raise fail(f"{name} outside the G17 plane is not supported (which axes its X and Y name in G18 and "
                   "G19 is unverified)")

    def number(letter: str) -> float | None:
        return values.get(letter)

    skip = _skipped(number, fail, name)
    if kind in ("line", "parallelogram", "grid"):
        pattern = _sided(kind, number, fail, name, skip)
    else:
        pattern = _round(kind, number, fail, name, skip)
    resolve_hole_pattern(block, pattern, ctx, name, at_code)


def _sided(kind: str, number: Callable[[str], float | None], fail: Callable[..., ProgramError], name: str,
           skip: tuple[int, ...]) -> HolePattern:
    count, step = _side(number, fail, name, "XIK")
    angle = number("A") or 0.0
    if kind == "line":
        return _checked(fail, name, lambda: HolePattern(kind, count, step, angle=angle, skip=skip))
    count2, step2 = _side(number, fail, name, "YJD")
    between = number("B")
    if between is None:
        between = 90.0
    if math.remainder(between, 180.0) == 0.0:
        raise fail(f"{name} angle B{between:g} between the sides makes no parallelogram", "B")
    return _checked(fail, name, lambda: HolePattern(kind, count, step, angle=angle, count2=count2, step2=step2,
                                                    angle2=between, skip=skip))


def _side(number: Callable[[str], float | None], fail: Callable[..., ProgramError], name: str,
          letters: str) -> tuple[int, float]:
    """(points, step) of one side from two of its length, step and count words."""
    length_letter, step_letter, count_letter = letters[0], letters[1], letters[2]
    length, step, count = number(length_letter), number(step_letter), number(count_letter)
    given = [letter for letter, value in zip(letters, (length, step, count)) if value is not None]
    if len(given) != 2:
        raise fail(f"{name} needs exactly two of {length_letter} (length), {step_letter} (step) and "
                   f"{count_letter} (number of points), not {len(given)}",
                   given[-1] if len(given) > 2 else None)
    for letter, value in ((length_letter, length), (step_letter, step)):
        if value is not None and value <= 0:
            raise fail(f"{name} {letter} must be positive (the angle gives the direction)", letter)
    if count is not None:
        points = _whole(count, fail, name, count_letter)
        if points < 2:
            raise fail(f"{name} {count_letter} must be at least 2 (point 1 included)", count_letter)
        if step is None:
            step = length / (points - 1)  # type: ignore[operator]
        return points, step
    assert length is not None and step is not None  # two of the three, and not the count
    steps = length / step
    if abs(steps - round(steps)) > WHOLE:
        raise fail(f"{name} length {length_letter}{length:g} is not a whole number of steps {step_letter}{step:g}",
                   step_letter)
    return round(steps) + 1, step


def _round(kind: str, number: Callable[[str], float | None], fail: Callable[..., ProgramError], name: str,
           skip: tuple[int, ...]) -> HolePattern:
    centre = {"X": number("X") or 0.0, "Y": number("Y") or 0.0}
    if not any(centre.values()):
        raise fail(f"{name} needs X or Y: the distance from the first point to the centre")
    c = number("C")
    mode = 0 if c is None else _whole(c, fail, name, "C")
    if not 0 <= mode <= 3:
        raise fail(f"{name} C{mode} is not a way to move between points (C0 rapid, C1 feed, C2 clockwise, "
                   "C3 counterclockwise)", "C")
    feed = number("F")
    if mode and feed is None:
        raise fail(f"{name} C{mode} needs the feed F of the moves between points", "C")
    if not mode and feed is not None:
        raise fail(f"{name} F is the feed between points, which C0 (rapid) does not use", "F")
    if feed is not None and feed <= 0:
        raise fail(f"{name} feed F must be positive", "F")
    sweep = 360.0
    if kind == "arc":
        b = number("B")
        if b is None:
            raise fail(f"{name} needs B, the angle of the arc")
        if not 0 < b < 360:
            raise fail(f"{name} B{b:g} must be more than 0 and less than 360 degrees", "B")
        sweep = b
    step_word, count_word = number("I"), number("K")
    if step_word is not None and count_word is not None:
        raise fail(f"{name} takes either the angular step I or the number of points K, not both", "K")
    if step_word is None and count_word is None:
        raise fail(f"{name} needs the angular step I or the number of points K")
    if step_word is not None:
        if step_word == 0:
            raise fail(f"{name} angular step I cannot be 0", "I")
        steps = sweep / abs(step_word)
        if abs(steps - round(steps)) > WHOLE or round(steps) < 1:
            what = "the full circle (360 degrees)" if kind == "circle" else f"the arc B{sweep:g}"
            raise fail(f"{name} angular step I{step_word:g} does not close {what}: the total angular movement "
                       "must be a whole number of steps", "I")
        count = round(steps) + (0 if kind == "circle" else 1)
        step = abs(step_word) if step_word > 0 else -abs(step_word)
    else:
        count = _whole(count_word, fail, name, "K")  # type: ignore[arg-type]
        if count < 2:
            raise fail(f"{name} K must be at least 2 (point 1 included)", "K")
        step = sweep / (count if kind == "circle" else count - 1)
    if count < 2:
        raise fail(f"{name} angular step I{step_word:g} leaves no point but the first", "I")
    move = MOVES[mode]
    if move == "cw":
        step = -abs(step)
    elif move == "ccw":
        step = abs(step)
    return _checked(fail, name, lambda: HolePattern(kind, count, step, center=centre, skip=skip, move=move,
                                                    feed=feed))


def _skipped(number: Callable[[str], float | None], fail: Callable[..., ProgramError], name: str) -> tuple[int, ...]:
    skip: list[int] = []
    for letter in SKIP_LETTERS:
        value = number(letter)
        if value is None:
            continue
        if value < 2:
            raise fail(f"{name} {letter}{value:g}: point 1 is machined by the cycle's own block and cannot be skipped",
                       letter)
        skip.append(int(value))
    return tuple(skip)


def _whole(value: float, fail: Callable[..., ProgramError], name: str, letter: str) -> int:
    if not float(value).is_integer():
        raise fail(f"{name} {letter}{value:g} must be a whole number", letter)
    return int(value)


def _checked(fail: Callable[..., ProgramError], name: str, make: Callable[[], HolePattern]) -> HolePattern:
    """The pattern, or its own consistency error (a skipped point beyond the last) located at the code."""
    try:
        return make()
    except ValueError as err:
        raise fail(f"{name}: {err}") from None


def _verbatim(block: Block, ctx: Context, what: str) -> None:
    """A pattern kept as its text (``what`` names it): computed words, whose points are known only when
    the program runs, or a construct the reference leaves unverified [?]. It round-trips to Fagor byte
    for byte; every other target and the simulator refuse it with a located error naming ``what``.
    Where the tool ends in the plane is unknown."""
    block.add(NativeCode(ctx.dialect, what, block.text or ""))
    first, second, _ = PLANE_AXES[ctx.state.plane]
    ctx.state.position[first] = ctx.state.position[second] = None


def pattern_words(pattern: HolePattern, number: Callable[[float], str]) -> list[str]:
    """The words of a pattern block, the code first (``number`` spells a decimal value): the inverse of
    ``multiple_machining`` up to the choice of words (a side by its step and count, a circle by its
    step, or by its count when the points turn counter-clockwise)."""
    words = [f"G{CODE_OF_KIND[pattern.kind]}"]
    if pattern.kind in ("line", "parallelogram", "grid"):
        if pattern.angle:
            words.append("A" + number(pattern.angle))
        if pattern.kind != "line" and pattern.angle2 != 90.0:
            words.append("B" + number(pattern.angle2))
        words += ["I" + number(pattern.step), f"K{pattern.count}"]
        if pattern.kind != "line":
            words += ["J" + number(pattern.step2 or 0.0), f"D{pattern.count2}"]
    else:
        first, second, _ = PLANE_AXES[pattern.plane]
        words += ["X" + number(pattern.center.get(first, 0.0)), "Y" + number(pattern.center.get(second, 0.0))]
        if pattern.kind == "arc":
            words.append("B" + number(abs(pattern.step) * (pattern.count - 1)))
        if pattern.step > 0 and pattern.move != "cw":
            words.append(f"K{pattern.count}")
        else:
            words.append("I" + number(pattern.step))
        mode = MOVES.index(pattern.move)
        if mode:
            words += [f"C{mode}", "F" + number(pattern.feed or 0.0)]
    if len(pattern.skip) > len(SKIP_LETTERS):
        raise UnsupportedError(f"a pattern skips {len(pattern.skip)} points; {words[0]} names at most "
                               f"{len(SKIP_LETTERS)} ({' '.join(SKIP_LETTERS)})")
    words += [f"{letter}{n}" for letter, n in zip(SKIP_LETTERS, pattern.skip)]
    return words
