"""``postproc.simulate.runs._is_axis``, the bit test that replaced ``k in _AXIS_KEYS`` in verify's reading of a
move event's end point: the same answer on every key an event may hold (single letters of any case, digits,
punctuation, characters beyond ASCII, the longer keys of an event) and on any text."""

from __future__ import annotations

import string

from hypothesis import given, strategies as st

from postproc.simulate.runs import _AXIS_KEYS, _is_axis

EVENT_KEYS = ["line", "move", "f", "feed_mode", "controlled", "plane", "cx", "cy", "cz", "held", "still",
              "programmed", "code", "name", "event", "toolpath", ""]


def test_every_single_character_and_event_key() -> None:
    keys = [chr(n) for n in range(0x250)] + list(string.ascii_uppercase) + EVENT_KEYS + ["\U0001F600"]
    for key in keys:
        assert _is_axis(key) == (key in _AXIS_KEYS), repr(key)
    assert sorted(k for k in keys if _is_axis(k)) == sorted("abcuvwxyz")


@given(st.text(max_size=3))
def test_any_text(key: str) -> None:
    assert _is_axis(key) == (key in _AXIS_KEYS)
