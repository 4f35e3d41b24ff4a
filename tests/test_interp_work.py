"""The interpreter's work bound (``Limits.repeated_work``): the blocks a run executes again, and the moves
they expand to, whatever its loops' iteration counts. A hostile loop (``M99`` in the main program,
``WHILE [1 EQ 1]``, ISG ``$WHILE 1``, ``$FOR`` with step 0, ``o.. repeat [99999999]``, a recursion that
calls itself twice, a loop around a cycle of 9999 holes) ends with a located error naming the repetition
that ran last, in every dialect and for every command; a straight program of any length runs once and
never reaches it.

Expected counts are derived by hand from each program below.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.interp.control import EndWhile, While
from postproc.errors import Diagnostics, ErrorList
from postproc.ir.expr import Binary, Num, Var
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.test_interp import P, error_of, run, v, words


def test_the_bound_counts_blocks_run_again_not_iterations():
    # the first iteration runs each block once (free); from the second on, an iteration runs 12 blocks
    # again (the while, ten moves, the end): iterations 2-9 run 96, the tenth its while and three moves
    # (100), and its fourth move is the 101st
    p = P()
    p(control=While("1", Binary("ne", Var(Num(1.0)), Num(-1.0))))  # tests the count (a fixed test is refused at once)
    for i in range(10):
        p(("X", f"{i}."))
    p(control=EndWhile("1"), assign=[(Var(Num(1.0)), Binary("add", Var(Num(1.0)), Num(1.0)))])  # counts: no iteration repeats
    p(("M", "30"))
    limits = Limits(repeated_work=100, loop_iterations=1_000_000)
    assert error_of(p, limits=limits) == (
        "main.nc:12:1: error: loop '(statement 12)' repeats more than 100 blocks and moves in all (the set-up's "
        "bound on work run again, <Limits repeatedWork=\"100\"/>)")
    ran: list[str] = []
    with pytest.raises(ErrorList):
        for block in _stream(p, limits):
            ran.extend(words([block]))
    assert len(ran) == 9 * 10 + 3


def test_every_block_held_runs_once_whatever_the_bound():
    # a computed program of 5000 straight moves: each runs once, within a bound of 1
    p = P()
    p(assign=[(v(1), Num(2.0))])
    for i in range(5000):
        p(("X", f"{i}."))
    p(("M", "30"))
    out = run(p, limits=Limits(repeated_work=1))
    assert len(words(out)) == 5001


def _stream(program: P, limits: Limits):
    """The interpreter's blocks one by one (``run`` collects them all before its check)."""
    from postproc.context import Context
    from postproc.errors import ErrorLevel
    from postproc.plugins import default_registry
    from tests.test_interp import FanucLike
    ctx = Context("main.nc", MachineSetup(limits=limits), Diagnostics(ErrorLevel.RAISE), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    ctx.program_mode = "execute"
    yield from FanucLike().process(iter(program.blocks), ctx)
    ctx.diagnostics.check()


HOSTILE = [
    # (dialect, program, the repetition named: line:col and how; a recursion: either of its two calls)
    ("fanuc", "#1=#1+1\nM99\n", "2:1: error: return 'M99'"),
    ("fanuc", "#1=0\nWHILE [#1 GE 0] DO1\nG0 X#1\n#1=#1+1\nEND1\nM30\n", "5:1: error: loop 'END1'"),
    ("fanuc", "#1=0\nN1 G0 X#1\n#1=#1+1\nGOTO 1\nM30\n", "4:1: error: jump 'GOTO 1'"),
    # each level calls itself twice down to level 40: 2^40 calls
    ("fanuc", "O1\n#1=0\nM98 P1000\nM30\nO1000\n#1=#1+1\nIF [#1 GT 40] GOTO 9\nM98 P1000\nM98 P1000\n"
              "N9 #1=#1-1\nM99\n", ("8:1: error: call 'M98 P1000'", "9:1: error: call 'M98 P1000'")),
    ("isg", "%1\nP1=0\n$WHILE P1 >= 0\nG0 X[P1]\nP1=P1+1\n$ENDWHILE\nM30\n", "6:1: error: loop '$ENDWHILE'"),
    ("isg", "%1\n$FOR P1 = 0, 1000000000, 1\nG0 X[P1]\n$ENDFOR\nM30\n", "4:1: error: loop '$ENDFOR'"),
    ("linuxcnc", "o100 repeat [99999999]\nG0 X1\no100 endrepeat\nM2\n", "3:1: error: loop 'o100 endrepeat'"),
    # a cycle of 9999 holes (4 moves each) in an endless loop: the moves of a block run again count
    ("fanuc", "G90 G0 X0 Y0 Z10\n#1=0\nWHILE [#1 GE 0] DO1\nG81 X0 Y0 Z-1 R1 K9999 F100\nG80\n#1=#1+1\nEND1\nM30\n",
     "7:1: error: loop 'END1'"),
    ("linuxcnc", "G90 G0 X0 Y0 Z10\no1 while [#1 GE 0]\nG81 X0 Y0 Z-1 R1 L9999 F100\nG80\n#1=[#1+1]\no1 endwhile\nM2\n",
     "6:1: error: loop 'o1 endwhile'"),
    ("linuxcnc", "o<w> sub\n#<d>=[#1+1]\no100 if [#<d> LT 9]\no<w> call [#<d>]\no<w> call [#<d>]\no100 endif\n"
                 "G0 X1\no<w> endsub\no<w> call [0]\nM2\n",
     ("4:1: error: call 'o<w> call [#<d>]'", "5:1: error: call 'o<w> call [#<d>]'")),
]


@pytest.mark.parametrize("dialect, program, named", HOSTILE)
def test_a_hostile_loop_ends_at_the_work_bound_naming_its_repetition(dialect, program, named):
    # the iteration bound is far off (every iteration runs at least one block): only the work bound ends
    # these within 2000 blocks
    setup = MachineSetup(limits=Limits(repeated_work=2000, loop_iterations=50_000))
    expected = [f"t.nc:{one} repeats more than 2000 blocks and moves in all (the set-up's bound on work run "
                "again, <Limits repeatedWork=\"2000\"/>)" for one in ((named,) if isinstance(named, str) else named)]
    with pytest.raises(ErrorList) as info:  # flattened for a target without control flow
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source=dialect, target="grbl", setup=setup,
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    _one(info.value, expected)
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(program), file="t.nc", dialect=dialect, setup=setup,
                             diagnostics=Diagnostics(warn_stream=io.StringIO())))
    _one(info.value, expected)


def _one(errors: ErrorList, expected: list[str]) -> None:
    """One error, one of ``expected`` (an error inside a call goes on with the call stack)."""
    assert len(errors.errors) == 1
    found = str(errors.errors[0])
    assert any(found == one or found.startswith(one + " (in ") for one in expected), found


def test_the_default_bound():
    """A million: a parametric program of 20,000 holes in nested loops (make bench, 141k blocks run) passes;
    an endless loop ends in about ten seconds. Its message, at a tenth of it (a second)."""
    assert Limits().repeated_work == 1_000_000
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO("#1=#1+1\nM99\n"), file="t.nc", dialect="fanuc",
                             setup=MachineSetup(limits=Limits(repeated_work=100_000)),
                             diagnostics=Diagnostics(warn_stream=io.StringIO())))
    assert [str(e) for e in info.value.errors] == [
        "t.nc:2:1: error: return 'M99' repeats more than 100000 blocks and moves in all (the set-up's bound on work "
        "run again, <Limits repeatedWork=\"100000\"/>)"]


@pytest.mark.parametrize("dialect, program, error", [
    ("fanuc", "#1=0\nWHILE [1 EQ 1] DO1\nG0 X#1\nEND1\nG0 X1.2.3\nM30\n", "t.nc:5:"),
    ("isg", "%1\n$WHILE 1\nG0 X1\n$ENDWHILE\nG0 X1.2.3\nM30\n", "t.nc:5:"),
    ("linuxcnc", "o100 repeat [99999999]\nG0 X1\no100 endrepeat\nG0 X1.2.3\nM2\n", "t.nc:4:"),
])
def test_a_refused_line_stops_the_run_before_the_program_is_flattened(dialect, program, error):
    # the loop would run to the bound (an error of its own) if the program were run
    setup = MachineSetup(limits=Limits(repeated_work=2000, loop_iterations=50_000))
    for target in ("grbl", "toolpath"):
        with pytest.raises(ErrorList) as info:
            if target == "toolpath":
                list(toolpath_events(io.StringIO(program), file="t.nc", dialect=dialect, setup=setup,
                                     diagnostics=Diagnostics(warn_stream=io.StringIO())))
            else:
                translate(io.StringIO(program), io.StringIO(), file="t.nc", source=dialect, target=target,
                          setup=setup, diagnostics=Diagnostics(warn_stream=io.StringIO()))
        found = [str(e) for e in info.value.errors]
        assert len(found) == 1 and found[0].startswith(error), found
