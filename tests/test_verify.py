"""verify: fanuc -> fanuc pairs (the only dialect so far): identical, rewritten, moved, restructured."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any, Callable

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSettings, MachineSetup, OutputSettings
from postproc.simulate.verify import Report, compare, normalise, verify_lines
from tests.support.tools import with_tools

G90 = """%
O0100
G21 G17 G90
G00 X10. Y10. Z5.
S1000 M03
G01 Z-2. F200.
X40.
G03 X50. Y20. I0. J10.
G01 Y40.
G03 X40. Y50. R10.
G04 P500
G00 Z5.
M05
M30
%
"""

G91 = """%
O0100
G21 G17 G91
G00 X10. Y10. Z5.
S1000 M03
G01 Z-7. F200.
X30.
G03 X10. Y10. I0. J10.
G01 Y20.
G03 X-10. Y10. R10.
G04 P500
G00 Z7.
M05
G90
M30
%
"""


def lines(text: str) -> list[str]:
    return text.splitlines(keepends=True)


def check(a: str, b: str, tolerance: float = 0.001, **kw: Any) -> Report:
    return verify_lines(lines(a), lines(b), file_in="in.nc", file_out="out.nc", source="fanuc",
                        target="fanuc", tolerance=tolerance, **kw)


def translated(text: str, **output: Any) -> str:
    out = io.StringIO()
    translate(lines(text), out, file="in.nc", source="fanuc", target="fanuc",
              setup=MachineSetup(output=OutputSettings(**output)))
    return out.getvalue()


def test_a_program_against_itself() -> None:
    report = check(G90, G90)
    assert report.ok and report.max_deviation == 0 and report.moves == 7
    assert report.summary() == "max deviation 0.0000 mm over 7 moves (IN:4 / OUT:4): ok"


@pytest.mark.parametrize("output", [{"normalize": True}, {"renumber_start": 10}])
def test_a_program_against_its_normalised_translation(output: dict[str, Any]) -> None:
    assert check(G90, translated(G90, **output)).ok


def test_a_g91_rewrite_matches() -> None:
    report = check(G90, G91)
    assert report.ok, report.summary()
    assert report.moves == 7 and report.max_deviation < 1e-9


def test_an_inch_program_matches_its_mm_twin() -> None:
    inch = "G20 G90\nG00 X1. Y1.\nG01 Z-0.1 F10.\nG02 X2. Y2. R1.\nM30\n"
    mm = "G21 G90\nG00 X25.4 Y25.4\nG01 Z-2.54 F254.\nG02 X50.8 Y50.8 R25.4\nM30\n"
    assert check(inch, mm).ok


def test_a_moved_point_fails_at_the_right_lines() -> None:
    moved = G90.replace("%\nO0100\n", "%\nO0100\n(A COMMENT)\n(SHIFTING LINES)\n").replace("Y40.", "Y40.5")
    report = check(G90, moved)
    assert not report.ok and report.mismatch is None
    assert report.max_deviation == pytest.approx(0.5)
    assert report.summary() == "max deviation 0.5000 mm over 7 moves (IN:9 / OUT:11): exceeds tolerance 0.001 mm"
    assert check(G90, moved, tolerance=0.6).ok


def test_a_deviation_within_the_tolerance_is_ok() -> None:
    report = check(G90, G90.replace("X40.\n", "X40.0004\n"))
    assert report.ok and report.max_deviation == pytest.approx(0.0004)
    assert report.where == (7, 7)


def test_an_arc_the_long_way_round_is_a_deviation() -> None:
    report = check(G90, G90.replace("R10.", "R-10."))
    assert not report.ok and report.where == (10, 10)
    # by hand: X50 Y40 to X40 Y50, R10 a quarter turn about (40, 40), R-10 three quarters about (50, 50);
    # the long way passes (50, 50) + 10 (1, 1)/sqrt(2), 10 sqrt(2) + 10 from (40, 40) on the ray through the
    # quarter's middle, so 10 sqrt(2) from the quarter (its radius 10 along that ray); the ends are the same
    assert report.max_deviation == pytest.approx(10.0 * 2 ** 0.5, abs=1e-6)


def test_a_different_kind_of_move_is_a_structural_mismatch() -> None:
    report = check(G90, G90.replace("G01 Y40.", "G00 Y40."))
    assert not report.ok
    assert report.summary().splitlines() == [
        "max deviation 0.0000 mm over 4 moves (IN:4 / OUT:4): structure differs",
        "first difference at IN:9 / OUT:9: IN has a feed to X50 Y40 Z-2 F200, OUT a rapid to X50 Y40 Z-2",
    ]


def test_a_different_feed_is_a_mismatch() -> None:
    report = check(G90, G90.replace("X40.\n", "X40. F250.\n"))
    assert report.mismatch == "IN feeds at F200, OUT at F250 (a feed to X40 Y10 Z-2 F200)"
    assert report.mismatch_at == (7, 7)


def test_event_differences_are_mismatches() -> None:
    assert check(G90, G90.replace("G04 P500", "G04 P300")).mismatch == \
        "IN has a dwell of 0.5 s, OUT a dwell of 0.3 s"
    assert check(G90, G90.replace("S1000 M03", "S1000 M04")).mismatch == "IN has spindle cw, OUT spindle ccw"
    report = check(G90, G90.replace("G04 P500\n", ""))
    assert report.mismatch == "IN has a dwell of 0.5 s, OUT a rapid to X40 Y50 Z5"
    assert report.mismatch_at == (11, 11)


def test_a_missing_move_at_the_end_is_a_mismatch() -> None:
    report = check(G90, G90.replace("G00 Z5.\nM05", "M05"))
    assert report.mismatch == "IN has a rapid to X40 Y50 Z5, OUT spindle stop"
    short = check(G90, G90.replace("M30\n", ""))
    assert short.mismatch == "OUT has no more moves or events, IN has the program end"
    assert short.mismatch_at == (14, None)


def test_split_lines_and_arcs_are_merged() -> None:
    split = G90.replace("X40.\n", "X25.\nX40.\n").replace("G03 X50. Y20. I0. J10.\n",
                                                         "G03 X47.071068 Y12.928932 I0. J10.\nX50. Y20. I-7.071068 J7.071068\n")
    report = check(G90, split)
    assert report.ok, report.summary()
    assert report.moves == 7


def test_moves_that_turn_back_are_not_merged() -> None:
    a = "G21 G90\nG01 X10. F100.\nM30\n"
    b = "G21 G90\nG01 X20. F100.\nX10.\nM30\n"
    assert check(a, b).mismatch is not None


def test_normalise_merges_collinear_runs_only() -> None:
    events = [
        {"line": 2, "move": "feed", "x": 1, "y": 1, "z": 0, "f": 100},
        {"line": 3, "move": "feed", "x": 2, "y": 2, "z": 0, "f": 100},
        {"line": 4, "move": "feed", "x": 3, "y": 2, "z": 0, "f": 100},
        {"line": 5, "event": "dwell", "seconds": 1},
        {"line": 6, "move": "feed", "x": 4, "y": 2, "z": 0, "f": 100},
    ]
    items = list(normalise(events, {"X": 0.0, "Y": 0.0, "Z": 0.0}, 0.0005))
    assert [(i.first_line, i.last_line) if hasattr(i, "first_line") else i["event"] for i in items] == [
        (2, 3), (4, 4), "dwell", (6, 6)]


def test_compare_headers() -> None:
    head = {"toolpath": 1, "units": "mm", "dialect": "fanuc"}
    report = compare([head], [{**head, "feed_mode": "per_rev"}], start_in={}, start_out={}, tolerance=0.001)
    assert not report.ok and "feed_mode" in (report.mismatch or "")


def test_each_program_uses_its_own_setup() -> None:
    a = "G21 G91\nG00 Z-50.\nM30\n"
    b = "G21 G90\nG00 Z50.\nM30\n"
    report = check(a, b, setup=MachineSetup(machine=MachineSettings(start_z=100.0)),
                   target_setup=MachineSetup())
    assert report.ok, report.summary()


def test_program_errors_in_either_file_are_raised_together() -> None:
    with pytest.raises(ErrorList) as info:
        check(G90.replace("G04 P500", "G31 X1."), G90.replace("R10.", "R1."))
    assert [str(e).split(": error")[0] for e in info.value.errors] == ["in.nc:11:1", "out.nc:10:15"]


# -- the command line ------------------------------------------------------------------------------

def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_cli_ok_and_failures(cli: Callable[..., Any], tmp_path: Path) -> None:
    a = write(tmp_path, "a.nc", G90)
    same = write(tmp_path, "b.nc", G91)
    moved = write(tmp_path, "c.nc", G90.replace("Y40.", "Y40.5"))
    r = cli("verify", a, same, "--from", "fanuc", "--to", "fanuc")
    assert (r.status, r.out.decode()) == (0, "max deviation 0.0000 mm over 7 moves (IN:4 / OUT:4): ok\n")
    r = cli("verify", a, moved, "--from", "fanuc", "--to", "fanuc")
    assert r.status == 1
    assert r.out.decode() == "max deviation 0.5000 mm over 7 moves (IN:9 / OUT:9): exceeds tolerance 0.001 mm\n"
    assert cli("verify", a, moved, "--from", "fanuc", "--to", "fanuc", "--tolerance", "0.5").status == 0


def test_cli_program_error_and_usage(cli: Callable[..., Any], tmp_path: Path) -> None:
    a = write(tmp_path, "a.nc", G90)
    bad = write(tmp_path, "bad.nc", G90.replace("R10.", "R1."))
    r = cli("verify", a, bad, "--from", "fanuc", "--to", "fanuc")
    assert r.status == 1
    assert r.err_lines == [f"{bad}:10:15: error: arc radius 1.0000 mm is too small for a chord of 14.1421 mm"]
    assert cli("verify", a, tmp_path / "none.nc", "--from", "fanuc", "--to", "fanuc").status == 2
    assert cli("verify", a, a, "--from", "fanuc", "--to", "nosuch").status == 2


# -- across dialects (plugins that may or may not be installed) --------------------------------------

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "fanuc"


@pytest.mark.parametrize("name, longest", [("o1001_plate_drill_tap.nc", 140.25), ("o1003_pocket_and_edge.nc", 105.0)])
def test_fanuc_to_grbl_translation_verifies(name: str, longest: float) -> None:
    """grbl has no canned cycles: O1001's holes come out expanded and must trace the same path. It has no
    tool table either: each G43 H is written as G43.1 with the example machine's length (H1 120, H2 95.5,
    H3 140.25, H4 105, H5 88), and the paths agree; run on a machine whose tools measure zero, every
    move of that output runs the tool's length off, the longest used being the largest deviation."""
    from postproc.errors import Diagnostics
    from postproc.plugins import default_registry
    if "grbl" not in default_registry().dialects:
        pytest.skip("the grbl plugin is not installed")
    source = (EXAMPLES / name).read_text()
    out = io.StringIO()
    machine = with_tools(lengths={1: 120.0, 2: 95.5, 3: 140.25, 4: 105.0, 5: 88.0})
    translate(lines(source), out, file=name, source="fanuc", target="grbl", on_unsupported="warn",
              diagnostics=Diagnostics(warn_stream=io.StringIO()), setup=machine)
    report = verify_lines(lines(source), lines(out.getvalue()), file_in=name, file_out="out.nc",
                          source="fanuc", target="grbl", setup=machine, allow_ignored=True)
    assert report.ok and report.max_deviation == 0, report.summary()
    report = verify_lines(lines(source), lines(out.getvalue()), file_in=name, file_out="out.nc",
                          source="fanuc", target="grbl", setup=with_tools())
    assert not report.ok and report.max_deviation == longest, report.summary()
    report.allow_ignored = True
    assert not report.ok  # measured, not left out: --allow-ignored does not accept it
    assert report.moves > 20


# -- verify's per-minute shortcut against per_minute itself ---------------------------------------------

from hypothesis import given, settings, strategies as st  # noqa: E402

from postproc.lowering.inverse_time import per_minute  # noqa: E402
from postproc.simulate.compare import per_minute_from_first  # noqa: E402

_COORD = st.integers(-50, 50).map(float)
_MODES = st.sampled_from([None, "inverse_time", "per_min", "per_rev"])


@st.composite
def _path(draw: Any) -> list[dict[str, Any]]:
    """A toolpath: a header (per minute or in inverse time), then straight and arc moves in any feed mode
    and machine events between them (arcs on a circle of their own, so their centre is consistent)."""
    head: dict[str, Any] = {"toolpath": 1, "units": "mm", "dialect": "fanuc"}
    if draw(st.booleans()):
        head["feed_mode"] = draw(st.sampled_from(["inverse_time", "per_rev"]))
    events: list[dict[str, Any]] = [head]
    x = y = 0.0
    for line in range(1, draw(st.integers(0, 12)) + 1):
        kind = draw(st.sampled_from(["rapid", "feed", "feed", "ccw", "event"]))
        if kind == "event":
            events.append({"line": line, "event": "coolant", "on": draw(st.booleans())})
            continue
        ev: dict[str, Any] = {"line": line, "move": kind}
        if kind == "ccw":  # a half circle about a centre one unit left of here
            ev.update(x=x - 2.0, y=y, z=draw(_COORD), cx=x - 1.0, cy=y, plane="XY")
        else:
            ev.update(x=draw(_COORD), y=draw(_COORD), z=draw(_COORD))
        if kind != "rapid":
            ev["f"] = draw(st.integers(1, 500))
            mode = draw(_MODES)
            if mode is not None:
                ev["feed_mode"] = mode
        x, y = ev["x"], ev["y"]
        events.append(ev)
    return events


@settings(max_examples=300, deadline=None)
@given(path=_path(), start=st.one_of(st.none(), st.fixed_dictionaries({"X": _COORD, "Y": _COORD, "Z": _COORD})))
def test_per_minute_from_first_is_per_minute(path: list[dict[str, Any]], start: dict[str, float] | None) -> None:
    start = start or {"X": 0.0, "Y": 0.0, "Z": 0.0}
    assert list(per_minute_from_first(iter(path), start)) == list(per_minute(path, start))


# -- controlled points read in place (``compare._move``) against the path with them resolved first -----------

from postproc.simulate.compare import _controlled  # noqa: E402
from postproc.simulate.normal_move import Move  # noqa: E402


@st.composite
def _offset_path(draw: Any) -> list[dict[str, Any]]:
    """A toolpath (``_path``) whose moves may carry a controlled point beside the programmed one, as the
    simulator writes it under a tool length or cutter compensation: some axes moved, the others the same
    objects, an arc's centre moved with its end."""
    events = draw(_path())
    for ev in events[1:]:
        if "move" not in ev or not draw(st.booleans()):
            continue
        controlled = {k: ev[k] for k in "xyz"}
        for k in draw(st.lists(st.sampled_from("xyz"), max_size=3, unique=True)):
            controlled[k] = ev[k] + draw(st.integers(-3, 3)) * 0.25
        if "cx" in ev:
            controlled["cx"] = ev["cx"] + controlled["x"] - ev["x"]
            controlled["cy"] = ev["cy"] + controlled["y"] - ev["y"]
        ev["controlled"] = controlled
    return events


def _fields(item: Any) -> Any:
    if isinstance(item, Move):
        return (item.kind, item.start, item.end, item.f, item.first_line, item.last_line, item.direction, item.centre,
                item.plane, item.radius, item.sweep, item.length)
    return item


@settings(max_examples=300, deadline=None)
@given(path=_offset_path())
def test_normalise_reads_a_controlled_point_as_the_path_resolved_first(path: list[dict[str, Any]]) -> None:
    start = {"X": 1.0, "Y": -2.0, "Z": 3.0}
    ours = [_fields(i) for i in normalise(iter(path), start, 0.0005)]
    assert ours == [_fields(i) for i in normalise(_controlled(iter(path)), start, 0.0005)]


@settings(max_examples=300, deadline=None)
@given(path=_offset_path(), start=st.one_of(st.none(), st.fixed_dictionaries({"X": _COORD, "Y": _COORD, "Z": _COORD})))
def test_per_minute_from_first_converts_the_controlled_path(path: list[dict[str, Any]],
                                                            start: dict[str, float] | None) -> None:
    start = start or {"X": 0.0, "Y": 0.0, "Z": 0.0}
    ours = list(_controlled(per_minute_from_first(iter(path), start)))
    assert ours == list(per_minute(_controlled(iter(path)), start))


def _report_fields(report: Report) -> Any:
    return (report.ok, report.moves, report.max_deviation, report.where, report.where_at, report.mismatch,
            report.mismatch_at, report.ignored)


@settings(max_examples=300, deadline=None)
@given(a=_offset_path(), b=_offset_path(), diameter=st.sampled_from([None, "in", "out", "both"]))
def test_compare_of_controlled_points_is_compare_of_the_paths_resolved_first(
        a: list[dict[str, Any]], b: list[dict[str, Any]], diameter: str | None) -> None:
    """Two random toolpaths, and each against a copy of itself with its controlled points moved a little
    (a lathe's diameter x on either side too): the same report as the controlled paths given resolved."""
    for side, path in (("in", a), ("out", b)):
        if diameter in (side, "both"):
            path[0]["x_mode"] = "diameter"
    start = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    for x, y in ((a, b), (a, [dict(ev) for ev in a])):
        ours = compare(x, y, start_in=start, start_out=start, tolerance=0.001)
        resolved = compare(list(_controlled(iter(x))), list(_controlled(iter(y))), start_in=start, start_out=start,
                           tolerance=0.001)
        assert _report_fields(ours) == _report_fields(resolved)
