"""The fast lane (``postproc.fast``) writes exactly what the writer's general path writes.

A CAM program's usual block (``N.. X.. Y.. Z.. F..``) is written by a few comparisons instead of the
section dispatch, for the runs whose writer class writes such a block with the word writer's own methods
(the lane decides, ``postproc.fast.lane``). Random programs of such blocks, mixed with what must leave the
lane (arcs, other axes, numbers with more places than are written exactly, incremental moves that carry
rounding, block numbers with leading zeros, a units change, cycles), are translated twice: with the lane,
and without it (``postproc.fast.lane.install`` replaced by nothing); text, warnings and errors must be the
same, for every dialect pair a lane is chosen for.
"""

from __future__ import annotations

import io
from decimal import Decimal

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import postproc.fast.lane
from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.fast.lane import COPY_METHODS, STRAIGHT_METHODS, choose, own
from postproc.fast.straight import CopyLane, SourceLane, StraightLane
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.rs274.writer import WordWriter
from postproc.setup.machine_setup import MachineSetup
from postproc.output.line_feeds import Batch
from postproc.output.writer_base import Lane, Writer

SOURCES = ("fanuc", "linuxcnc")
"""Dialects that read the random programs (Fanuc's words; LinuxCNC reads most of them alike)."""


def _lane(source: str, target: str, normalize: bool = True) -> type | None:
    """The lane a run from ``source`` to ``target`` takes (normalised when it is the same dialect, unless
    not ``normalize``): the class of its shortcut, or None."""
    dialect = default_registry().dialect(target)
    setup = MachineSetup()
    setup.output.normalize = target == source and normalize
    ctx = default_registry().dialect(source).context("p.nc", setup, Diagnostics())
    writer = dialect.WRITER(ctx, source, dialect)  # type: ignore[misc]
    lane = choose(writer)
    return None if lane is None else type(lane)


PAIRS = tuple((source, target) for source in SOURCES for target in sorted(default_registry().dialects)
              if _lane(source, target) is not None)
"""Every pair of a source of the random programs and a target that a run writes with a lane."""


def _writer(target: str) -> type[WordWriter]:
    writer = default_registry().dialect(target).WRITER
    assert isinstance(writer, type) and issubclass(writer, WordWriter)
    return writer


@st.composite
def numbers(draw: st.DrawFn) -> str:
    """An axis or feed number: mostly canonical (what CAM writes), sometimes with more places than a
    writer spells exactly, a trailing zero, no leading zero or no point (the general path's cases)."""
    places = draw(st.integers(min_value=0, max_value=8))
    whole = draw(st.integers(min_value=-99999, max_value=99999))
    value = whole / 10 ** places
    text = f"{value:.{places}f}".rstrip("0") if places else f"{whole}."
    if text in ("-0.", "-0"):
        text = "0."
    shape = draw(st.sampled_from(["canonical"] * 6 + ["trailing zero", "no leading zero", "integer"]))
    if shape == "trailing zero":
        text += "0"
    elif shape == "no leading zero" and text.startswith(("0.", "-0.")) and text not in ("0.", "-0."):
        text = text.replace("0.", ".", 1)
    elif shape == "integer":
        text = str(whole)
    return text


def _decimal(value: Decimal) -> str:
    """A decimal in canonical spelling (``X12.5``, ``X0.``, ``X-0.125``)."""
    text = format(value.normalize(), "f") if value else "0"
    return text if "." in text else text + "."


@st.composite
def arcs(draw: st.DrawFn, number: str) -> list[str]:
    """An arc in one of the three planes, from a point a rapid move sets: a half circle with its centre
    I/J/K (its end point opposite its start, so on the circle) or its radius R, maybe a helix, maybe
    written as a straight path cannot (centre letters out of order, a zero radius, no end point in the
    plane, a following modal arc); each time, the straight path must write it as ``generate`` does."""
    plane = draw(st.sampled_from(["G17", "G18", "G19"]))
    first, second = {"G17": ("X", "Y"), "G18": ("Z", "X"), "G19": ("Y", "Z")}[plane]
    offset_letter = {"X": "I", "Y": "J", "Z": "K"}
    p = Decimal(draw(st.integers(min_value=-9999, max_value=9999))) / 100
    q = Decimal(draw(st.integers(min_value=-9999, max_value=9999))) / 100
    i = Decimal(draw(st.integers(min_value=-400, max_value=400))) / 8
    j = Decimal(draw(st.integers(min_value=-400, max_value=400))) / 8
    code = draw(st.sampled_from(["G2", "G02", "G3", "G03"]))
    out = [plane, "G90", f"G0 {first}{_decimal(p)} {second}{_decimal(q)}"]
    ends = {first: _decimal(p + 2 * i), second: _decimal(q + 2 * j)}
    axes = [f"{a}{ends[a]}" for a in "XYZ" if a in ends]
    shape = draw(st.sampled_from(["centre"] * 4 + ["radius", "helix", "reversed", "zero", "no end", "modal"]))
    feed = draw(st.sampled_from(["", " F250.", " F80."]))
    if shape == "radius":
        if j:  # a chord along the first axis, shorter than the diameter (grbl's float32 refuses a half
            # circle by R whose chord rounds longer than 2R: error 34)
            ends = {first: _decimal(p + 2 * j), second: _decimal(q)}
            axes = [f"{a}{ends[a]}" for a in "XYZ" if a in ends]
            out.append(f"{number}{code} {' '.join(axes)} R{_decimal(abs(j) + Decimal('0.5'))}{feed}")
        return out
    centre = {offset_letter[first]: _decimal(i), offset_letter[second]: _decimal(j)}
    words = [f"{k}{centre[k]}" for k in "IJK" if k in centre]
    if shape == "reversed":
        words.reverse()
    if shape == "helix":
        third = next(a for a in "XYZ" if a not in ends)
        axes.append(f"{third}-1.5")
    if shape == "zero":
        axes = [f"{first}{_decimal(p)}"]
        words = [f"{k}0." for k in "IJK" if k in centre]
    if shape == "no end":
        third = next(a for a in "XYZ" if a not in ends)
        axes = [f"{third}-2."]
    out.append(f"{number}{code} {' '.join(axes)} {' '.join(words)}{feed}")
    if shape == "modal":  # the same half circle back, its motion code modal
        back = {offset_letter[first]: _decimal(-i), offset_letter[second]: _decimal(-j)}
        out.append(f"{first}{_decimal(p)} {second}{_decimal(q)} " + " ".join(f"{k}{back[k]}" for k in "IJK" if k in back))
    return out


@st.composite
def lines(draw: st.DrawFn) -> list[str]:
    out = [draw(st.sampled_from(["G21", "G20"])), draw(st.sampled_from(["G90", "G91"])),
           draw(st.sampled_from(["G1 F100.", "G1 F100.", "G0", "G1"]))]
    if draw(st.booleans()):
        out.insert(0, "%")
    for i in range(draw(st.integers(min_value=1, max_value=12))):
        kind = draw(st.sampled_from(["move"] * 6 + ["coded"] * 2 + ["arc", "arc", "mode", "units", "rapid", "cycle"]))
        number = draw(st.sampled_from([f"N{10 * (i + 1)} ", f"N0{i + 1} ", "", f"N{10_000_000 + i} "]))  # (grbl's
        # limit is 10,000,000: a larger number is the general path's to drop)
        if kind == "arc":
            out.extend(draw(arcs(number)))
            out.append(draw(st.sampled_from(["G17 G1", "G17 G0"])))  # then straight moves again
        elif kind == "mode":
            out.append(draw(st.sampled_from(["G90", "G91", "G1", "G0"])))
        elif kind == "units":
            out.append(draw(st.sampled_from(["G20", "G21"])) + " F50.")
        elif kind == "cycle":  # an expansion's moves (``compound``: the base's ``item_line`` when declared)
            out.append("G0 Z5.")
            out.append(number + draw(st.sampled_from([
                "G99 G81 X1. Y2. Z-3. R1. F100.", "G98 G83 X0. Y1.5 Z-6. R1. Q2. F80.",
                "G82 X2. Y2. Z-1. R0.5 P500 F60.", "G91 G81 X5. Z-4. R-4. K3 F100."])))
            out.append(draw(st.sampled_from(["X3. Y1.", "Y-2."])))
            out.append("G80 G90")
        else:
            axes = draw(st.lists(st.sampled_from("XYZAB"), min_size=1, max_size=4, unique=True))
            if kind == "rapid":
                number += "G0 "
            elif kind == "coded":
                number += draw(st.sampled_from(["G1 ", "G01 ", "G0 ", "G00 "]))
            words = [f"{axis}{draw(numbers())}" for axis in axes]
            if draw(st.booleans()):
                feed = draw(numbers()).lstrip("-")
                words.append(f"F{feed}" if feed.strip("0.") else "F100.")
            out.append(number + " ".join(words))
    if out[0] == "%":
        out.append("%")
    return out


def _run(program: list[str], target: str, source: str = "fanuc", normalize: bool = True) -> str:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    setup = MachineSetup()
    setup.output.normalize = target == source and normalize
    try:
        translate([line + "\n" for line in program], out, file="p.nc", source=source, target=target,
                  diagnostics=diagnostics, setup=setup)
    except ErrorList as err:
        return "errors:\n" + str(err)
    return out.getvalue() + "\n".join(str(w) for w in diagnostics.warnings)


def _no_lane(writer: Writer) -> None:
    """``postproc.fast.lane.install`` turned off: every block takes the general path."""


@pytest.mark.parametrize(("source", "target"), PAIRS)
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(program=lines())
@example(program=["G21", "G90", "G1 F100.", "N10 X1.5 Y-2.25 Z0.001 F1200."])
@example(program=["G21", "G90", "G1 F100.", "N10000001 X1.5 Y-2.25 Z0.001 F1200."])  # above grbl's limit
@example(program=["G21", "G91", "G1 F100.", "X0.0000001", "X1.5"])
@example(program=["G21 G90", "G1 X1. F100.", "%"])  # a motion code in the first block: LinuxCNC sees it open
@example(program=["(SETUP)", "G1 X1. F100.", "%"])
@example(program=["%", "G1 X1. F100.", "G2 X3. Y0. I1. J0.", "%"])
@example(program=["G21 G90 G17", "G1 F100.", "G0 X1. Y1.", "G2 Z-2. I1. J0."])  # no end point in its plane
@example(program=["G21 G90 G18", "G1 F100.", "G0 X1. Z1.", "G3 X1. I0. K0."])  # zero radius
@example(program=["G21 G90 G19", "G1 F100.", "G0 Y1. Z1.", "G3 Y1. Z3. K1. J0."])  # centre words K before J
@example(program=["G21", "G90", "G1 F100.", "G0 Z5.", "G99 G81 X1. Y2. Z-3. R1. F100.", "X3. Y1.", "G80 G90"])
@example(program=["G20", "G91", "G0 Z1.", "G98 G83 X0. Y1.5 Z-6. R1. Q2. F80.", "G91 G81 X5. Z-4. R-4. K3 F100.",
                  "G82 X2. Y2. Z-1. R0.5 P500 F60.", "G80 G90"])  # an expansion's moves (``compound``)
@example(program=["G21 G90", "G0 Z10.", "G1 F100.", "G82 X2. Y2. Z-1. R0.5 P500 F60.", "G0 Z5.",
                  "G82 X3. Y2. Z-1. R0.5 P500 F60.", "G80"])  # a move on the lane cancels the cycle (Fagor's K)
def test_the_lane_writes_what_the_general_path_writes(program: list[str], source: str, target: str,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    fast = _run(program, target, source)
    with monkeypatch.context() as patch:
        patch.setattr(postproc.fast.lane, "install", _no_lane)
        slow = _run(program, target, source)
    assert fast == slow


COPIES = tuple(source for source in SOURCES if _lane(source, source, normalize=False) is not None)
"""The sources of the random programs whose copy (not normalised) a run writes with a lane."""


@pytest.mark.parametrize("source", COPIES)
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(program=lines())
@example(program=["G21 G90", "M3", "G95", "G1 X1. F0.1", "X2."])  # feed per revolution, no speed: refused
@example(program=["G21 G90", "G1 F100.", "N10 X1.5 Y-2.25 F1200.", "X0.0000001", "S1000.5 M3", "X2."])
def test_the_copy_lane_copies_what_the_general_path_copies(program: list[str], source: str,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    fast = _run(program, source, source, normalize=False)
    with monkeypatch.context() as patch:
        patch.setattr(postproc.fast.lane, "install", _no_lane)
        slow = _run(program, source, source, normalize=False)
    assert fast == slow


def test_the_lane_is_chosen_where_the_base_writes() -> None:
    """The lanes of the shipped writers: a dialect whose writer class overrides none of the methods a
    lane copies takes it; the test above would pass with no lane ever chosen."""
    lanes = {name: _lane("fanuc", name) for name in sorted(default_registry().dialects)}
    assert lanes["grbl"] is StraightLane and lanes["fanuc"] is CopyLane and _lane("linuxcnc", "grbl") is StraightLane
    assert lanes["isg"] is StraightLane and lanes["fagor"] is StraightLane  # (their splits: ``split_block``)
    assert _lane("fanuc", "fanuc", normalize=False) is SourceLane and COPIES == SOURCES
    assert all(lane in (None, StraightLane, CopyLane) for lane in lanes.values())


@pytest.mark.parametrize("target", sorted({target for source, target in PAIRS if source == "fanuc"}))
def test_cam_blocks_take_the_lane(target: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """A CAM program's straight blocks take the lane (``Writer.lane``): each block it answers, in order."""
    taken: list[str] = []
    install = postproc.fast.lane.install

    def counting(writer: Writer) -> None:
        install(writer)
        lane = writer.lane
        assert lane is not None

        class Counted(Lane):
            def write(self, block: Block) -> str | None:
                assert lane is not None
                text = lane.write(block)
                if text is not None:
                    taken.append(text)
                return text
        writer.lane = Counted()

    monkeypatch.setattr(postproc.fast.lane, "install", counting)
    program = ["G21 G90 G17", "G0 X0. Y0.", "N10 G1 Z-1. F300.", "N20 X10.5 Y2.25", "N30 X-3.125 Y0.5 F1200.",
               "X0.000001 Y7.", "N40 Y8.5 Z-1.5", "G0 X5.", "N50 X2.", "G1 X0. Y0.", "N60 G02 X4. Y0. I2. J0.",
               "G3 X0. Y0. R2.5", "X4. Y0. I2. J0."]
    out = _run(program, target)
    if target == "fanuc":  # normalised back: every block of a move (motion code or not) is its source line
        assert taken == [line + "\n" for line in program[1:]]
    else:
        expected = ["G0 X0. Y0.\n", "N10 G1 Z-1. F300.\n", "N20 G1 X10.5 Y2.25\n", "N30 G1 X-3.125 Y0.5 F1200.\n",
                    "G1 X0.000001 Y7.\n", "N40 G1 Y8.5 Z-1.5\n", "G0 X5.\n", "N50 G0 X2.\n", "G1 X0. Y0.\n",
                    "N60 G2 X4. Y0. I2. J0.\n", "G3 X0. Y0. R2.5\n", "G3 X4. Y0. I2. J0.\n"]
        assert [line.replace("G00", "G0").replace("G01", "G1").replace("G02", "G2").replace("G03", "G3")
                for line in taken] == expected
    assert all(line in out for line in taken)


class _Overriding(WordWriter):
    """A plugin writer that overrides how motion is written and says nothing about straight moves."""

    def motion_words(self, s: object, block: Block) -> list[str]:  # type: ignore[override]
        return ["G1", "X0."]


class _Delegating(WordWriter):
    """Overrides ``motion_words`` with the base's own: still an override (the lane cannot know)."""

    def motion_words(self, s: object, block: Block) -> list[str]:  # type: ignore[override]
        return super().motion_words(s, block)  # type: ignore[arg-type]


class _Normalizing(WordWriter):
    """Overrides how a block of its own dialect is normalised."""

    def normalized(self, block: Block) -> str:
        return super().normalized(block).lower()


def test_the_copy_puts_its_straight_lines(monkeypatch: pytest.MonkeyPatch) -> None:
    """A copy's straight blocks reach the output through ``SourceLane.put`` (the line and its end of line as two
    pieces, ``Batch.write_line``); a blank line, a comment, a tape mark and the other blocks through the writer's
    general path: the copy is the program, byte for byte (hand-derived: every line as written)."""
    put: list[str | None] = []
    install = postproc.fast.lane.install

    def counting(writer: Writer) -> None:
        install(writer)
        lane = writer.lane
        assert isinstance(lane, SourceLane) and lane.puts

        class Counted(Lane):
            def __init__(self) -> None:
                super().__init__()
                self.puts = True

            def write(self, block: Block) -> str | None:
                assert lane is not None
                return lane.write(block)

            def put(self, block: Block, out: Batch, below: int) -> bool:
                assert lane is not None
                done = lane.put(block, out, below)
                if done:
                    put.append(block.text)
                return done
        writer.lane = Counted()

    monkeypatch.setattr(postproc.fast.lane, "install", counting)
    program = ["%", "O1000 (COPY)", "G21 G90 G17", "G0 X0. Y0.", "   ", "N10 G1 Z-1. F300.", "N20  X10.5 Y2.25",
               "(A COMMENT)", "", "N30 X-3.125", "M30", "%"]
    assert _run(program, "fanuc", normalize=False) == "".join(line + "\n" for line in program)
    assert put == ["G0 X0. Y0.", "N10 G1 Z-1. F300.", "N20  X10.5 Y2.25", "N30 X-3.125"]


def test_an_override_turns_the_lane_off() -> None:
    """Whatever an override does, the lane is not taken for its class (a plugin declares nothing)."""
    assert own(WordWriter, STRAIGHT_METHODS) and own(WordWriter, COPY_METHODS)
    assert not own(_Overriding, STRAIGHT_METHODS)
    assert not own(_Delegating, STRAIGHT_METHODS)
    assert not own(_Normalizing, COPY_METHODS) and own(_Normalizing, STRAIGHT_METHODS)


def test_canonical_numbers_have_at_most_max_places() -> None:
    """``StraightLane`` relies on it: a writer exact to ``MAX_PLACES`` places writes every canonical number
    as written, so only its magnitude is tested (``postproc.numbers.SHORT_RANGE``)."""
    from postproc.numbers import CANONICAL_BLOCK, MAX_PLACES
    from postproc.rs274.canonical_line import CANONICAL, scan_words

    most, more = "X0." + "1" * MAX_PLACES, "X0." + "1" * (MAX_PLACES + 1)
    assert CANONICAL_BLOCK.fullmatch(most) and not CANONICAL_BLOCK.fullmatch(more)
    assert scan_words(most)[0] & CANONICAL and not scan_words(more)[0] & CANONICAL


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
@pytest.mark.parametrize("below", [0, 14, 20, 24])
def test_the_straight_lane_puts_the_lines_its_rule_passes(target: str, below: int,
                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    """Under a line rule (grbl's buffer, LinuxCNC's length), ``StraightLane.put`` puts a move's line and its end of
    line into the output where the text is shorter than the length the rule passes as it is (``passes_below``, made
    shorter here: 14, 20 and 24 characters; 0 keeps the rule's own), and leaves a longer one to ``write`` and the
    rule, having changed nothing (the feed rate is carried once: an ``F`` only on the blocks that say it). The
    output is the general path's, and which lines were put is told by their lengths (hand-derived)."""
    put: list[str] = []
    install = postproc.fast.lane.install

    def counting(writer: Writer) -> None:
        install(writer)
        lane = writer.lane
        assert isinstance(lane, StraightLane) and lane.puts and lane.passes_below > 0
        if below:
            lane.passes_below = below

        class Counted(Lane):
            def __init__(self) -> None:
                super().__init__()
                self.puts = True
                self.passes_below = lane.passes_below if isinstance(lane, Lane) else 0

            def write(self, block: Block) -> str | None:
                assert lane is not None
                text = lane.write(block)
                self.plain = lane.plain
                return text

            def put(self, block: Block, out: Batch, limit: int) -> bool:
                assert lane is not None and limit == self.passes_below
                done = lane.put(block, out, limit)
                if done:
                    put.append(str(block.text))
                return done
        writer.lane = Counted()

    monkeypatch.setattr(postproc.fast.lane, "install", counting)
    program = ["G21 G90 G17", "G0 X0. Y0.", "N10 G1 Z-1. F300.", "N20 X10.5 Y2.25", "N30 X-3.125 Y0.5 F1200.",
               "X1. Y7.", "N40 Y8.5 Z-1.5", "G0 X5."]
    fast = _run(program, target)
    with monkeypatch.context() as patch:
        patch.setattr(postproc.fast.lane, "install", _no_lane)
        assert fast == _run(program, target)
    # the lines written, G0 or G1 and the end of line included: 11, 18, 19, 27, 11, 18 and 7 characters
    moves = program[1:]
    written = [11, 18, 19, 27, 11, 18, 7]
    expected = [line for line, n in zip(moves, written) if not below or n < below]
    assert put == expected and (below or put == moves)
