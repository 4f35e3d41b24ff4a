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
assert _PLACES == PLACES and _UNITS == 10 ** PLACES == _SCALE
# Final: compiled, a constant is a C constant, not a look-up in the module's dictionary (17 a float)


def float_text(value: float) -> str:
    """``float.__repr__(value)``; ValueError for a value that is not finite (json's ``allow_nan=False``)."""
    if _SMALLEST <= value < _LARGEST or -_LARGEST < value <= -_SMALLEST:
        units = int(value * _SCALE + (0.5 if value > 0.0 else -0.5))
        magnitude = -units if units < 0 else units
        whole = magnitude // _UNITS
        fraction = magnitude - whole * _UNITS
        if fraction != 0 and units / _SCALE == value:
            digits = str(fraction + _UNITS)  # "1" and the six digits, leading zeros kept
            end = _PLACES + 1
            while fraction % 10 == 0:
                fraction //= 10
                end -= 1
            return f"{'-' if units < 0 else ''}{whole}.{digits[1:end]}"
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


def _dict_text(items: dict[Any, Any], written: list[tuple[object, str]] | None = None) -> str | None:
    """``items`` as JSON. ``written``: the floats of the enclosing event with their texts; a value that is
    the same object is not spelt again (a controlled point shares the programmed point's floats on the axes
    its offset does not move: two of a move's six floats under a tool length)."""
    if not items:
        return "{}"
    parts: list[str] = ["{"]  # joined once: no string made per item
    floats: list[tuple[object, str]] = []
    for key, value in items.items():
        if not isinstance(key, str):
            return None
        text: str | None = None
        if written is not None:
            for prior, prior_text in written:
                if prior is value:
                    text = prior_text
                    break
        if text is None:
            if isinstance(value, dict):
                text = _dict_text(value, floats)
            else:
                text = _value_text(value)
                if text is not None and written is None and isinstance(value, float):
                    floats.append((value, text))
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
