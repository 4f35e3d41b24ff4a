"""One place decides what a valid block is (``postproc.block_rules``): ``translate`` refuses what
``toolpath`` refuses - a negative F or S, a feed move with no feed rate - with the same located message,
to every target."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events

CASES = [
    ("G1 X10. F-100.", "p.nc:3:9: error: feed rate F-100 cannot be negative"),
    ("G1 X10.", "p.nc:3:1: error: a feed move with no feed rate (program F first)"),
    ("G2 X10. R5.", "p.nc:3:1: error: a feed move with no feed rate (program F first)"),
    ("S-1000 M3", "p.nc:3:1: error: spindle speed S-1000 cannot be negative"),
    ("G1 X10. F0", "p.nc:3:1: " + "error: a feed move at a zero feed rate (F0 is in force: program a feed rate above 0 first)"),
    ("G3 X10. R5. F0.", "p.nc:3:1: error: a feed move at a zero feed rate (F0 is in force: program a feed rate above 0 "
                        "first)"),
]


def _program(line: str) -> str:
    return f"G21 G17 G90\nG0 X0. Y0. Z0.\n{line}\nM30\n"


@pytest.mark.parametrize("target", ["fanuc", "grbl", "linuxcnc"])
@pytest.mark.parametrize("line, message", CASES)
def test_translate_refuses_what_toolpath_refuses(target: str, line: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(_program(line)), io.StringIO(), file="p.nc", source="fanuc", target=target)
    assert [str(e) for e in info.value.errors] == [message]


@pytest.mark.parametrize("line, message", CASES)
def test_toolpath_gives_the_same_message(line: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(_program(line)), file="p.nc", dialect="fanuc"))
    assert [str(e) for e in info.value.errors] == [message]


def test_feed_set_inside_an_expanded_cycle_counts() -> None:
    """A cycle's F feeds its expansion, and the feed stays in force after it."""
    program = "G21 G17 G90\nG0 X0. Y0. Z10.\nG98 G81 X5. Y5. Z-1. R2. F100.\nG80\nG1 X0.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="grbl")
    assert "G1 X0." in out.getvalue()


def test_zero_length_feed_move_needs_a_feed_too() -> None:
    """The command is what a controller refuses, even when the tool would not move."""
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(_program("G1 X0.")), file="p.nc", dialect="fanuc"))
    assert [str(e) for e in info.value.errors] == ["p.nc:3:1: error: a feed move with no feed rate (program F first)"]


def test_a_zero_feed_rate_refuses_feed_moves_only() -> None:
    """F0 is a value a program may set (a rapid move ignores it); the feed move after it is what Fanuc
    (FEED ZERO), rs274 and grbl refuse, and the first block programming a rate again is fine."""
    program = "G21 G17 G90\nG1 X1. F100.\nF0\nG0 X2.\nG1 X3.\nG1 X4. F50.\nM30\n"
    message = "p.nc:5:1: error: a feed move at a zero feed rate (F0 is in force: program a feed rate above 0 first)"
    for target in ("fanuc", "linuxcnc", "grbl"):
        with pytest.raises(ErrorList) as info:
            translate(io.StringIO(program), io.StringIO(), file="p.nc", source="fanuc", target=target)
        assert [str(e) for e in info.value.errors] == [message]
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(program), file="p.nc", dialect="fanuc"))
    assert [str(e) for e in info.value.errors] == [message]
    fine = program.replace("G1 X3.\n", "")
    translate(io.StringIO(fine), io.StringIO(), file="p.nc", source="fanuc", target="linuxcnc")


def test_a_zero_feed_rate_in_a_program_that_computes_is_left_to_the_run() -> None:
    """``F100 GOTO 20 / N10 F0 / N20 G1 X1.`` runs: the jump skips the F0. The text's order says otherwise,
    so ``translate`` keeps the program; the run (toolpath) follows the jump and finds nothing wrong."""
    program = "G21 G17 G90\nG0 X0. Y0.\nF100.\nGOTO 20\nN10 F0\nN20 G1 X1.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="fanuc")
    assert "N10 F0" in out.getvalue()
    assert list(toolpath_events(io.StringIO(program), file="p.nc", dialect="fanuc"))


def test_a_program_that_computes_leaves_the_feed_order_to_the_run() -> None:
    """A subroutine defined before the main program feeds at its caller's F: from the first construct on,
    the text's order is not the run's, and the step does not judge it (the run does)."""
    from postproc.context import Context
    from postproc.interp.control import SubEnd, SubStart
    from postproc.dialect import Dialect
    from postproc.errors import Diagnostics
    from postproc.ir import Block, Feed, Motion
    from postproc.lowering.feed_first import check_blocks
    from postproc.setup.machine_setup import MachineSetup

    def block(line: int, *sections: object) -> Block:
        b = Block(line, None, "\n")
        for s in sections:
            b.add(s)  # type: ignore[arg-type]
        return b

    blocks = [block(1, SubStart("s")), block(2, Motion("linear", {"X": 5.0})), block(3, SubEnd("s")),
              block(4, Feed(200.0))]
    diagnostics = Diagnostics()
    ctx = Context("p.ngc", MachineSetup(), diagnostics, "linuxcnc")
    assert list(check_blocks(iter(blocks), ctx, Dialect)) == blocks
    assert diagnostics.errors == []
    diagnostics = Diagnostics()
    ctx = Context("p.ngc", MachineSetup(), diagnostics, "linuxcnc")
    list(check_blocks(iter(blocks[1:2]), ctx, Dialect))
    assert [e.message for e in diagnostics.errors] == ["a feed move with no feed rate (program F first)"]


ARCS = [
    ("G02 X20. Y0 I5. J0", "t.nc:3:13: error: arc end point is not on the circle: radius 5.0000 mm at the start, "
                          "15.0000 mm at the end (the controller accepts a difference up to 0.01 mm here)"),
    ("G02 X10. Y0 R2.", "t.nc:3:13: error: arc radius 2.0000 mm is too small for a chord of 10.0000 mm"),
    ("G03 X0 Y0 R5.", "t.nc:3:11: error: a full circle cannot be programmed with R (use I/J/K)"),
]


@pytest.mark.parametrize("arc, message", ARCS)
@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_translate_refuses_the_arcs_the_toolpath_refuses(arc: str, message: str, target: str) -> None:
    """One place decides (postproc.block_rules.arc_centre): translate, toolpath and verify agree."""
    program = f"G21 G17 G90 G00 X0 Y0 Z5.\nG01 Z-1. F100.\n{arc}\nM30\n"
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source="fanuc", target=target)
    assert [str(e) for e in exc.value.errors] == [message]
    with pytest.raises(ErrorList) as exc:
        list(toolpath_events(io.StringIO(program), file="t.nc", dialect="fanuc"))
    assert [str(e) for e in exc.value.errors] == [message]


@pytest.mark.parametrize("target, normalize", [("linuxcnc", False), ("grbl", False), ("fanuc", True)])
def test_a_feed_rate_written_as_zero_is_refused(target: str, normalize: bool) -> None:
    """F0.0000001 is no zero feed in the source, but the output's resolution writes it F0., which the
    controller refuses for the feed move after it: the translation fails instead."""
    from postproc.setup.machine_setup import MachineSetup

    setup = MachineSetup()
    setup.output.normalize = normalize
    program = "G21 G17 G90\nG0 X0. F0.0000001\nG1 X1.\nM30\n"
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(program), io.StringIO(), file="p.nc", source="fanuc", target=target, setup=setup)
    assert [str(e) for e in info.value.errors] == [
        "p.nc:2:8: error: feed rate F1e-07 is written F0. at the output's resolution: a zero feed rate, which the "
        "controller refuses for a feed move"]
