"""verify's account of the tool data a translation lost: which tool length, cutter radius compensation or tool
selection in force in the source the translation does not have, and from which line (issue 26: "verify fails
on any ... tool data lost, and says which").

Each simulation records the tool data in force as it changes (``Position.tool_data``: the length in mm of
``G43 H18``, the radius of ``G41 D18``, the tool a ``T`` selects). The verdict stays the comparison's (the
controlled points, the events, the settings): a translation may resolve a length or a radius into its
coordinates (grbl's compensated path, a length written into Z), and then has no such data in force while
it moves the tool exactly as the source does. So these lines only explain a comparison that fails: the first
place, per kind of data, where the two programs' sequences of values in force part.
"""

from __future__ import annotations

import math
from typing import Iterable

from .events import CUTTER_RADIUS, TOOL_LENGTH, TOOL_SELECTION

__all__ = ["lost_tool_data"]

Change = tuple[int, str, str, float]
"""(line, kind, what, value): ``Position.tool_data``."""

VALUE_TOLERANCE = 1e-6
"""Two lengths or radii within this (mm) are the same value: an inch length converted, written with 6 places."""

_NAMES = {TOOL_LENGTH: "tool length", CUTTER_RADIUS: "cutter radius compensation", TOOL_SELECTION: "tool selection"}


def lost_tool_data(changes_in: Iterable[Change], changes_out: Iterable[Change], *, file_in: str,
                   file_out: str, address_in: str = "H", address_out: str = "H") -> list[str]:
    """One line per kind of tool data whose values in force differ between the source (IN) and the
    translation (OUT), at their first difference; none when they agree. ``address_in``, ``address_out``: the
    address each program names a length register by (``Dialect.LENGTH_REGISTER_ADDRESS``)."""
    found_in = [_spelled(c, address_in) for c in changes_in]
    found_out = [_spelled(c, address_out) for c in changes_out]
    lines: list[str] = []
    for kind in (TOOL_SELECTION, TOOL_LENGTH, CUTTER_RADIUS):
        a = _states(c for c in found_in if c[1] == kind)
        b = _states(c for c in found_out if c[1] == kind)
        line = _first_difference(kind, a, b, file_in, file_out)
        if line is not None:
            lines.append(line)
    return lines


def _spelled(change: Change, address: str) -> Change:
    """A length change's neutral record (``positive 18``) as its program names it (``H18``; ``H18 subtracted``,
    ``a length given in the block``)."""
    line, kind, what, value = change
    if kind != TOOL_LENGTH or what == "off":
        return change
    if what == "dynamic":
        return line, kind, "a length given in the block", value
    mode, _, register = what.partition(" ")
    name = f"{address}{register}" if register else f"{address} (the spindle's tool)"
    return line, kind, name if mode == "positive" else f"{name} subtracted", value


def _same(x: float, y: float) -> bool:
    if math.isnan(x) or math.isnan(y):
        return math.isnan(x) and math.isnan(y)
    return abs(x - y) <= VALUE_TOLERANCE


def _states(changes: Iterable[Change]) -> list[Change]:
    """The values in force in order, a value repeated by the next change kept once (``G43 H1`` then ``G43.1 Z..``
    with the same length is no change), without the leading zero ("off") a program may start with: that is where
    every program starts."""
    out: list[Change] = []
    for change in changes:
        if out and _same(out[-1][3], change[3]) and (not math.isnan(change[3]) or out[-1][2] == change[2]):
            continue
        if not out and change[1] != TOOL_SELECTION and change[3] == 0.0:
            continue
        out.append(change)
    return out


def _value(kind: str, change: Change) -> str:
    """``H18 (25.4 mm)``, ``left D18 (radius 5 mm)``, ``T5``."""
    line, _, what, value = change
    if kind == TOOL_SELECTION:
        return what
    if math.isnan(value):
        return f"{what} (a radius the set-up does not give)"
    mm = f"{value:.4f}".rstrip("0").rstrip(".")
    return f"{what} ({mm} mm)" if kind == TOOL_LENGTH else f"{what} (radius {mm} mm)"


def _amount(kind: str, change: Change) -> str:
    """``20 mm``, ``radius 3 mm`` (a radius the set-up does not give: ``an unknown radius``)."""
    if math.isnan(change[3]):
        return "an unknown radius"
    mm = f"{change[3]:.4f}".rstrip("0").rstrip(".") + " mm"
    return mm if kind == TOOL_LENGTH else f"radius {mm}"


def _off(change: Change | None) -> bool:
    return change is None or (change[1] != TOOL_SELECTION and change[3] == 0.0)


def _first_difference(kind: str, a: list[Change], b: list[Change], file_in: str, file_out: str) -> str | None:
    name = _NAMES[kind]
    for i in range(max(len(a), len(b))):
        x = a[i] if i < len(a) else None
        y = b[i] if i < len(b) else None
        if x is not None and y is not None and _same(x[3], y[3]) and (kind != TOOL_SELECTION or x[2] == y[2]):
            continue
        if x is not None and not _off(x):
            where = f"{file_in}:{x[0]}"
            if kind == TOOL_SELECTION:
                if y is None:
                    return f"{name} {x[2]} in the source at {where} is not in the translation"
                return f"{name} {x[2]} in the source at {where} is {y[2]} in the translation ({file_out}:{y[0]})"
            if _off(y) and not any(_same(x[3], other[3]) for other in b[i:]):
                return f"{name} {_value(kind, x)} in force in the source from {where} is not in the translation"
            if _off(y):
                return (f"{name} {_value(kind, x)} in force in the source from {where} is not in the translation "
                        "there" + (f" (off from {file_out}:{y[0]})" if y is not None else ""))
            assert y is not None
            return (f"{name} {_value(kind, x)} in force in the source from {where} is {_amount(kind, y)} in the "
                    f"translation ({y[2]}, {file_out}:{y[0]})")
        if x is not None:  # the source turns it off; the translation keeps what was in force, or another
            kept = y if y is not None and not _off(y) else (b[i - 1] if 0 < i <= len(b) else None)
            if kept is None or _off(kept):
                continue
            return (f"{name} off in the source from {file_in}:{x[0]} is not in the translation: "
                    f"{_value(kind, kept)} is in force there (from {file_out}:{kept[0]})")
        assert y is not None
        if _off(y):
            kept = a[i - 1] if 0 < i <= len(a) else None
            if kept is None or _off(kept):
                continue
            return (f"{name} {_value(kind, kept)} in force in the source from {file_in}:{kept[0]} is off in the "
                    f"translation from {file_out}:{y[0]}")
        return f"{name} {_value(kind, y)} in force in the translation from {file_out}:{y[0]} is not in the source"
    return None
