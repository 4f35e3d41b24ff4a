"""How a toolpath writes its numbers and its lines: ``toolpath.num`` against its definition on any float,
and the JSON lines encoder of a run (``export.event_encoder``) against ``json.JSONEncoder(allow_nan=False)
.encode``, the definition of the format, on any event."""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import given, settings, strategies as st

from postproc.errors import ProgramError
from postproc.commands.export import event_encoder
from postproc.simulate.toolpath import num


@settings(max_examples=500, deadline=None)
@given(value=st.floats(allow_nan=True, allow_infinity=True))
def test_num_rounds_to_six_places_integral_as_int_and_refuses_what_is_not_finite(value: float) -> None:
    if not math.isfinite(value):
        with pytest.raises(ProgramError, match="nan|beyond the range of a float"):
            num(value)
        return
    r = round(value, 6)
    written = num(value)
    if r.is_integer():
        assert type(written) is int and written == int(r)  # -0.0 and 0.0 as 0
    else:
        assert type(written) is float and written == r


FLOATS = st.one_of(st.floats(allow_nan=False, allow_infinity=False), st.sampled_from([0.0, -0.0, 1.5, -2.25]))
SCALARS = st.one_of(st.integers(-10**20, 10**20), FLOATS, st.booleans(), st.none(), st.text(max_size=8))
VALUES = st.one_of(SCALARS, st.lists(SCALARS, max_size=3), st.dictionaries(st.text(max_size=3), SCALARS, max_size=4))
EVENTS = st.dictionaries(st.one_of(st.text(max_size=6), st.integers(0, 9)), VALUES, max_size=8)
ENCODER = event_encoder()


@settings(max_examples=500, deadline=None)
@given(event=EVENTS)
def test_the_encoder_writes_what_json_writes(event: dict[str, object]) -> None:
    assert ENCODER(event) == json.JSONEncoder(allow_nan=False).encode(event)


@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan])
def test_the_encoder_refuses_what_is_not_finite(bad: float) -> None:
    with pytest.raises(ValueError):
        ENCODER({"line": 3, "move": "feed", "x": bad})
    with pytest.raises(ValueError):
        ENCODER({"line": 3, "move": "feed", "controlled": {"x": bad}})
