"""The plain-block lane (``postproc.fast.plain``) reads a block as the block syntax's general path does.

A CAM program's usual blocks (``N.. G1 X.. Y.. F..``, ``G2 X.. Y.. R..``, ``G3 X.. Y.. I.. J..``, or axis
words alone) are read in one pass; anything else goes to the general path, which also explains every
error. Random programs of such blocks, mixed with what must leave the lane (a second code, point-less
numbers, I/J/K/R beside a straight move, both arc forms, a repeated address, lower-case letters, under an
active canned cycle anything but N and axis words), are read twice, with the lane and without it
(``postproc.fast.reading.block_lane`` answering None): blocks, sections, warnings and errors must be the
same, for every reading the lane is chosen for (mill and lathe; the RS274/NGC readings take their own lane,
``postproc.fast.plain_ngc``, with its own rules: a block number first, no motion mode after a cycle cancel, a
feed rate in force for a feed motion code, the dialect's declared hooks).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import postproc.fast.reading as reading
from postproc.api import read_program
from postproc.errors import Diagnostics, ErrorList
from postproc.fast.reading import install_reading
from postproc.fast.plain import PlainLane, PlainLatheLane, whole_number
from postproc.fast.plain_ngc import NgcPlainLane
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.collector import gc_paused
from postproc.reading import read_blocks
from postproc.rs274.block_syntax import WordBlockSyntax
from postproc.setup.machine_setup import MachineSetup

CANDIDATES = (("fanuc", "mill"), ("fanuc", "lathe"), ("gsk", "lathe"), ("isg", "mill"), ("fagor", "mill"),
              ("linuxcnc", "mill"), ("linuxcnc", "lathe"), ("grbl", "mill"), ("grblhal", "mill"), ("mach3", "mill"))


def _setup(machine: str) -> MachineSetup:
    setup = MachineSetup()
    setup.input.machine_type = machine  # type: ignore[assignment]
    return setup


def _syntax(dialect: str, machine: str) -> WordBlockSyntax | None:
    """The block syntax of the reading (None: it has none of the family's)."""
    steps = default_registry().dialect(dialect).pipeline(_setup(machine)).steps
    return next((step for step in steps if isinstance(step, WordBlockSyntax)), None)


def _takes_lane(dialect: str, machine: str) -> bool:
    syntax = _syntax(dialect, machine)
    return syntax is not None and reading.block_lane(syntax) is not None


READINGS = tuple(reading_ for reading_ in CANDIDATES if _takes_lane(*reading_))
"""The readings the lane is chosen for."""


@contextmanager
def lanes(make: Any) -> Iterator[None]:
    """The run's plain-block lane made by ``make(syntax)`` (None: no lane)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(reading, "block_lane", make)
        yield


def _read(program: list[str], dialect: str, machine: str, setup: MachineSetup | None = None) -> str:
    """The blocks read, then the warnings (the point-mix check's among them), or the errors."""
    diagnostics = Diagnostics()
    try:
        with gc_paused():
            _, stream = read_blocks([line + "\n" for line in program], "p.nc", default_registry().dialect(dialect),
                                    setup or _setup(machine), diagnostics, lanes=install_reading)
            blocks = list(stream)
        diagnostics.check()
    except ErrorList as err:
        return "errors:\n" + str(err)
    return "\n".join([_shown(b) for b in blocks] + [f"warning: {w}" for w in diagnostics.warnings])


def _shown(block: Block) -> str:
    return f"{block.line} {block.words} {sorted(block.values.items())} {list(block.sections.values())!r}"


@st.composite
def number(draw: st.DrawFn) -> str:
    """Mostly a pointed number (what CAM writes); sometimes a point-less one or a trailing zero."""
    whole = draw(st.integers(min_value=-9999, max_value=9999))
    places = draw(st.integers(min_value=0, max_value=4))
    text = f"{whole / 10 ** places:.{places}f}".rstrip("0") if places else f"{whole}."
    shape = draw(st.sampled_from(["pointed"] * 6 + ["bare", "trailing zero"]))
    if shape == "bare":
        return str(whole)
    return text + "0" if shape == "trailing zero" else text


@st.composite
def programs(draw: st.DrawFn) -> list[str]:
    out = [draw(st.sampled_from(["G21", "G20"])), draw(st.sampled_from(["G90", "G91", ""])),
           draw(st.sampled_from(["G1 F100.", "G0", "G2", "", "G17", "G18"]))]
    for i in range(draw(st.integers(min_value=1, max_value=10))):
        words: list[str] = []
        number_last = False
        if draw(st.integers(min_value=0, max_value=3)):
            words.append(draw(st.sampled_from([f"N{10 * (i + 1)}", f"N0{i + 1}", "N1.5", f"n{i + 1}"])))
            number_last = draw(st.integers(min_value=0, max_value=7)) == 0  # RS274/NGC: N first or nowhere
        code = draw(st.sampled_from(["", "", "G1", "G01", "G0", "G00", "G2", "G02", "G3", "G03", "g1", "G4",
                                     "G17", "G90 G1", "G1 G2", "G81", "G80", "G2.5", "G001",
                                     "G98 G81 Z-2. R1. F50.", "G90.1", "G91.1", "G64 P0.1", "G61", "G93", "G94",
                                     "G33 K1.", "G1 F0."]))
        if code:
            words.append(code)
        for letter in draw(st.lists(st.sampled_from("XYZUWAB"), max_size=3, unique=True)):
            words.append(letter + draw(number()))
        for letter in draw(st.lists(st.sampled_from("IJKRQ"), max_size=2, unique=True)):
            words.append(letter + draw(number()))
        extra = draw(st.sampled_from(["", "", "", "F300.", "F250", "X1.", "M3", "R2. Z-3.", "x2.5"]))
        if extra:
            words.append(extra)
        if number_last:
            words.append(words.pop(0))
        out.append(draw(st.sampled_from(["", "", "", "", " ", "/"])) + " ".join(words))
    return [line for line in out if line]


@pytest.mark.parametrize("dialect,machine", READINGS)
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(program=programs())
@example(program=["G21", "G90", "G1 F100.", "N10 X1.5 Y-2.25", "G2 X3. Y1. R2.", "G03 X1. I-1. J0.5 F200."])
@example(program=["G21", "G3 X1. Y2. I1.", "X2. Y3. R1.5", "G0 X1. R2."])
@example(program=["G21", "G90", "G1 F100.", "X1. X2.", "N10 G1 X1. Y2. X3.", "N20 X1. F1. F2.", "G1 G1 X1.",
                  "G2 X1. I1. I2."])  # repeated addresses: the general path refuses them
@example(program=["G21", "G90", "G0 X0. Y0. Z5.", "G99 G81 X1. Y2. Z-3. R1. F100.", "X2.", "N30 Y3.5", "X4 Y5",
                  "x5.", "Z-4.", "X6. R0.5", "X7. F90.", "N40", "X1. X2.", "G80", "X8."])  # the next holes of a cycle
@example(program=["G21", "G90", "G1 F100.", "X1. U2.", "Z1. W-1.", "G2 X2. Z1. I1. J0."])  # lathe: its own refusals
@example(program=[":1234", "G21 G90", "G1 X1. F100."])  # ISO's program number address
def test_the_lane_reads_what_the_general_path_reads(program: list[str], dialect: str, machine: str) -> None:
    fast = _read(program, dialect, machine)
    with lanes(lambda syntax, numbers=None: None):
        slow = _read(program, dialect, machine)
    assert fast == slow


@st.composite
def cam_programs(draw: st.DrawFn) -> list[str]:
    """A CAM program's moves, arcs and next holes whose axis and arc words are now and then point-less (least
    input increments, or calculator input), in either unit system: the numbers the lane reads with the
    general path's divisor, and the point-mix warning it tells in word order."""
    out = [draw(st.sampled_from(["G21 G90", "G20 G90", "G21 G91"])), "G0 X0. Y0. Z5."]
    for i in range(draw(st.integers(min_value=1, max_value=8))):
        words = [f"N{10 * (i + 1)}"] if draw(st.booleans()) else []
        code = draw(st.sampled_from(["", "", "G1", "G0", "G2", "G3", "G81 Z-2. R1. F50.", "G80"]))
        if code:
            words.append(code)
        for letter in draw(st.lists(st.sampled_from("XYZ"), max_size=3, unique=True)):
            words.append(letter + draw(number()))
        if code in ("G2", "G3"):
            for letter in draw(st.sampled_from(["IJ", "I", "J", "R"])):
                words.append(letter + draw(number()))
        if draw(st.integers(min_value=0, max_value=4)) == 0:
            words.append(draw(st.sampled_from(["F300.", "X-0", "Y+12", "Z0012"])))
        out.append(" ".join(words))
    return [line for line in out if line]


@settings(max_examples=150, deadline=None)
@given(program=cam_programs(), system=st.sampled_from(["IS-A", "IS-B", "IS-C"]),
       point=st.sampled_from(["least-increment", "least-increment", "calculator"]),
       machine=st.sampled_from(["mill", "lathe"]))
@example(program=["G21 G90", "G1 X1. Y2. F100.", "X1500 Y2.5", "G2 X0 Y1000 I-1000 J0"], system="IS-B",
         point="least-increment", machine="mill")  # X mixed, warned at the block's X1500
@example(program=["G21 G90", "G1 X1500 Y2500 F100.", "Y3. X4."], system="IS-C",
         point="least-increment", machine="mill")  # two axes mixed in one block: word order says which warns
@example(program=["G20 G90", "G81 X1. Y1. Z-0.1 R0.1 F5.", "X2000 Y3.", "X3. Y4000", "G80"], system="IS-A",
         point="least-increment", machine="mill")  # next holes, inch
def test_point_less_numbers_read_as_the_general_path_reads(program: list[str], system: str, point: str,
                                                           machine: str) -> None:
    setup = _setup(machine)
    setup.input.increment_system = system  # type: ignore[assignment]
    setup.input.decimal_point = point  # type: ignore[assignment]
    fast = _read(program, "fanuc", machine, setup)
    with lanes(lambda syntax, numbers=None: None):
        slow = _read(program, "fanuc", machine, setup)
    assert fast == slow


def test_point_less_words_take_the_lane() -> None:
    """A block with a point-less axis or arc word is read by the lane (the test above would pass with the lane
    declining every such block), with the general path's values and the point-mix warning."""
    taken: list[int] = []

    class Counted(PlainLane):
        __slots__ = ()

        def read(self, block: Block, ctx: Any, words: Any) -> bool:
            took = super().read(block, ctx, words)
            if took:
                taken.append(block.line)
            return took

        def read_marked(self, block: Block, ctx: Any) -> bool:  # a canonical line, its words unmade
            took = super().read_marked(block, ctx)
            if took:
                taken.append(block.line)
            return took

    program = ["G21 G90 G17", "G1 X1. Y2. F100.", "N10 X1500 Y2.5", "G2 X0.5 Y3500 I-1000 J0", "G3 X1. Y0 R5000"]
    with lanes(Counted):
        shown = _read(program, "fanuc", "mill")
    assert taken == [2, 3, 4, 5]
    assert "('X', 1.5), ('Y', 2.5)" in shown and "('I', -1.0), ('J', 0.0)" in shown and "('R', 5.0)" in shown
    assert "p.nc:3:5" in shown and "X1500 has no decimal point" in shown


@given(num=st.one_of(st.integers(min_value=0, max_value=10 ** 20).map(str),
                     st.from_regex(r"[+-]?[0-9]{1,20}", fullmatch=True)))
@example(num="999999999999999999")  # 18 digits: summed
@example(num="9999999999999999999")  # 19: by int
@example(num="0010")
def test_a_block_number_reads_as_int_reads_it(num: str) -> None:
    """The lanes' block number (``whole_number``) is ``int``'s, summed for plain digits."""
    assert whole_number(num) == int(num)


@settings(max_examples=60, deadline=None)
@given(program=programs())
@example(program=["G21", "G90", "G1 F100.", "N10 X1.5 Y-2.25", "G2 X3. Y1. R2.", "G03 X1. I-1. J0.5 F200."])
def test_a_line_scanned_again_reads_as_the_readers_scan(program: list[str]) -> None:
    """A block whose line is not the one whose numbers the run holds (a step read ahead; here: a lane that never
    shares the reader's ``LineNumbers``) is scanned again for them: the same blocks."""
    shared = _read(program, "fanuc", "mill")
    with lanes(lambda syntax, numbers=None: PlainLane(syntax)):
        apart = _read(program, "fanuc", "mill")
    assert shared == apart


def test_the_lane_is_chosen_where_the_base_reads() -> None:
    """Fanuc's mill and lathe readings and GSK's take the lane; a reading whose class overrides a method the
    lane skips (ISG's and Fagor's ``g_sections``, grblHAL's ``_g_code``) does not: the test above would pass
    with no lane ever chosen. LinuxCNC's, grbl's and Mach3's take the RS274/NGC lane: LinuxCNC overrides only
    hooks its declarations select (``before_sections``, ``after_sections``, ``special_g_code``)."""
    assert {("fanuc", "mill"), ("fanuc", "lathe"), ("gsk", "lathe"), ("linuxcnc", "mill"), ("grbl", "mill"),
            ("mach3", "mill")} <= set(READINGS)
    assert not {("isg", "mill"), ("fagor", "mill"), ("grblhal", "mill")} & set(READINGS)
    lathe = _syntax("fanuc", "lathe")
    assert lathe is not None and type(reading.block_lane(lathe)) is PlainLatheLane
    ngc = _syntax("linuxcnc", "mill")
    assert ngc is not None and type(reading.block_lane(ngc)) is NgcPlainLane

    class Overriding(type(_syntax("fanuc", "mill"))):  # type: ignore[misc]
        __slots__ = ()

        def finish_words(self, *args: Any) -> None:
            super().finish_words(*args)

    assert reading.block_lane(Overriding()) is None


def test_cam_blocks_take_the_lane() -> None:
    """Count the blocks the lane reads: each plain one, in order."""
    taken: list[int] = []

    class Counted(PlainLane):
        __slots__ = ()

        def read(self, block: Block, ctx: Any, words: Any) -> bool:
            took = super().read(block, ctx, words)
            if took:
                taken.append(block.line)
            return took

        def read_marked(self, block: Block, ctx: Any) -> bool:  # a canonical line, its words unmade
            took = super().read_marked(block, ctx)
            if took:
                taken.append(block.line)
            return took

    program = ["G21 G90 G17", "G0 X0. Y0.", "N10 G01 Z-1. F300.", "N20 X10.5 Y2.25", "G02 X12. Y4. R2.",
               "N30 G3 X10. Y6. I-2. J0.", "X8. Y4. I0. J-2.", "G1 X0. Y0. F1200.", "G0 Z5. M9"]
    with lanes(Counted):
        read_program([line + "\n" for line in program], file="p.nc", dialect="fanuc")
    assert taken == [2, 3, 4, 5, 6, 7, 8]


def test_ngc_cam_blocks_take_the_lane() -> None:
    """Count the blocks the RS274/NGC lane reads: the plain ones, not a block with an M code, nor one a
    LinuxCNC hook reads (after ``G90.1`` its arcs' centres are absolute: ``after_sections``, until ``G91.1``),
    nor a block number that is not the first word (refused by the general path)."""
    taken: list[int] = []

    class Counted(NgcPlainLane):
        __slots__ = ()

        def read(self, block: Block, ctx: Any, words: Any) -> bool:
            took = super().read(block, ctx, words)
            if took:
                taken.append(block.line)
            return took

        def read_marked(self, block: Block, ctx: Any) -> bool:  # a canonical line, its words unmade
            took = super().read_marked(block, ctx)
            if took:
                taken.append(block.line)
            return took

    program = ["G21 G90 G17", "G0 X0 Y0", "N10 G01 Z-1. F300.", "N20 X10.5 Y2.25", "G02 X12 Y4 R2",
               "N30 G3 X10 Y6 I-2 J0", "x8 y4 i0 j-2", "G1 X0 Y0 F1200", "G0 Z5 M9", "G90.1", "G2 X2 Y0 I1 J0",
               "G91.1", "G1 X1 Y1", "Y2 N40"]
    with lanes(lambda syntax, numbers=None: Counted(syntax)):
        try:
            read_program([line + "\n" for line in program], file="p.ngc", dialect="linuxcnc")
        except ErrorList as err:
            assert "p.ngc:14:" in str(err)  # the number last: refused by the general path
        else:
            raise AssertionError("N last was read")
    assert taken == [2, 3, 4, 5, 6, 7, 8, 13]


def test_modal_arc_without_centre_is_refused_where_it_is() -> None:
    """The lane declines an arc with no centre; the general path refuses it, located."""
    with pytest.raises(ErrorList, match=r"p\.nc:3:1: error: an arc needs a centre"):
        read_program(["G21 G90\n", "G2 X1. Y1. R1.\n", "X2. Y2.\n"], file="p.nc", dialect="fanuc")
