"""Milling hole cycles, Fanuc semantics: resolution (CannedCycleResolveSyntax), each family's exact
expansion, the G87 seed, errors, and the XML round trip of every class the cycles package registers."""

from __future__ import annotations

from typing import Any

import pytest
from lxml import etree

from postproc.api import read_blocks, read_program
from postproc.cycles import (
    XML_CLASSES, BackBoringExpansion, BoringExpansion, CannedCycle, CannedCycleResolveSyntax, DrillingExpansion,
    FineBoringExpansion, ManualBoringExpansion, PeckDrillingExpansion, TappingExpansion,
)
from postproc.cycles.expansion import ToolPath
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.ir import (
    Block, CompoundMotion, Dwell, Feed, Motion, ProgramControl, Section, SpindleControl, SpindleOrientation,
)
from postproc.plugins import default_registry
from postproc.setup.machine_setup import CycleSettings, InputSettings, MachineSetup
from postproc.xmlio import DEFAULT, parse_xml_bytes, to_bytes

HEAD = "G21 G17 G90 G54\nS1000 M03\nG00 X0. Y0. Z50.\n"
"""Lines 1-3 of most programs here: the tool starts at X0 Y0 Z50."""


def setup(**cycles: Any) -> MachineSetup:
    inp = cycles.pop("input", None)
    return MachineSetup(cycles=CycleSettings(**cycles), input=inp)


def read(text: str, **cycles: Any) -> list[Block]:
    default_registry()
    return read_program(text.splitlines(keepends=True), file="t.nc", dialect="fanuc", setup=setup(**cycles))


def error(text: str, **cycles: Any) -> tuple[str, int, int]:
    """The first error of a program: message, line, column."""
    with pytest.raises(ErrorList) as caught:
        read(text, **cycles)
    err = caught.value.errors[0]
    assert err.location is not None
    return err.message, err.location.line, err.location.col


def rows(items: list[Section]) -> list[tuple[Any, ...]]:
    """Items as (kind, ...) tuples: ('rapid'|'feed', x, y, z), ('spindle', dir), ('dwell', s), ..."""
    out: list[tuple[Any, ...]] = []
    for item in items:
        if isinstance(item, Motion):
            kind = "rapid" if item.mode == "rapid" else "feed"
            out.append((kind, item.axes["X"], item.axes["Y"], item.axes["Z"]))
        elif isinstance(item, SpindleControl):
            out.append(("spindle", item.direction))
        elif isinstance(item, Dwell):
            out.append(("dwell", item.seconds))
        elif isinstance(item, SpindleOrientation):
            out.append(("orient", item.angle))
        elif isinstance(item, ProgramControl):
            out.append(("stop", item.kind))
        elif isinstance(item, Feed):
            out.append(("F", item.value))
        else:
            raise AssertionError(f"unexpected item {item!r}")
    return out


def cycle_rows(blocks: list[Block], line: int) -> list[tuple[Any, ...]]:
    block = next(b for b in blocks if b.line == line)
    return rows(block.sections["CompoundMotion"].items)


# -- the G87 seed ------------------------------------------------------------------------------------

SEED_ITEMS = [
    SpindleOrientation(0.0),
    Motion("rapid", {"X": 51.0, "Y": 30.0, "Z": 0.0}),
    Motion("rapid", {"X": 51.0, "Y": 30.0, "Z": -10.0}),
    Motion("rapid", {"X": 50.0, "Y": 30.0, "Z": -10.0}),
    SpindleControl("cw"),
    Motion("linear", {"X": 50.0, "Y": 30.0, "Z": 2.0}),
    SpindleOrientation(0.0),
    Motion("rapid", {"X": 51.0, "Y": 30.0, "Z": 2.0}),
    Motion("rapid", {"X": 51.0, "Y": 30.0, "Z": 0.0}),
    Motion("rapid", {"X": 50.0, "Y": 30.0, "Z": 0.0}),
    SpindleControl("cw"),
]
"""The seed's eleven items for G87 G98 X50 Y30 Z-10 R2 Q1 F600 from an initial level of Z0."""


def test_seed_back_boring_from_a_resolved_section() -> None:
    """The seed's #BeforeBuild: a pre-populated CannedCycle, initial Z0, no previous position data."""
    cycle = CannedCycle("back_bore", call=True, semantics="fanuc", initial=0.0, r=2.0, bottom=-10.0, top=2.0, orient=0.0,
                        feed=600.0, start={"X": 0.0, "Y": 0.0, "Z": 0.0}, position={"X": 50.0, "Y": 30.0},
                        shift={"X": 1.0}, words={"X": 50.0, "Y": 30.0, "Z": -10.0, "R": 2.0, "Q": 1.0})
    block = Block(1, "G87 G98 X50. Y30. Z-10. R2. Q1. F600.")
    block.add(cycle)
    BackBoringExpansion().build(block, None)  # type: ignore[arg-type]
    compound = block.sections["CompoundMotion"]
    assert compound == CompoundMotion("back_bore", SEED_ITEMS)
    assert len(compound.items) == 11
    assert BackBoringExpansion().expand(cycle)[1] == {"X": 50.0, "Y": 30.0, "Z": 0.0}


def test_seed_back_boring_from_a_program() -> None:
    text = HEAD + "G00 Z0.\nG87 G98 X50. Y30. Z-10. R2. Q1. F600.\n"
    diagnostics = Diagnostics(ErrorLevel.IMMEDIATE)
    ctx, stream = read_blocks(text.splitlines(keepends=True), "t.nc", default_registry().dialect("fanuc"),
                              MachineSetup(), diagnostics)
    blocks = list(stream)
    g87 = blocks[4]
    assert g87.sections["CompoundMotion"] == CompoundMotion("back_bore", SEED_ITEMS)
    assert g87.sections["Feed"] == Feed(600.0)
    cycle = g87.sections["CannedCycle"]
    assert (cycle.kind, cycle.initial, cycle.bottom, cycle.top, cycle.r) == ("back_bore", 0.0, -10.0, 2.0, 2.0)
    assert cycle.words == {"X": 50.0, "Y": 30.0, "Z": -10.0, "R": 2.0, "Q": 1.0}
    assert "CycleCall" not in g87.sections and "Motion" not in g87.sections
    assert ctx.state.position == {"X": 50.0, "Y": 30.0, "Z": 0.0}


def test_back_boring_manual_levels() -> None:
    """R is the bottom, Z the top; the tool positions on the hole first, as the Fanuc manual draws it."""
    blocks = read(HEAD + "G87 G98 X50. Y30. Z-10. R-20. Q1. P200 F600.\n", back_boring_levels="manual")
    assert cycle_rows(blocks, 4) == [
        ("rapid", 50, 30, 50), ("orient", 0), ("rapid", 51, 30, 50), ("rapid", 51, 30, -20),
        ("rapid", 50, 30, -20), ("spindle", "cw"), ("feed", 50, 30, -10), ("dwell", 0.2), ("orient", 0),
        ("rapid", 51, 30, -10), ("rapid", 51, 30, 50), ("rapid", 50, 30, 50), ("spindle", "cw"),
    ]


@pytest.mark.parametrize("levels, text, message, col", [
    ("seed", "G87 G98 X50. Y30. Z5. R2. Q1. F600.", "G87 Z must lie below R (back-boring levels 'seed': "
     "Z is the bottom, R the top)", 19),
    ("manual", "G87 G98 X50. Y30. Z-10. R2. Q1. F600.", "G87 R must lie below Z (back-boring levels "
     "'manual': R is the bottom, Z the top)", 25),
])
def test_back_boring_levels_contradicting_the_convention(levels: str, text: str, message: str, col: int) -> None:
    assert error(HEAD + text + "\n", back_boring_levels=levels) == (message, 4, col)


def test_back_boring_shift_direction_and_angle_from_the_setup() -> None:
    blocks = read(HEAD + "G00 Z0.\nG87 G98 X50. Y30. Z-10. R2. Q1. F600.\n", shift_direction="-Y",
                  orient_angle=90.0)
    got = cycle_rows(blocks, 5)
    assert got[0] == ("orient", 90.0) and got[1] == ("rapid", 50, 29, 0)


# -- each family, through a program (HEAD puts the tool at Z50) --------------------------------------

def test_drilling_g98_g99_and_initial_level() -> None:
    blocks = read(HEAD + "G98 G81 X10. Y10. Z-5. R2. F200.\nG99 X20.\nG98 X30.\n")
    assert cycle_rows(blocks, 4) == [("rapid", 10, 10, 50), ("rapid", 10, 10, 2), ("feed", 10, 10, -5),
                                     ("rapid", 10, 10, 50)]
    assert cycle_rows(blocks, 5) == [("rapid", 20, 10, 50), ("rapid", 20, 10, 2), ("feed", 20, 10, -5),
                                     ("rapid", 20, 10, 2)]
    # positioned at R (no zero-length "rapid to R"), back to the first initial level
    assert cycle_rows(blocks, 6) == [("rapid", 30, 10, 2), ("feed", 30, 10, -5), ("rapid", 30, 10, 50)]


def test_g98_after_g99_with_a_lower_r_positions_at_the_current_level() -> None:
    """Operation 1 rapids in the plane at the current level (DIALECTS.md §2.1): after a G99 hole the
    tool stands at R, so a G98 hole with a lower R is positioned there, never by a diagonal rapid."""
    blocks = read(HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nG98 X20. R1.\nG99 X30. R3.\nG98 X40. R4.\n")
    assert cycle_rows(blocks, 5) == [("rapid", 20, 10, 2), ("rapid", 20, 10, 1), ("feed", 20, 10, -5),
                                     ("rapid", 20, 10, 50)]
    assert cycle_rows(blocks, 7) == [("rapid", 40, 10, 3), ("rapid", 40, 10, 4), ("feed", 40, 10, -5),
                                     ("rapid", 40, 10, 50)]


def test_spot_drilling_dwell_in_milliseconds() -> None:
    blocks = read(HEAD + "G99 G82 X10. Y10. Z-3. R2. P500 F150.\n")
    assert cycle_rows(blocks, 4) == [("rapid", 10, 10, 50), ("rapid", 10, 10, 2), ("feed", 10, 10, -3),
                                     ("dwell", 0.5), ("rapid", 10, 10, 2)]


def test_spot_drilling_without_p_has_no_dwell() -> None:
    assert ("dwell", 0.0) not in cycle_rows(read(HEAD + "G82 X10. Y10. Z-3. R2. F150.\n"), 4)


def test_high_speed_peck() -> None:
    blocks = read(HEAD + "G98 G73 X10. Y10. Z-12.5 R2. Q4. F100.\n", peck_retract=0.5)
    assert cycle_rows(blocks, 4) == [
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 2), ("feed", 10, 10, -2), ("rapid", 10, 10, -1.5),
        ("feed", 10, 10, -6), ("rapid", 10, 10, -5.5), ("feed", 10, 10, -10), ("rapid", 10, 10, -9.5),
        ("feed", 10, 10, -12.5), ("rapid", 10, 10, 50)]


def test_deep_hole_peck_and_exact_last_peck() -> None:
    blocks = read(HEAD + "G99 G83 X10. Y10. Z-10. R2. Q4. F100.\n", peck_clearance=0.3)
    got = cycle_rows(blocks, 4)
    assert got == [
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 2), ("feed", 10, 10, -2), ("rapid", 10, 10, 2),
        ("rapid", 10, 10, pytest.approx(-1.7)), ("feed", 10, 10, -6), ("rapid", 10, 10, 2),
        ("rapid", 10, 10, pytest.approx(-5.7)), ("feed", 10, 10, -10), ("rapid", 10, 10, 2)]


def test_peck_clearance_converted_for_inch_programs() -> None:
    blocks = read("G20 G17 G90\nG00 X0. Y0. Z2.\nG99 G83 X1. Y1. Z-1. R0.1 Q0.5 F10.\n", peck_clearance=0.254)
    cycle = blocks[2].sections["CannedCycle"]
    assert cycle.clearance == pytest.approx(0.01)
    assert ("rapid", 1, 1, pytest.approx(-0.39)) in cycle_rows(blocks, 3)


def test_tapping_and_left_hand_tapping() -> None:
    right = read(HEAD + "G98 G84 X10. Y10. Z-15. R5. P300 F750.\n")
    assert cycle_rows(right, 4) == [
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 5), ("feed", 10, 10, -15), ("dwell", 0.3), ("spindle", "ccw"),
        ("feed", 10, 10, 5), ("rapid", 10, 10, 50), ("spindle", "cw")]
    left = read(HEAD + "M04\nG99 G74 X10. Y10. Z-15. R5. F750.\n")
    assert cycle_rows(left, 5) == [
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 5), ("feed", 10, 10, -15), ("spindle", "cw"),
        ("feed", 10, 10, 5), ("spindle", "ccw")]


def test_boring_families() -> None:
    assert cycle_rows(read(HEAD + "G98 G85 X1. Y1. Z-20. R2. F120.\n"), 4) == [
        ("rapid", 1, 1, 50), ("rapid", 1, 1, 2), ("feed", 1, 1, -20), ("feed", 1, 1, 2), ("rapid", 1, 1, 50)]
    assert cycle_rows(read(HEAD + "G99 G89 X1. Y1. Z-20. R2. P1000 F120.\n"), 4) == [
        ("rapid", 1, 1, 50), ("rapid", 1, 1, 2), ("feed", 1, 1, -20), ("dwell", 1.0), ("feed", 1, 1, 2)]
    assert cycle_rows(read(HEAD + "G98 G86 X1. Y1. Z-20. R2. P500 F120.\n"), 4) == [
        ("rapid", 1, 1, 50), ("rapid", 1, 1, 2), ("feed", 1, 1, -20), ("spindle", "stop"), ("rapid", 1, 1, 50),
        ("spindle", "cw")]


def test_fine_boring_shift_at_the_bottom() -> None:
    assert cycle_rows(read(HEAD + "G99 G76 X10. Y10. Z-15. R2. Q0.5 P200 F80.\n"), 4) == [
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 2), ("feed", 10, 10, -15), ("dwell", 0.2), ("orient", 0),
        ("rapid", 10.5, 10, -15), ("rapid", 10.5, 10, 2), ("rapid", 10, 10, 2), ("spindle", "cw")]


def test_manual_boring_program_stop() -> None:
    assert cycle_rows(read(HEAD + "G98 G88 X10. Y10. Z-20. R2. P500 F120.\n"), 4) == [
        ("rapid", 10, 10, 50), ("rapid", 10, 10, 2), ("feed", 10, 10, -20), ("dwell", 0.5),
        ("spindle", "stop"), ("stop", "stop"), ("rapid", 10, 10, 50), ("spindle", "cw")]


def test_every_kind_has_exactly_one_family() -> None:
    families = [DrillingExpansion, PeckDrillingExpansion, TappingExpansion, BoringExpansion, FineBoringExpansion,
                BackBoringExpansion, ManualBoringExpansion]
    kinds = [k for f in families for k in f.KINDS]
    assert len(kinds) == len(set(kinds)) == 12


def test_toolpath_drops_zero_length_moves_and_emits_feed_only_on_change() -> None:
    cycle = CannedCycle("drill", semantics="fanuc", initial=2.0, r=2.0, bottom=-1.0, feed=100.0,
                        start={"X": 0.0, "Y": 0.0, "Z": 2.0},
                        position={"X": 0.0, "Y": 0.0})
    path = ToolPath(cycle)
    path.rapid(0.0, 0.0, 2.0)
    path.cut(-1.0, 100.0)
    path.cut(2.0, 50.0)
    assert rows(path.items) == [("feed", 0, 0, -1), ("F", 50.0), ("feed", 0, 0, 2)]


# -- common rules --------------------------------------------------------------------------------------

def test_incremental_rows_and_k0() -> None:
    """G91: R from the initial level, Z from R, a row of K holes; K0 stores the data only."""
    blocks = read(HEAD + "G91 G99 G81 Z-7. R-48. F200. K0\nX10. K3\nG98 Y10. K2\n")
    k0 = blocks[3]
    assert k0.sections["CompoundMotion"].items == [] and k0.sections["CannedCycle"].repeat == 0
    assert (k0.sections["CannedCycle"].r, k0.sections["CannedCycle"].bottom) == (2.0, -5.0)
    assert cycle_rows(blocks, 5) == [
        ("rapid", 10, 0, 50), ("rapid", 10, 0, 2), ("feed", 10, 0, -5), ("rapid", 10, 0, 2),
        ("rapid", 20, 0, 2), ("feed", 20, 0, -5), ("rapid", 20, 0, 2),
        ("rapid", 30, 0, 2), ("feed", 30, 0, -5), ("rapid", 30, 0, 2)]
    row = blocks[5].sections["CannedCycle"]
    assert (row.position, row.step, row.repeat) == ({"X": 30.0, "Y": 10.0}, {"X": 0.0, "Y": 10.0}, 2)
    assert cycle_rows(blocks, 6)[-1] == ("rapid", 30, 20, 50)


def test_absolute_k_drills_the_same_spot() -> None:
    got = cycle_rows(read(HEAD + "G99 G81 X10. Y10. Z-5. R2. F200. K3\n"), 4)
    assert got.count(("feed", 10, 10, -5)) == 3 and len(got) == 2 + 2 * 3


def test_repeat_address_l() -> None:
    blocks = read(HEAD + "G99 G81 X10. Y10. Z-5. R2. F200. L2\n", input=InputSettings(repeat_address="L"))
    assert blocks[3].sections["CannedCycle"].repeat == 2


def test_planes_g18_and_g19() -> None:
    g18 = read("G21 G18 G90\nG00 X0. Y50. Z0.\nG98 G81 X10. Z-10. Y-5. R2. F200.\n")
    assert cycle_rows(g18, 3) == [("rapid", 10, 50, -10), ("rapid", 10, 2, -10), ("feed", 10, -5, -10),
                                  ("rapid", 10, 50, -10)]
    g19 = read("G21 G19 G90\nG00 X50. Y0. Z0.\nG99 G81 Y10. Z-10. X-5. R2. F200.\n")
    assert cycle_rows(g19, 3) == [("rapid", 50, 10, -10), ("rapid", 2, 10, -10), ("feed", -5, 10, -10),
                                  ("rapid", 2, 10, -10)]


def test_shift_follows_the_plane() -> None:
    """'+X' shifts along the plane's first axis: Z in G18 (Fanuc's parameter table)."""
    blocks = read("G21 G18 G90\nG00 X0. Y50. Z0.\nG98 G76 X10. Z-10. Y-5. R2. Q1. F200.\n")
    assert blocks[2].sections["CannedCycle"].shift == {"Z": 1.0}
    assert ("rapid", 10, -5, -9) in cycle_rows(blocks, 3)


def test_modal_data_carries_over_between_cycle_codes() -> None:
    """Fanuc gotcha 9: Q of a G83 becomes the shift of a later G76; the initial level stays."""
    blocks = read(HEAD + "G99 G83 X10. Y10. Z-12. R2. Q4. F100.\nG98 G76 X30.\n")
    g76 = blocks[4].sections["CannedCycle"]
    assert (g76.kind, g76.shift, g76.bottom, g76.r, g76.initial) == ("fine_bore", {"X": 4.0}, -12.0, 2.0, 50.0)
    assert cycle_rows(blocks, 5)[-3:] == [("rapid", 34, 10, 50), ("rapid", 30, 10, 50), ("spindle", "cw")]


def test_block_without_position_data_changes_the_data_only() -> None:
    blocks = read(HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nZ-8.\nR3.\nX20.\n")
    for line in (5, 6):
        assert blocks[line - 1].sections["CompoundMotion"].items == []
        assert blocks[line - 1].sections["CannedCycle"].repeat == 0
    assert cycle_rows(blocks, 7) == [("rapid", 20, 10, 2), ("rapid", 20, 10, 3), ("feed", 20, 10, -8),
                                     ("rapid", 20, 10, 3)]


def test_cancel_by_g80_and_by_group_01() -> None:
    blocks = read(HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nG80\nX30.\nG81 X40. Z-5. R2.\nG01 X50. F500.\nY30.\n")
    assert blocks[5].sections["Motion"] == Motion("rapid", {"X": 30.0})
    assert "CannedCycle" in blocks[6].sections
    assert blocks[8].sections["Motion"] == Motion("linear", {"Y": 30.0})
    # G80 clears the hole data too
    assert error(HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nG80\nG81 X20.\n") == ("G81 needs a hole bottom Z", 6, 1)


def test_dwell_or_verbatim_block_during_a_cycle_is_not_cycle_data() -> None:
    blocks = read(HEAD + "G99 G82 X10. Y10. Z-5. R2. P100 F200.\nG04 P900\nM98 P1234\nX20.\n")
    assert "CannedCycle" not in blocks[4].sections and "CannedCycle" not in blocks[5].sections
    assert blocks[6].sections["CannedCycle"].dwell == 0.1


def test_cycle_block_without_position_drills_where_the_tool_is() -> None:
    assert cycle_rows(read(HEAD + "G98 G81 Z-5. R2. F200.\n"), 4) == [
        ("rapid", 0, 0, 2), ("feed", 0, 0, -5), ("rapid", 0, 0, 50)]


def test_position_follows_the_cycle() -> None:
    text = HEAD + "G99 G81 X10. Y10. Z-5. R2. F200.\nG80\nG91 G00 X1.\n"
    ctx, stream = read_blocks(text.splitlines(keepends=True), "t.nc", default_registry().dialect("fanuc"),
                              MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE))
    list(stream)
    assert ctx.state.position == {"X": 11.0, "Y": 10.0, "Z": 2.0}
    assert ctx.state.cycle is None


# -- errors --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("text, expected", [
    (HEAD + "G99 G81 X10. Y10. R2. F200.\n", ("G81 needs a hole bottom Z", 4, 5)),
    (HEAD + "G98 G83 X10. Y10. Z-12. R2. F100.\n", ("G83 needs a peck depth Q", 4, 5)),
    (HEAD + "G98 G73 X10. Y10. Z-12. R2. F100.\n", ("G73 needs a peck depth Q", 4, 5)),
    (HEAD + "G99 G87 X50. Y30. Z-10. R2. Q1. F600.\n", ("G87 cannot be used with G99", 4, 5)),
    (HEAD + "G98 G87 X50. Y30. Z-10. R2. Q1. F600.\nG99 X60.\n", ("G87 cannot be used with G99", 5, 1)),
    (HEAD + "G98 G81 X10. Y10. Z-5. F200.\n", ("G81 needs an R level R", 4, 5)),
    (HEAD + "G98 G83 X10. Y10. Z-12. R2. Q0 F100.\n", ("G83 peck depth Q must be positive", 4, 29)),
    (HEAD + "G98 G83 X10. Y10. Z-12. R2. Q-1. F100.\n", ("G83 peck depth Q must be positive", 4, 29)),
    (HEAD + "G98 G81 X10. Y10. Z-5. R2. F200. K-1\n", ("repeat count K cannot be negative", 4, 34)),
    (HEAD + "G98 G81 X10. Y10. Z5. R2. F200.\n", ("G81 hole bottom Z is above the R level", 4, 19)),
    (HEAD + "G91 G98 G81 X10. Y10. Z5. R-48. F200.\n", ("G81 hole bottom Z is above the R level", 4, 23)),
    (HEAD + "G98 G76 X10. Y10. Z-5. R2. Q-1. F200.\n",
     ("G76 shift Q cannot be negative: the set-up gives its direction", 4, 28)),
    (HEAD + "G98 G87 X50. Y30. Z-10. R2. F600.\n", ("G87 needs a shift Q", 4, 5)),
    (HEAD + "G98 G82 X10. Y10. Z-5. R2. P-5 F200.\n", ("G82 dwell time P cannot be negative", 4, 28)),
    ("G21 G17 G90\nG98 G81 X10. Y10. Z-5. R2. F200.\n",
     ("the initial level of G81 is unknown: Z was never positioned absolutely", 2, 5)),
    ("G21 G17 G90\nG00 Z50.\nG98 G81 Y10. Z-5. R2. F200.\n",
     ("the hole position of G81 is unknown: X was never positioned absolutely", 3, 5)),
    ("G21 G17 G90\nG00 X0. Y0. Z50.\nG98 G81 X10. Y10. Z-5. R2.\n", ("G81 needs a feed rate F", 3, 5)),
    (HEAD + "G98 G81 X10. Y10. Z-5. R2. F200.\nX20. A5.\n",
     ("G81 cannot move axis A: only X, Y and Z take part in a hole cycle", 5, 6)),
    (HEAD + "G98 G81 X10. Y10. Z-5. R2. F200.\nG18 X20.\n",
     ("the plane cannot change while G81 is active (cancel the cycle first)", 5, 1)),
    (HEAD + "G98 G081 X10. Y10. Z-5. F200.\n", ("G81 needs an R level R", 4, 5)),
])
def test_errors_are_located(text: str, expected: tuple[str, int, int]) -> None:
    assert error(text) == expected


def test_an_error_reports_the_block_once() -> None:
    with pytest.raises(ErrorList) as caught:
        read(HEAD + "G99 G81 X10. Y10. R2. F200.\n")
    assert len(caught.value.errors) == 1
    assert "CycleCall" not in read(HEAD)[0].sections


# -- XML -----------------------------------------------------------------------------------------------

def full_section() -> CannedCycle:
    return CannedCycle("peck_deep", call=True, semantics="rs274", return_level="r", plane="ZX", initial=50.0,
                       r=2.0, bottom=-5.5, top=1.25, q=4.0, clearance=0.3, dwell=0.5, orient=45.0, feed=200.0,
                       repeat=3, spindle="ccw", motion="rapid", start={"X": 0.0, "Y": 50.0, "Z": 0.0},
                       position={"Z": 10.0, "X": -3.0}, step={"Z": 1.0, "X": 0.0}, shift={"Z": -0.5},
                       words={"X": -3.0, "Y": -5.5, "R": 2.0, "Q": 4.0, "P": 500, "K": 3})


@pytest.mark.parametrize("node", [
    full_section(), CannedCycle("drill", semantics="fanuc"), CannedCycle("fine_bore", semantics="rs274", shift={}),
    CannedCycleResolveSyntax("fanuc"), CannedCycleResolveSyntax("rs274"),
    CannedCycleResolveSyntax("fanuc", [BackBoringExpansion()]),
    DrillingExpansion(), PeckDrillingExpansion(), TappingExpansion(), BoringExpansion(), FineBoringExpansion(),
    BackBoringExpansion(), ManualBoringExpansion(),
], ids=repr)
def test_xml_round_trip(node: Any) -> None:
    default_registry()
    el = node.make_xml_source(".", "", False)
    again = DEFAULT.create(parse_xml_bytes(to_bytes(el), "t.xml"))
    assert again == node
    assert etree.tostring(again.make_xml_source(".", "", False), method="c14n") == \
        etree.tostring(node.make_xml_source(".", "", False), method="c14n")


def test_every_registered_cycle_class_round_trips() -> None:
    default_registry()
    for cls in XML_CLASSES:
        assert cls.XNAME in DEFAULT.names()
        cls.reg(DEFAULT)  # idempotent
        node = cls("drill", semantics="fanuc") if cls is CannedCycle else \
            cls("fanuc") if cls is CannedCycleResolveSyntax else cls()
        assert DEFAULT.create(node.make_xml_source(".", "", False)) == node


def test_words_keep_their_kind_in_xml() -> None:
    again = DEFAULT.create(full_section().make_xml_source(".", "", False))
    assert isinstance(again.words["P"], int) and isinstance(again.words["X"], float)


def test_block_with_cycle_round_trips() -> None:
    block = read(HEAD + "G98 G83 X10. Y10. Z-12. R2. Q4. F100.\n")[3]
    assert Block.from_xml(block.make_xml_source()) == block


def test_fanuc_pipeline_resolves_cycles_before_the_modal_state() -> None:
    names = [type(step).XNAME for step in default_registry().dialect("fanuc").pipeline(MachineSetup()).steps]
    assert names == ["FanucProgramSyntax", "FanucBlockSyntax", "CannedCycleResolveSyntax", "ModalStateSyntax"]


@pytest.mark.parametrize("xml, message", [
    (b'<CannedCycleResolveSyntax semantics="heidenhain"/>', "unknown cycle semantics 'heidenhain'"),
    (b'<CannedCycleResolveSyntax mode="x"/>', "unknown attribute(s) mode"),
    (b'<CannedCycleResolveSyntax/>', "needs attribute 'semantics' (fanuc or rs274: how the controller moves"),
    (b'<CannedCycleResolveSyntax semantics="fanuc"><ModalStateSyntax/></CannedCycleResolveSyntax>',
     "is not a cycle expansion"),
    (b'<CannedCycleResolveSyntax semantics="fanuc"><Nope/></CannedCycleResolveSyntax>', "unknown element <Nope>"),
    (b'<CannedCycle kind="drill" semantics="fanuc"><Holes/></CannedCycle>', "unexpected <Holes>"),
    (b'<CannedCycle kind="drill"/>', "<CannedCycle> needs attribute 'semantics'"),
    (b'<DrillingSyntax><X/></DrillingSyntax>', "takes no children"),
])
def test_bad_xml_is_a_located_config_error(xml: bytes, message: str) -> None:
    from postproc.errors import ConfigError
    default_registry()
    with pytest.raises(ConfigError) as caught:
        DEFAULT.create(parse_xml_bytes(xml, "bad.xml"))
    assert message in caught.value.message
    assert caught.value.location is not None and caught.value.location.file == "bad.xml"
