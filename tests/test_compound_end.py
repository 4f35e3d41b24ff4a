"""Where an expanded construct leaves the point (``postproc.lowering.point_after.compound_end``), found once a
construct and kept on its ``CompoundMotion`` (the cutter resolver and the tool length timing both ask it of every
expanded hole), and the comment text cleaning that every expanded hole's note passes through.

Independent checks: the end derived by hand from the rule the docstring states (each axis at its last move's
number, a computed number unknown, a move other than G0-G3 loses the point, items that are not moves change
nothing), computed here from the items by a separate walk from the last item back; a kept answer forgotten when
the items are replaced (a step that rewrites an expansion, ``arcs.settle``, ``_handle_orientation``).
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from postproc.ir import CompoundMotion, Dwell, Feed, Motion, Section
from postproc.ir.expr import Var
from postproc.lowering.point_after import compound_end
from postproc.syntaxes.comments import CommentSyntax

_VALUE = st.one_of(st.floats(-1e4, 1e4, allow_nan=False), st.builds(Var, name=st.sampled_from(["a", "b"])))
_MOTION = st.builds(Motion, st.sampled_from(["rapid", "linear", "cw", "ccw", "home", "home2"]),
                    st.dictionaries(st.sampled_from("XYZA"), _VALUE, max_size=4))
_ITEM = st.one_of(_MOTION, st.builds(Feed, st.floats(1.0, 1e3)), st.builds(Dwell, st.floats(0.0, 5.0)))


def _by_hand(items: list[Section]) -> dict[str, float | None] | None:
    """The docstring's rule, walked from the last item back: an axis takes the number of the last move that
    names it; any reference return among the moves loses the point."""
    if any(isinstance(item, Motion) and item.mode not in ("rapid", "linear", "cw", "ccw") for item in items):
        return None
    end: dict[str, float | None] = {}
    for item in reversed(items):
        if isinstance(item, Motion):
            for axis, value in item.axes.items():
                if axis not in end:
                    end[axis] = value if isinstance(value, float) else None
    return end


@given(st.lists(_ITEM, max_size=12), st.lists(_ITEM, max_size=12))
def test_compound_end_is_the_last_move_of_each_axis_and_follows_new_items(first: list[Section],
                                                                         second: list[Section]) -> None:
    compound = CompoundMotion("drill", list(first))
    assert compound_end(compound) == _by_hand(first)
    assert compound_end(compound) == _by_hand(first)  # asked again (the kept answer)
    compound.items = list(second)  # a step rewrote the expansion: its end is found again
    assert compound_end(compound) == _by_hand(second)


def test_a_lazy_expansion_is_made_when_its_end_is_asked() -> None:
    made: list[int] = []

    def make() -> list[Section]:
        made.append(1)
        return [Motion("rapid", {"X": 1.0, "Y": 2.0}), Motion("linear", {"Z": -3.0}), Motion("rapid", {"Z": 2.0})]

    compound = CompoundMotion.lazy("drill", make)
    assert compound_end(compound) == {"X": 1.0, "Y": 2.0, "Z": 2.0}
    assert compound_end(compound) == {"X": 1.0, "Y": 2.0, "Z": 2.0} and made == [1]


_BREAKS = [*map(chr, range(0x20)), "\x7f", "\x85", "\u2028", "\u2029"]


@given(st.text(alphabet=st.sampled_from(["A", "1", ".", " ", "(", ")", "é", "Ø", "\u00a0", *_BREAKS]), max_size=40))
def test_comment_text_has_no_line_break_or_control_character(text: str) -> None:
    """Each line break or control character becomes a space and nothing else changes but the parentheses,
    whether or not the text has one (the common text skips the table)."""
    syntax = CommentSyntax(parens=True)
    safe = syntax.inside(text)
    expected = "".join(" " if ch in _BREAKS else "[" if ch == "(" else "]" if ch == ")" else ch for ch in text)
    assert safe == expected
