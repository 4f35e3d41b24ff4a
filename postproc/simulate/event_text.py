"""A toolpath event as its JSON line, written here rather than by json's encoder for the events a
toolpath is made of (compiled with the simulator: a CAM program writes one a block).

The text is json's: ``json.JSONEncoder(allow_nan=False).encode`` (``", "`` and ``": "`` between items,
ASCII escapes, a float as ``float.__repr__``), held to it on any event by ``tests/test_toolpath_numbers.py``.
Two things make json's encoder cost what a simulated block costs: it escapes every key of every event
again, and it spells each float with ``float.__repr__``, a shortest round-trip conversion of about 3,500
instructions (six floats a move under a tool length). A toolpath's floats are ``num``'s: a whole number of
millionths, nearest the decimal of those millionths. Such a float's shortest round-trip spelling is that
decimal (at most 14 significant digits below 1e8, and two decimals of at most 15 digits are never the
same float), which integer arithmetic writes; a float that is not one (``units / 1e6`` differs) or lies
where ``repr`` writes an exponent goes to ``float.__repr__``. An event holding anything but str keys and
str, int, bool, None, float or such a dict values is handed whole to ``fallback`` (json's own encoder).
"""

from __future__ import annotations

from json.encoder import encode_basestring_ascii
from typing import Any, Callable, Final

from ..geometry import PLACES

_PLACES: Final = 6
_UNITS: Final = 1_000_000
_SCALE: Final = 1e6
_SMALLEST: Final = 1e-4
"""``float.__repr__`` writes an exponent below this (``9e-05``) and from 1e16 on."""
_LARGEST: Final = 1e8
"""Below this a whole number of millionths has at most 14 digits (one float per decimal)."""
_KEYS: Final[dict[str, str]] = {}
"""Key -> its text with the separator (``'"x": '``): a toolpath has a dozen keys."""
_WORDS: Final[dict[str, str]] = {}
"""Short string values (``"feed"``, ``"XY"``, ``"cw"``) -> their text; at most ``_MOST_WORDS`` kept."""
_MOST_WORDS: Final = 512
_FLOATS: Final[dict[float, str]] = {}
"""Float -> its text, for the floats ``float_text`` spells by integer arithmetic; at most ``_MOST_FLOATS``."""
_MOST_FLOATS: Final = 4096
_ZEROS: Final = "00000"
"""Zeros between the point and the digits of a value below 0.1 (at most five: below 1e-4 is ``repr``'s)."""
assert _PLACES == PLACES and _UNITS == 10 ** PLACES == _SCALE
# Final: compiled, a constant is a C constant, not a look-up in the module's dictionary (17 a float)


def float_text(value: float) -> str:
    """``float.__repr__(value)``; ValueError for a value that is not finite (json's ``allow_nan=False``).

    The texts of the integer path are kept (``_FLOATS``, emptied when full): a move's controlled point
    repeats the programmed one on the axes its offset does not move, and a feed or a depth is written
    again and again (a fanuc toolpath finds about half its floats there)."""
    text = _FLOATS.get(value)
    if text is not None:
        return text
    if _SMALLEST <= value < _LARGEST or -_LARGEST < value <= -_SMALLEST:
        units = int(value * _SCALE + (0.5 if value > 0.0 else -0.5))
        if units % _UNITS != 0 and units / _SCALE == value:
            magnitude = -units if units < 0 else units
            places = _PLACES
            while magnitude % 10 == 0:  # not 0: the fraction is not
                magnitude //= 10
                places -= 1
            digits = str(magnitude)  # one conversion: the point goes in by slicing
            cut = len(digits) - places
            if cut > 0:
                text = f"{'-' if units < 0 else ''}{digits[:cut]}.{digits[cut:]}"
            else:
                text = f"{'-' if units < 0 else ''}0.{_ZEROS[:-cut]}{digits}"
            if len(_FLOATS) >= _MOST_FLOATS:
                _FLOATS.clear()
            _FLOATS[value] = text
            return text
    if value - value != 0.0:  # inf - inf and nan - nan are nan
        raise ValueError(f"Out of range float values are not JSON compliant: {value!r}")
    return float.__repr__(value)


def _key_text(key: str) -> str:
    text = _KEYS.get(key)
    if text is None:
        text = encode_basestring_ascii(key) + ": "
        if len(_KEYS) < _MOST_WORDS:
            _KEYS[key] = text
    return text


def _value_text(value: object) -> str | None:
    """A scalar's text, a dict's (the ``controlled`` point), or None: not an event's value. Subclasses
    as json writes them: a bool before an int, an int or float by its base's ``__repr__``."""
    if isinstance(value, float):
        return float_text(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if type(value) is int:
        return str(value)  # int's own spelling, without a method look-up (a line number each event)
    if isinstance(value, int):
        return int.__repr__(value)
    if isinstance(value, str):
        text = _WORDS.get(value)
        if text is None:
            text = encode_basestring_ascii(value)
            if len(value) <= 16 and len(_WORDS) < _MOST_WORDS:
                _WORDS[value] = text
        return text
    if value is None:
        return "null"
    if isinstance(value, dict):
        return _dict_text(value)
    return None


def _dict_text(items: dict[Any, Any]) -> str | None:
    if not items:
        return "{}"
    parts: list[str] = ["{"]  # joined once: no string made per item
    for key, value in items.items():
        if not isinstance(key, str):
            return None
        text = _value_text(value)
        if text is None:
            return None
        if len(parts) > 1:
            parts.append(", ")
        parts.append(_key_text(key))
        parts.append(text)
    parts.append("}")
    return "".join(parts)


def event_text(event: dict[Any, Any], fallback: Callable[[Any], str]) -> str:
    """The JSON text of one event (without its line end)."""
    text = _dict_text(event)
    return fallback(event) if text is None else text
