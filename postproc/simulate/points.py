"""A point of a toolpath as verify's normalising reads it (``postproc.simulate.runs``): a tuple of axis keys and a
list of floats in their order (``postproc.simulate.normal_move``), read from a ``MoveRecord`` by field or from an
event's dictionary; a key looked for where it stood in the other point first; distances with the first three
axes in unboxed locals (``beyond``: ``hypot`` only where a sum of squares cannot decide). Compiled with the
normalising (``pyproject.toml [tool.postproc] compiled``)."""

from __future__ import annotations

import math
from typing import Any, Final

from mypy_extensions import mypyc_attr

from ..geometry.arcs import PLANE_INDEX
from .events import Event
from .move_record import MoveRecord

_hypot: Final = math.hypot
"""Compiled, ``math.hypot`` is an attribute look-up on the module each call; a Final is a C static."""

_AXIS_KEYS: Final = frozenset("xyzabcuvw")
_AXIS_BITS: Final = 0x3f00007  # bit n: chr(ord("a") + n) is in _AXIS_KEYS (a, b, c, u, v, w, x, y, z)
assert _AXIS_BITS == sum(1 << (ord(k) - 97) for k in _AXIS_KEYS)

Keys = tuple[str, ...]


def _is_axis(k: str) -> bool:
    """``k in _AXIS_KEYS`` by the letter's bit: compiled, ``ord`` and a shift are a few instructions where a
    frozenset look-up is a call through Python's set (~125 instructions, four an event in ``_event_point``)."""
    if len(k) != 1:
        return False
    n = ord(k) - 97
    return 0 <= n < 26 and (_AXIS_BITS >> n) & 1 == 1


# -- points: axis keys and their values ------------------------------------------------------------

def key_index(keys: Keys, k: str, hint: int) -> int:
    """Where ``k`` stands in ``keys`` (-1: not there), looked for at ``hint`` first: the points of one simulation
    share their keys, so a key stands where it stood in the other point."""
    if hint < len(keys) and keys[hint] == k:
        return hint
    for i in range(len(keys)):
        if keys[i] == k:
            return i
    return -1


def point_value(keys: Keys, values: list[float], k: str, hint: int) -> float:
    """The value of ``k`` in a point (0.0 where it has none: an axis a point lacks counts from 0)."""
    i = key_index(keys, k, hint)
    return values[i] if i >= 0 else 0.0


@mypyc_attr(allow_interpreted_subclasses=True)
class Steps:
    """The per-axis differences of two points (a move's steps, the distance of a pair's ends) in the form ``beyond``
    and ``_norm`` take them: the first three as unboxed fields (``d0``, ``d1``, ``d2``; 0.0 where there are fewer),
    any further one in ``more``, ``n`` how many. The one loop that collects them for the normalising
    (``runs.Normaliser``) and for the comparison (``compare._differ``): each owner keeps one and ``clear``s it, so
    the steps cost no object a move (compiled, a list boxes each float)."""

    def __init__(self) -> None:
        self.d0 = 0.0
        self.d1 = 0.0
        self.d2 = 0.0
        self.n = 0
        self.more: list[float] | None = None
        """The steps after the third (None: there are none; a new list each time, never changed once given)."""

    def clear(self) -> None:
        self.d0 = self.d1 = self.d2 = 0.0
        self.n = 0
        self.more = None

    def add(self, d: float) -> None:
        """The next axis's step."""
        n = self.n
        if n == 0:
            self.d0 = d
        elif n == 1:
            self.d1 = d
        elif n == 2:
            self.d2 = d
        else:
            more = self.more
            if more is None:
                more = self.more = []
            more.append(d)
        self.n = n + 1


def _floats(values: list[float | int]) -> list[float]:
    """A record's values as floats: the list itself where every value is one (a record's lists are never
    changed: ``postproc.simulate.move_record``), else a copy with each int converted."""
    for v in values:
        if not isinstance(v, float):
            return [_real(x) for x in values]
    return values


def _record_point(record: MoveRecord, all_axes: bool) -> tuple[Keys, list[float]]:
    """The end point of a straight move's record: its controlled point where it has one, read by field. Its keys are
    the machine's axes, each in both points. ``all_axes``: every key is an axis key (``_all_axes`` of the record's
    keys, one tuple a simulation: tested once, not a key a move)."""
    controlled = record.controlled
    values = record.point if controlled is None else controlled
    if all_axes:
        return record.keys, _floats(values)
    keys: list[str] = []
    floats: list[float] = []
    record_keys = record.keys
    for i in range(len(record_keys)):
        k = record_keys[i]
        if _is_axis(k):
            keys.append(k)
            floats.append(_real(values[i]))
    return tuple(keys), floats


def _event_point(ev: Event, controlled: Event | None) -> tuple[Keys, list[float]]:
    """The end point of a move event, in its order (the machine's axes): its controlled point where it has
    one, as ``compare._controlled`` gives it (the controlled axes replace the programmed ones in place, any other
    follows). A number is converted as its type: compiled, ``float(v)`` of a value of unknown type is a call
    of the builtin through Python (~250 instructions)."""
    keys: list[str] = []
    values: list[float] = []
    matched = 0
    for k, v in ev.items():
        if _is_axis(k):
            c = None if controlled is None else controlled.get(k)
            if c is None:
                x = _real(v)
            else:
                x = _real(c)
                matched += 1
            keys.append(k)
            values.append(x)
    if controlled is not None and matched != len(controlled):  # an arc's centre, or an axis the programmed
        for k, c in controlled.items():                        # point does not name
            if _is_axis(k) and k not in keys:
                keys.append(k)
                values.append(_real(c))
    return tuple(keys), values


def _all_axes(keys: Keys) -> bool:
    """Every key of a record's keys is an axis key."""
    for k in keys:
        if not _is_axis(k):
            return False
    return True


def _real(v: Any) -> float:
    """``float(v)`` of a toolpath's number, an int or a float mostly."""
    if isinstance(v, float):
        return v
    if isinstance(v, int):
        return float(v)
    return float(v)


def _plane_point(keys: Keys, values: list[float], plane: str) -> tuple[float, float]:
    i, j, _ = PLANE_INDEX[plane]
    return point_value(keys, values, "xyz"[i], i), point_value(keys, values, "xyz"[j], j)


def norm(values: list[float]) -> float:
    """``math.hypot(*values)`` (it scales: no overflow near the float range). Compiled, a call of a fixed number
    of arguments is a vector call, where ``*`` of a list builds a tuple and calls through Python (~450
    instructions more)."""
    n = len(values)
    if n == 3:
        return _hypot(values[0], values[1], values[2])
    if n == 2:
        return _hypot(values[0], values[1])
    return _hypot(*values)


def _norm(a: float, b: float, c: float, n: int, rest: list[float] | None) -> float:
    """``norm`` of ``n`` components held as ``beyond``'s are (``a``, ``b``, ``c`` the first three, ``rest`` those
    after the third)."""
    if rest is not None:
        return _hypot(a, b, c, *rest)
    if n == 3:
        return _hypot(a, b, c)
    if n == 2:
        return _hypot(a, b)
    if n == 1:
        return _hypot(a)
    return 0.0


def beyond(a: float, b: float, c: float, n: int, rest: list[float] | None, limit: float) -> bool:
    """``math.hypot(*components) > limit`` of ``n`` components (``a``, ``b``, ``c`` the first three, 0.0 where
    there are fewer; ``rest`` those after the third), exactly: the plain sum of squares decides where it lies
    more than a millionth of ``limit``'s square from it (it is within a few ulps of the true square: the
    answer cannot differ there), ``hypot`` only in between or where the sum overflows, underflows or is not a
    number (compiled, ``hypot`` is a call through Python, ~850 instructions, where the squares are a few)."""
    q = a * a + b * b + c * c
    if rest is not None:
        for v in rest:
            q += v * v
    square = limit * limit
    if q > square * 1.000001 and q < _INF:
        return True
    if q < square * 0.999999 and q > 0.0:
        return False
    if rest is None and a == 0.0 and b == 0.0 and c == 0.0:  # two points that agree exactly (a translation that
        return 0.0 > limit                                   # writes the source's numbers): no call of hypot
    if rest is not None:
        return _hypot(a, b, c, *rest) > limit
    if n == 3:
        return _hypot(a, b, c) > limit
    if n == 2:
        return _hypot(a, b) > limit
    return (_hypot(a) if n == 1 else 0.0) > limit


_INF: Final = math.inf
