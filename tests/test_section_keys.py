"""``postproc.ir.keys``: the per-block tests every lowering step asks first, against their plain meaning."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from postproc.frames.lowering import _WATCHED as FRAMES
from postproc.grbl_family.lengths import _WATCHED as GRBL_LENGTHS
from postproc.ir import Section
from postproc.ir.keys import only_move, watches_none
from postproc.isg_family.tool_data import _WATCHED as ISG_TOOL_DATA
from postproc.lowering.length_timing import _STATE as LENGTH_TIMING
from postproc.frames.measured_entries import _WATCHED as MEASURED

KEYS = ("Motion", "Sequence", "Units", "DataSetting", "ToolLengthOffset", "Comments", "Coolant", "DistanceMode",
        "CutterCompensation", "FrameChange", "Plane")
blocks = st.lists(st.sampled_from(KEYS), unique=True, max_size=5).map(lambda keys: {k: Section() for k in keys})
watched_sets = st.frozensets(st.sampled_from(KEYS[2:]))


@given(blocks)
def test_only_move_is_a_motion_and_at_most_a_block_number(sections: dict[str, Section]) -> None:
    assert only_move(sections) == ("Motion" in sections and set(sections) <= {"Motion", "Sequence"})


@given(blocks, watched_sets)
def test_watches_none_is_disjointness(sections: dict[str, Section], watched: frozenset[str]) -> None:
    assert watches_none(sections, watched) == watched.isdisjoint(sections)


def test_no_step_watches_what_only_move_passes() -> None:
    """``watches_none`` answers True for a move and its block number whatever the set: each step's set names
    neither (the frames' and the lean controller's steps ask for moves themselves, after it)."""
    for watched in (FRAMES, GRBL_LENGTHS, ISG_TOOL_DATA, LENGTH_TIMING, MEASURED):
        assert not watched & {"Motion", "Sequence"}, sorted(watched)
