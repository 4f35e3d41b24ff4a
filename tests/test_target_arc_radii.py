"""The modal step's judgement of a translated arc by the target's rule (``postproc.syntaxes.modal_state``,
``_target_accepts``) accepts at once an arc whose radii differ by no more than the rule's absolute limit, for a
target that runs an accepted arc as a spiral: held to the rule's own arithmetic (``rule_allows``) on random rules
and radii (the radii it is handed are the ones it computed: the same ``hypot`` of the same numbers)."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from postproc.geometry.arc_end import SPIRAL, ArcEndRule
from postproc.geometry.arc_end_math import rule_allows

limits = st.floats(min_value=0.0, max_value=1.0)
radii = st.floats(min_value=0.0, max_value=1e4)


@settings(max_examples=500, deadline=None)
@given(metric=limits, inch=limits, relative=st.sampled_from([0.0, 0.001, 0.01]), ceiling=st.sampled_from([0.0, 10.0,
       100.0]), of_start=st.booleans(), r0=radii, r1=radii, in_inch=st.booleans(),
       chord=st.floats(min_value=0.0, max_value=2e4))
def test_a_difference_within_the_absolute_limit_is_one_the_rule_allows(
        metric: float, inch: float, relative: float, ceiling: float, of_start: bool, r0: float, r1: float,
        in_inch: bool, chord: float) -> None:
    rule = ArcEndRule(metric, inch, relative, ceiling, of_start, SPIRAL)
    if abs(r0 - r1) <= (inch if in_inch else metric):
        assert rule_allows(rule, r0, r1, in_inch, chord)


def test_grbls_rule_allows_beyond_its_absolute_limit_too() -> None:
    """Not vacuous: the shortcut is the absolute limit only; the relative one is the rule's arithmetic's."""
    rule = ArcEndRule(0.005, 0.005 / 25.4, 0.001, 100.0, True, SPIRAL)
    assert rule_allows(rule, 100.0, 100.05, False) and abs(100.0 - 100.05) > rule.metric
