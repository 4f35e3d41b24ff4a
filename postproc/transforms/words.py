"""What the two program transforms share: the roles of a hole cycle's words, the sections that carry no
length or point, and rewriting a setting kept as written (``G10 ...``, a frame command) with new numbers.
"""

from __future__ import annotations

import re
from typing import Final

from ..cycle_words import CycleWords
from ..cycles.semantics import PECK, SHIFT
from ..cycles.section import CannedCycle
from ..interp.control import ASSIGN, CONTROL, LABEL
from ..errors import ProgramError
from ..frames.frame import PLANE_AXES

INERT: Final = frozenset((
    "BlockDelete", "ProgramStart", "TapeMark", "Plane", "DistanceMode", "WorkOffset", "FeedMode", "SpindleSpeed",
    "SpindleControl", "SpindleOrientation", "ToolSelect", "ToolChange", "Coolant", "Dwell", "ProgramControl",
    "ReturnLevel", "CycleCancel", "CycleCall", "Sequence", "Comments", "MachineFunction", "Generated",
    "SpindleClamp", "XProgramming",
))
"""Sections with no length and no point in them: both transforms pass them untouched (a dwell's seconds,
a spindle's speed, a machine function's code)."""

COMPUTES: Final = frozenset((ASSIGN, CONTROL, LABEL))
"""A program kept symbolically: its words compute from variables whose unit and frame are not known here."""

SYMBOLIC: Final = ("a program kept symbolically (variables, control flow) cannot be {what}: the units or position "
                   "its variables hold are not known here (a target without them gets it flattened)")
COMPUTED: Final = "a computed word cannot be {what} (its variables' unit and frame are not known here)"

_TOKEN: Final = re.compile(r"([A-Za-z])([+-]?(?:\d+\.?\d*|\.\d+))")


def cycle_roles(cycle: CannedCycle, words: CycleWords) -> dict[str, str]:
    """Each of the cycle's programmed letters -> its role: 'first' and 'second' (the hole in the plane),
    'level' (R), 'bottom', 'peck', 'shift', 'dwell' or 'repeat'; a letter with none is an error."""
    first, second, normal = PLANE_AXES[cycle.plane]
    repeat = words.repeat if words.repeat is not None else ("K", "L")
    roles: dict[str, str] = {}
    for letter in cycle.words:
        if letter == first:
            roles[letter] = "first"
        elif letter == second:
            roles[letter] = "second"
        elif letter == words.level:
            roles[letter] = "level"
        elif letter == words.bottom_letter(cycle.plane, normal):
            roles[letter] = "bottom"
        elif letter == words.peck and cycle.kind in PECK:
            roles[letter] = "peck"
        elif letter == words.shift and cycle.kind in SHIFT:
            roles[letter] = "shift"
        elif letter == words.dwell:
            roles[letter] = "dwell"
        elif letter in repeat:
            roles[letter] = "repeat"
        else:
            raise ProgramError(f"the cycle word {letter} has no known role (a length, a position or a count): it "
                               "cannot be converted")
    return roles


def named(key: str, section: object) -> str:
    """How a message names a section: a native construct by what it is (``#SLOPE (acceleration profile)``),
    a pattern or setting by its own description, anything else by its IR name."""
    what = getattr(section, "what", None)
    if isinstance(what, str):
        return what
    describe = getattr(section, "describe", None)
    return str(describe()) if callable(describe) else key


def number_text(value: float) -> str:
    """A number with its decimal point (``10.``, ``-0.25``): read the same by every dialect's rules."""
    text = f"{round(value, 6):.6f}".rstrip("0")
    return "0." if text in ("-0.", "0.") else text


def respell(text: str, values: dict[str, float]) -> str:
    """``text`` (a setting kept as written, words separated by spaces) with the words of ``values``
    given their new numbers; a letter that is not there as a plain number is an error."""
    done: set[str] = set()

    def swap(match: re.Match[str]) -> str:
        letter = match.group(1).upper()
        if letter in values and letter not in done:
            done.add(letter)
            return match.group(1) + number_text(values[letter])
        return match.group(0)

    out = _TOKEN.sub(swap, text)
    missing = set(values) - done
    if missing:
        raise ProgramError(f"{text}: the word {''.join(sorted(missing))} is not a plain number here and cannot be "
                           "rewritten")
    return out
