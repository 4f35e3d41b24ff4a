"""The toolpath's events: their numbers, the header line, the start position, and the settings a
simulation records instead of applying (``verify`` compares those). Compiled with the simulator
(``pyproject.toml [tool.postproc] compiled``): ``num`` runs five times a move."""

from __future__ import annotations

from typing import Any, Final

from mypy_extensions import i64

from ..context import Context
from ..errors import ProgramError
from ..geometry.arcs import PLACES
from ..setup.machine_setup import MachineSetup

UNEVALUATED = "a computed word reaches the simulation unevaluated"
"""The interpreter evaluates every expression first: an ``Expr`` here is a defect, reported where it is."""

Event = dict[str, Any]

HEADER_LOOKAHEAD = 1000
"""Events held back at most while waiting for the first feed move to fix the header's feed mode."""
LINEAR_AXES = frozenset("XYZUVW")
"""Axes converted from inches; rotary axes (A, B, C) are in degrees whatever the length unit."""


_UNITS: Final = 1_000_000
"""A toolpath's numbers count in these units (millionths of a mm): ``num`` rounds to a whole number of them."""
_SCALE: Final = 1e6
_FAST: Final = 1e14
"""``num``'s integer path holds for values below this many units: the units (< 2**47) are exact in a
float, the value's error in units is below 0.012 (half an ulp), and a whole number of units divided by
``_SCALE`` is correctly rounded and integral only when the units are a multiple of ``_UNITS``."""
_TIE: Final = 2.3e-16
"""Relative error of ``value * _SCALE`` (a product's half ulp, 2**-53, with margin): a fraction of a
unit that close to one half may lie on the other side of it, and goes to ``round``."""
_LARGEST: Final = 1e8
"""``all_as_written`` decides below this (a whole number of millionths below 1e14, exact in a float)."""
ROUND: Final = 6755399441055744.0
"""1.5 * 2**52: ``(y + ROUND) - ROUND`` is the integer nearest ``y`` (ties to even), as a float and exactly, for any
``|y| < 2**51``: the sum lies where floats are whole numbers one apart, so its rounding is to the nearest."""
assert _UNITS == 10 ** PLACES == _SCALE
# Final: compiled, a constant is a C constant, not a look-up in the module's dictionary (six a call)


def num(value: float) -> float | int:
    """A number as written to a toolpath: ``round(value, 6)``, integral values as int, never -0, always
    finite (a value beyond the float range fails at its block, rather than as JSON's invalid ``Infinity``).

    ``round(value, 6)`` is the float nearest the decimal that rounds the value to six places, half to
    even; it costs a correctly rounded decimal conversion (about 2,500 instructions, five a move). The
    same result by integer arithmetic: the value in millionths, rounded to the nearest whole one (the
    product's error is far from a half but for near-ties, which go to ``round``), then divided by a
    million (one correctly rounded division of two exact floats: the float nearest the same decimal).
    ``tests/test_toolpath_numbers.py`` holds it to ``round`` on any float and on near-ties."""
    y = value * _SCALE
    if -_FAST < y < _FAST:  # false for nan; an infinity is beyond
        units = i64(y)  # (a machine integer, |units| < 2**47: compiled, no tagged int's checks at each step)
        whole = float(units)
        if whole > y:
            units -= 1  # the floor
            whole -= 1.0
        fraction = y - whole  # exact: both below 2**47
        if abs(fraction - 0.5) > abs(y) * _TIE:
            if fraction > 0.5:
                units += 1
                whole += 1.0
            if units % _UNITS == 0:
                return units // _UNITS  # 0 for -0.0 too
            return whole / _SCALE
    r = round(value, PLACES)
    if r == 0:
        return 0
    if r.is_integer():
        return int(r)
    if r - r != 0.0:  # inf - inf and nan - nan are nan
        raise ProgramError(f"a value beyond the range of a float ({value!r}) cannot be simulated"
                           if value == value else "a value that is not a number (nan) cannot be simulated")
    return r


def all_as_written(values: list[float]) -> bool:
    """``num`` of every value is a float equal to it: each a whole number ``k`` of millionths that is not integral
    (``num`` writes an integral value as an int), as a CAM program's coordinates are. Such a point's list stands
    for the point its event writes as it is: a move keeps its end point's list rather than making a list and a
    float an axis (``CompensatedMoves._offset_line``). The test, a value at a time: it is the float nearest
    ``k / 10**6``, ``k`` its millionths rounded (then ``round(value, 6)``, the float nearest the six-place decimal
    nearest the value, is the value itself: that decimal is ``k / 10**6``, six-place decimals lying far wider
    apart than a float's ulp below 1e8); beyond 1e8 never (the general path calls ``num``). One loop, no call a
    value (compiled, ~80 instructions a value where a call each cost ~140). ``tests/test_toolpath_numbers.py``
    holds it to ``round``. The rounding and the tests in floats (``ROUND``: no machine integer made and made a
    float again, ~55 instructions a value less, branch tpmove): ``k`` is the integer nearest the value's millionths
    (a tie, where the two roundings could differ, is never a float's as written: such a float lies within 0.03 of its
    ``k``); ``k`` is a multiple of a million exactly when the value is integral (below 1e8 a float is a millionth
    or more from any other decimal of six places)."""
    for value in values:  # (compiled, an item taken unchecked: an index was a checked call, ~30 instructions)
        if not -_LARGEST < value < _LARGEST:  # (also nan)
            return False
        k = (value * _SCALE + ROUND) - ROUND  # (|value * 1e6| < 1e14 < 2**51)
        if k / _SCALE != value or (value + ROUND) - ROUND == value:  # (not as written, or integral)
            return False
    return True


def start_position(setup: MachineSetup) -> dict[str, float]:
    """Where a program starts, per machine axis, in mm (rotary axes at 0)."""
    m = setup.machine
    start = {"X": m.start_x, "Y": m.start_y, "Z": m.start_z}
    return {a: float(start.get(a, 0.0)) * (m.mm() if a in LINEAR_AXES else 1.0) for a in m.axes}



def differs(a: float | int, b: float | int) -> bool:
    """``a != b`` of two of ``num``'s numbers: compiled, two floats compared unboxed, where ``!=`` of two values of
    unknown type is Python's rich comparison (~90 instructions; twice a move under a tool length)."""
    if isinstance(a, float) and isinstance(b, float):
        return a != b
    return a != b


def header(ctx: Context, feed_mode: str | None, program_units: str = "mm") -> Event:
    """The first line of a toolpath; keys beyond the fixed three only when they apply. ``program_units``:
    the units of the program's first move (lengths here are mm whatever they are; a backplot labels its
    drawing in the program's own)."""
    head: Event = {"toolpath": 1, "units": "mm", "dialect": ctx.dialect}
    if ctx.diameter:
        head["x_mode"] = "diameter"
    if feed_mode is not None and feed_mode != "per_min":
        head["feed_mode"] = feed_mode
    if program_units == "inch":
        head["program_units"] = "inch"
    return head



TOUCH_OFF = ("tool_entry_at_point", "tool_entry_at_point_9")
"""Tool tables whose length the tool's position decides: in the active work system, in work system 9."""

UNSIMULATED = {"CutterCompensation": "cutter compensation", "WorkOffset": "work offset",
               "PathControl": "path control", "SpindleSpeed": "spindle speed",
               "SpindleMode": "spindle speed mode", "SpindleClamp": "spindle speed clamp"}
"""Settings the simulation does not apply, by section key: ``verify`` compares their changes instead.
Cutter compensation is among them only for a dialect without ``CUTTER_RULES``; the work offset is
recorded although a G10's values are applied (the set-up's are not: the path stays in work
coordinates). A lathe's spindle speed mode (constant surface speed or rpm) and the clamp of constant surface
speed are the spindle speed's meaning: a translation that lost a G96 or its clamp cuts the same path at
another speed, so verify lists it as it lists a different S (issue 29)."""
LATHE_TOOL_OFFSET: Final = "lathe tool offset"
"""The setting a lathe's tool offset selection is recorded as (``Moves.lathe_offset``)."""
TOOL_LENGTH: Final = "tool length"
CUTTER_RADIUS: Final = "cutter radius"
TOOL_SELECTION: Final = "tool selection"
"""The kinds of tool data a simulation records as they change (``Position.tool_data``)."""
MOVES_THE_TOOL = frozenset(("cutter compensation", "work offset", "path control", "tool offset data",
                            LATHE_TOOL_OFFSET))


def _setting_text(key: str, section: Any) -> str | None:
    """How a setting reads in a verify report (None: it changes nothing, e.g. a one-shot exact stop)."""
    if key == "CutterCompensation":
        return section.mode if section.register is None else f"{section.mode} D{section.register}"
    if key == "ToolLengthOffset":
        return section.mode if section.register is None else f"{section.mode} H{section.register}"
    if key == "WorkOffset":
        return str(section.index)
    if key == "PathControl":
        return None if section.one_shot else section.mode.replace("_", " ")
    if key == "SpindleMode":
        return "constant surface speed" if section.mode == "css" else "rpm"
    if key == "SpindleClamp":
        return f"{section.rpm:g} rpm" if isinstance(section.rpm, (int, float)) else None
    return f"S{section.rpm:g}" if isinstance(section.rpm, (int, float)) else None
