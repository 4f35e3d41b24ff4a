"""verify's comparison computes its distances as ``math.hypot`` of the differences
(``postproc.simulate.compare``): the same float as ``math.dist`` of the two points, which it replaced."""

from __future__ import annotations

import math

from hypothesis import given, strategies as st

from postproc.simulate.compare import _dist

_COORD = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e300, max_value=1e300)


@given(st.dictionaries(st.sampled_from("xyzabc"), _COORD, min_size=1),
       st.dictionaries(st.sampled_from("xyzabc"), _COORD))
def test_distance_is_math_dist_bit_for_bit(a: dict[str, float], b: dict[str, float]) -> None:
    expected = math.dist([a[k] for k in a], [b.get(k, 0.0) for k in a])
    assert _dist(a, b) == expected
