"""The expansion-move lane (``postproc.fast.expansion_moves``) writes an expanded cycle's moves exactly as the
writer's general path writes them (``WordWriter.compound``: ``item_line`` of each move less the axes
``_left_out`` leaves out). Random hole programs (every family, the three planes, G98/G99, repeats, inch and
mm, incremental distances, numbers with more places than are written exactly, block numbers, moves in
between) are translated twice, with the lane and without it (``install_expansion`` replaced by nothing);
text, warnings and errors must be the same, for every source and target whose run takes the lane."""

from __future__ import annotations

import io

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import postproc.fast.expansion_moves as expansion_moves
from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.fast.expansion_moves import ExpansionMoves, choose_moves
from postproc.ir import Block, Motion, Section
from postproc.output.writer_base import Writer
from postproc.plugins import default_registry
from postproc.rs274.writer import WordWriter
from postproc.setup.machine_setup import MachineSetup

SOURCES = ("fanuc", "linuxcnc")
"""Dialects that read the random programs (Fanuc's cycle words; LinuxCNC reads them alike)."""
CALLS = ["G81", "G82 P300", "G83 Q2.", "G73 Q1.5", "G84", "G85", "G86", "G89 P200", "G76 Q0.5", "G87 Q0.5"]
NUMBERS = ["0.", "1.", "-2.5", "0.0", "3.25", "1.2345678", "-0.0004", "12.7", "0.1"]
"""Numbers as a program writes them: canonical, not canonical (``0.0``), and more places than are written
exactly (``1.2345678`` carries its rounding on an incremental move)."""


def _writer(source: str, target: str) -> Writer:
    dialect = default_registry().dialect(target)
    ctx = default_registry().dialect(source).context("p.nc", MachineSetup(), Diagnostics())
    writer: Writer = dialect.WRITER(ctx, source, dialect)  # type: ignore[misc]
    return writer


PAIRS = tuple((source, target) for source in SOURCES for target in sorted(default_registry().dialects)
              if source != target and choose_moves(_writer(source, target)) is not None)
"""Every pair of a source of the random programs and a target whose run writes with the lane."""


@st.composite
def programs(draw: st.DrawFn) -> list[str]:
    number = st.sampled_from(NUMBERS)
    lines = [draw(st.sampled_from(["G21", "G20"])) + " G17 G90 G0 X0. Y0. Z20.", "S1000 M03", "F150."]
    for _ in range(draw(st.integers(1, 10))):
        kind = draw(st.integers(0, 4))
        if kind <= 1:
            plane = draw(st.sampled_from(["", "G17 ", "G18 ", "G19 "]))
            level = draw(st.sampled_from(["G98 ", "G99 ", ""]))
            repeat = draw(st.sampled_from(["", " K2", " K3"]))
            lines.append(f"{draw(st.sampled_from(['', 'N5 ']))}{plane}{level}{draw(st.sampled_from(CALLS))} "
                         f"X{draw(number)} Y{draw(number)} Z{draw(st.sampled_from(['-5.', '-9.25', '-1.2345678']))} "
                         f"R{draw(st.sampled_from(['2.', '0.5', '3.0']))}{repeat}")
        elif kind == 2:
            x, y = draw(st.sampled_from(["", "X"])), draw(st.sampled_from(["", "Y"]))
            words = [w + draw(number) for w in (x, y) if w] or ["X" + draw(number)]
            lines.append(" ".join([*draw(st.sampled_from([[], ["N20"]])), *words]))
        elif kind == 3:
            lines.append(draw(st.sampled_from(["G91", "G90", "F80.", "G80", "G98", "G99", "G0 Z12.", "M05", "M03",
                                               "G1 X3. F100.", "G04 P100", "(NOTE)", "Z-6.", "R1."])))
        else:
            lines.append(f"G0 X{draw(number)} Y{draw(number)}")
    return [*lines, "G80", "G90", "M30"]


def _run(program: list[str], source: str, target: str) -> str:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    try:
        translate([line + "\n" for line in program], out, file="p.nc", source=source, target=target,
                  diagnostics=diagnostics, setup=MachineSetup())
    except ErrorList as err:
        return "errors:\n" + str(err)
    return out.getvalue() + "\n".join(str(w) for w in diagnostics.warnings)


def _no_lane(writer: Writer) -> None:
    """``install_expansion`` turned off: ``compound`` writes every move itself."""


@pytest.mark.parametrize(("source", "target"), PAIRS)
@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(program=programs())
@example(program=["G21 G17 G90 G0 X0. Y0. Z20.", "S1000 M03", "F150.", "G99 G81 X1. Y0.0 Z-5. R2.", "X6.35 Y0.0",
                  "G98 G83 X0. Y5.0 Z-12. R2. Q3. F120.", "X1.2345678", "G80", "M30"])
@example(program=["G21 G17 G90 G0 X0. Y0. Z20.", "S1000 M03", "F150.", "G99 G81 X1. Y0. Z-5. R2.", "X2.", "X2.5",
                  "X2.75", "G99 G81 X3. Y0. Z-9.25 R2.", "X4.", "X4.5", "X4.75", "G83 X5. Z-5. R2. Q2.", "X6.", "X6.5",
                  "G81 X7. Z-5. R2.", "X8.", "X8.5", "G80", "M30"])  # (a row of other lines after a row whose moves were kept as one text: ``ExpansionMoves.rest``)
@example(program=["G20 G17 G90 G0 X0. Y0. Z20.", "G91", "G99 G81 X1.2345678 Y0.1 Z-1.2345678 R2. K3 F10.",
                  "G90", "G18 G98 G82 X1. Y2. Z-5. R0.5 P300", "G19 G87 X1. Y2. Z-5. R3.0 Q0.5", "G80", "M30"])
def test_the_lane_writes_what_the_general_path_writes(program: list[str], source: str, target: str,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    fast = _run(program, source, target)
    with monkeypatch.context() as patch:
        patch.setattr(expansion_moves, "install_expansion", _no_lane)
        slow = _run(program, source, target)
    assert fast == slow


def test_the_lane_is_chosen_where_the_base_writes_moves() -> None:
    """The shipped writers that write a move of an expansion with the base's methods take the lane (grbl's
    family base too: its ``item_line``, which ``compound`` asks of an item that is no move only, adds a spindle
    stop before a program stop); the test above would pass with no lane ever chosen. A writer class that
    overrides a method the lane skips (``move_line``, ``motion_words``) does not, whatever it does."""
    for target in ("linuxcnc", "grbl", "grblhal", "isg", "fagor"):
        assert ("fanuc", target) in PAIRS, target

    class Moving(type(_writer("fanuc", "linuxcnc"))):  # type: ignore[misc]
        def motion_words(self, s: Motion, block: Block) -> list[str]:
            return super().motion_words(s, block)

    class Lining(type(_writer("fanuc", "linuxcnc"))):  # type: ignore[misc]
        def move_line(self, item: Motion, block: Block) -> str:
            return super().move_line(item, block)

    ctx = default_registry().dialect("fanuc").context("p.nc", MachineSetup(), Diagnostics())
    assert choose_moves(Moving(ctx, "fanuc", default_registry().dialect("linuxcnc"))) is None
    assert choose_moves(Lining(ctx, "fanuc", default_registry().dialect("linuxcnc"))) is None


def test_the_lane_writes_the_moves_of_a_row_of_holes() -> None:
    """On the cycles benchmark's rows, the lane (not the general path) writes each move: the comparison above
    is between two paths. A hole's moves after its first are the lines of the same moves of the hole before
    (``ExpansionMoves.made``), not spelt again: the lane spells only the first hole and each hole's move to its
    spot."""
    spelt: list[str] = []
    written: list[str] = []

    class Spy(ExpansionMoves):
        def line(self, item: Motion, before: object, block: Block) -> str | None:  # type: ignore[override]
            text = super().line(item, before, block)  # type: ignore[arg-type]
            assert text is not None  # (None: the general path writes the move)
            spelt.append(text)
            return text

        def write(self, items: list[Section], block: Block, lines: list[str]) -> None:
            at = len(lines)
            super().write(items, block, lines)
            written.extend(lines[at:])

    def spy(writer: Writer) -> None:
        assert isinstance(writer, WordWriter)
        writer.move_lane = Spy(writer)

    program = ["G21 G17 G90 G0 X0. Y0. Z10.", "S1800 M03", "G99 G81 X0. Y0.0 Z-5. R2. F150.", "X6.35 Y0.0",
               "X12.7 Y0.0", "G80", "M30"]
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(expansion_moves, "install_expansion", spy)
        text = _run(program, "fanuc", "linuxcnc")
    assert written == ["G0 X0. Y0. Z2.\n", "G1 Z-5.\n", "G0 Z2.\n", "G0 X6.35 Y0. Z2.\n", "G1 Z-5.\nG0 Z2.\n",
                       "G0 X12.7 Y0. Z2.\n", "G1 Z-5.\nG0 Z2.\n"]  # (a hole's moves after its first: one text, ``rest``)
    assert spelt == ["G0 X0. Y0. Z2.\n", "G1 Z-5.\n", "G0 Z2.\n", "G0 X6.35 Y0. Z2.\n", "G0 X12.7 Y0. Z2.\n"]
    assert "".join(written) in "".join(line for line in text.splitlines(keepends=True) if not line.startswith("("))


def test_an_expansions_move_is_a_motion_of_its_axes() -> None:
    """An expansion's move to a spot known in X, Y and Z (``PathMove``) equals the ``Motion`` of its mode and
    axes, hashes as it, and holds the same three numbers as floats, in every plane."""
    from postproc.cycles.expansion import PathMove, ToolPath
    from postproc.cycles.section import CannedCycle

    for plane, (first, second, normal) in (("XY", "XYZ"), ("ZX", "ZXY"), ("YZ", "YZX")):
        cycle = CannedCycle("drill", semantics="fanuc", plane=plane, start={"X": 1.0, "Y": 2.0, "Z": 3.0})
        path = ToolPath(cycle)
        path.rapid(4.5, 5.5, 6.5)
        path.rapid(level=-1.25)
        moves = path.items
        assert moves == [Motion("rapid", {first: 4.5, second: 5.5, normal: 6.5}),
                         Motion("rapid", {first: 4.5, second: 5.5, normal: -1.25})]
        for move in moves:
            assert isinstance(move, PathMove)
            assert list(move.axes) == ["X", "Y", "Z"]
            assert (move.x, move.y, move.z) == (move.axes["X"], move.axes["Y"], move.axes["Z"])
            assert hash(move) == hash(Motion(move.mode, dict(move.axes)))


def test_a_move_given_other_axes_is_written_from_them() -> None:
    """A step may give an expansion's move other axes (``cycles.lathe_offsets`` shifts them): the lane writes
    the axes the move has then, not the numbers it was made with."""
    from postproc.cycles.expansion import PathMove

    writer = _writer("fanuc", "linuxcnc")
    assert isinstance(writer, WordWriter)
    lane = choose_moves(writer)
    assert isinstance(lane, ExpansionMoves)
    block = Block(1, None, "\n")
    move = PathMove("rapid", {"X": 1.0, "Y": 2.0, "Z": 3.0}, 1.0, 2.0, 3.0)
    assert lane.line(move, None, block) == "G0 X1. Y2. Z3.\n"
    move.axes = {"X": 1.0, "Y": 2.0, "Z": 7.5}
    assert lane.line(move, {"X": 1.0, "Y": 2.0, "Z": 3.0}, block) == "G0 Z7.5\n"
    moved = PathMove("linear", {"X": 1.0, "Y": 2.0, "Z": -4.0}, 1.0, 2.0, -4.0)
    assert lane.line(moved, move.axes, block) == "G1 Z-4.\n"
