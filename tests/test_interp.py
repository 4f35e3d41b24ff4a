"""The interpreter, on programs built as IR (the dialect readers are wired to it separately).

Every expected block is derived by hand from the program in the test. A Fanuc-like host spells
integer addresses without a point and ends the program at M30; an o-word-like host has LinuxCNC's
variables.
"""

from __future__ import annotations

import math
from typing import Any, Iterable, Iterator

import pytest

from postproc.interp.control import (
    Assign, Break, Call, Continue, EndIf, EndWhile, Goto, If, IfThen, ModalCall, ModalCallCancel, Return,
    SubEnd, SubStart, While,
)
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.ir.expr import Binary, Expr, Func, Num, Var
from postproc.syntaxes.program import ProgramSyntax
from postproc.rs274.variables import MacroBVariables, NgcVariables
from postproc.ir import Block, ProgramStart, Sequence
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.ir.source_map import ExecutedBlock
from postproc.context import Context
from postproc.plugins import default_registry


class FanucLike(ProgramSyntax):
    INTEGER_ADDRESSES = frozenset("GMNOTHDLP")
    END_CODES = frozenset({("M", 30), ("M", 2)})
    PROGRAM_LABEL = "O{number:04d}"
    LIBRARY_FILES = ("O{number:04d}", "O{number:04d}.nc", "{name}.nc")
    MACRO_LOCALS = 33
    VARIABLES = MacroBVariables


class NgcLike(ProgramSyntax):
    INTEGER_ADDRESSES = frozenset("GMNT")
    END_CODES = frozenset({("M", 30), ("M", 2)})
    MACRO_LOCALS = 30
    VARIABLES = NgcVariables
    PROGRAM_LABEL = "o{raw}"


def v(n: int) -> Var:
    return Var(Num(float(n)))


def b(op: str, left: Expr, right: Expr | float) -> Binary:
    return Binary(op, left, right if isinstance(right, Expr) else Num(float(right)))


class P:
    """A program under construction: one block per call, lines numbered from 1."""

    def __init__(self) -> None:
        self.blocks: list[Block] = []

    def __call__(self, *words: tuple[str, Any], seq: int | None = None, control: Any = None,
                 assign: Any = None, start: int | None = None) -> "P":
        line = len(self.blocks) + 1
        block = Block(line, None)
        if seq is not None:
            block.words.append(("N", str(seq)))
            block.add(Sequence(seq))
        for letter, value in words:
            if isinstance(value, Expr):
                block.words.append((letter, "[expr]"))
                block.values[letter] = value
            else:
                block.words.append((letter, value))
        block.text = " ".join(a + n for a, n in block.words) or f"(statement {line})"
        if start is not None:
            block.add(ProgramStart(start))
        if assign is not None:
            block.add(Assign(assign))
        if control is not None:
            block.add(control)
        self.blocks.append(block)
        return self


def run(program: P | Iterable[Block], host: type[ProgramSyntax] = FanucLike, file: str = "main.nc",
        limits: Limits | None = None, setup: MachineSetup | None = None) -> list[Block]:
    setup = setup or MachineSetup()
    if limits is not None:
        setup.limits = limits
    ctx = Context(file, setup, Diagnostics(ErrorLevel.RAISE), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    ctx.program_mode = "execute"
    blocks = program.blocks if isinstance(program, P) else program
    out = list(host().process(iter(blocks), ctx))
    ctx.diagnostics.check()
    return out


def words(blocks: list[Block]) -> list[str]:
    """The executed blocks' words (comment blocks left out)."""
    return [" ".join(a + n for a, n in blk.words) for blk in blocks if blk.words]


def comments(blocks: list[Block]) -> list[str]:
    return [blk.sections["Comments"].texts[0] for blk in blocks if not blk.words and "Comments" in blk.sections]


def error_of(program: P, **kwargs: Any) -> str:
    with pytest.raises(ErrorList) as info:
        run(program, **kwargs)
    assert len(info.value.errors) == 1
    return str(info.value.errors[0])


# -- loops, conditions, jumps ----------------------------------------------------------------------

def test_bolt_circle_with_while():
    """4 holes on a radius of 50 starting at 0 degrees: #1 counts, #2 = holes, #3 = radius."""
    p = P()
    p(assign=[(v(1), Num(0.0))])
    p(assign=[(v(2), Num(4.0))])
    p(assign=[(v(3), Num(50.0))])
    p(control=While("1", b("lt", v(1), v(2))))
    angle = b("mul", v(1), b("div", Num(360.0), v(2)))
    p(("G", "81"), ("X", b("mul", v(3), Func("cos", [angle]))), ("Y", b("mul", v(3), Func("sin", [angle]))),
      ("Z", "-5."), ("R", "2."))
    p(assign=[(v(1), b("add", v(1), 1))])
    p(control=EndWhile("1"))
    p(("M", "30"))
    out = run(p)
    got = [blk for blk in out if blk.words and blk.words[0] == ("G", "81")]
    assert len(got) == 4
    for i, blk in enumerate(got):
        x, y = float(blk.words[1][1]), float(blk.words[2][1])
        assert math.isclose(x, 50 * math.cos(math.radians(90 * i)), abs_tol=1e-9)
        assert math.isclose(y, 50 * math.sin(math.radians(90 * i)), abs_tol=1e-9)
        assert blk.words[3:] == [("Z", "-5."), ("R", "2.")]
        assert blk.text is None and blk.line == 5
    assert words(out)[0] == "G81 X50. Y0. Z-5. R2."
    assert words(out)[-1] == "M30"
    assert comments(out) == ["LINE 4: [statement 4], iteration"] * 4


def test_nested_loops_make_a_grid():
    p = P()
    p(assign=[(v(1), Num(0.0))])
    p(control=While("1", b("lt", v(1), 2)))
    p(assign=[(v(2), Num(0.0))])
    p(control=While("2", b("lt", v(2), 3)))
    p(("G", "0"), ("X", b("mul", v(2), 10)), ("Y", b("mul", v(1), 20)))
    p(assign=[(v(2), b("add", v(2), 1))])
    p(control=EndWhile("2"))
    p(assign=[(v(1), b("add", v(1), 1))])
    p(control=EndWhile("1"))
    assert words(run(p)) == ["G0 X0. Y0.", "G0 X10. Y0.", "G0 X20. Y0.", "G0 X0. Y20.", "G0 X10. Y20.", "G0 X20. Y20."]


def test_if_goto_backward_and_forward():
    p = P()
    p(("G", "0"), ("X", "0."))
    p(assign=[(v(1), b("add", v(1), 1))], seq=10)  # vacant + 1 = 1
    p(("X", v(1)))
    p(control=Goto(Num(10.0), b("lt", v(1), 3)))
    p(control=Goto(Num(50.0), b("eq", v(1), 3)))
    p(("X", "99."))
    p(("X", "1."), seq=50)
    assert words(run(p)) == ["G0 X0.", "X1.", "X2.", "X3.", "N50 X1."]  # N10 with a statement only: no block


def test_goto_searches_forward_first_then_from_the_start():
    p = P()
    p(("X", "1."), seq=5)
    p(assign=[(v(1), b("add", v(1), 1))])
    p(control=Goto(Num(5.0), b("lt", v(1), 2)))  # first: forward to the second N5
    p(("X", "2."), seq=5)
    p(("M", "30"))
    assert words(run(p)) == ["N5 X1.", "N5 X2.", "M30"]


def test_if_then_assigns_only_when_true():
    p = P()
    p(assign=[(v(1), Num(5.0))])
    p(control=IfThen(b("gt", v(1), 3), Assign([(v(2), Num(1.0))])))
    p(control=IfThen(b("gt", v(1), 9), Assign([(v(3), Num(1.0))])))
    p(("X", v(2)), ("Y", v(3)))  # #3 vacant: Y omitted
    assert words(run(p)) == ["X1."]


def test_break_and_continue():
    """Counts 1..9, skips 3, stops after 5."""
    p = P()
    p(assign=[(v(1), Num(0.0))])
    p(control=While("1", b("lt", v(1), 9)))
    p(assign=[(v(1), b("add", v(1), 1))])
    p(control=If("2", b("eq", v(1), 3)))
    p(control=Continue("1"))
    p(control=EndIf("2"))
    p(control=If("3", b("gt", v(1), 5)))
    p(control=Break("1"))
    p(control=EndIf("3"))
    p(("X", v(1)))
    p(control=EndWhile("1"))
    p(("Y", v(1)))
    assert words(run(p, host=NgcLike)) == ["X1.", "X2.", "X4.", "X5.", "Y6."]


def test_assignments_read_every_value_first():
    """LinuxCNC: ``#1=2 G0 X#1`` moves to the old #1; ``#1=#2 #2=#1`` swaps."""
    p = P()
    p(assign=[(v(1), Num(1.0)), (v(2), Num(2.0))])
    p(("G", "0"), ("X", v(1)), assign=[(v(1), Num(7.0))])
    p(assign=[(v(1), v(2)), (v(2), v(1))])
    p(("X", v(1)), ("Y", v(2)))
    assert words(run(p, host=NgcLike)) == ["G0 X1.", "X2. Y7."]


# -- subprograms -----------------------------------------------------------------------------------

def _fanuc_sub(p: P, number: int, *body: tuple[Any, ...]) -> None:
    p(start=number)
    for item in body:
        p(*item[0], **item[1])
    p(control=Return())


def test_m98_p_l_repeats_a_subprogram_after_m30():
    p = P()
    p(("G", "91"))
    p(control=Call("2000", repeat=Num(3.0)), seq=20)
    p(("M", "30"))
    _fanuc_sub(p, 2000, ([("G", "1"), ("X", "10.")], {}))
    out = run(p)
    assert words(out) == ["G91", "G1 X10.", "G1 X10.", "G1 X10.", "M30"]
    subs = [blk for blk in out if blk.words and blk.words[0] == ("G", "1")]
    assert [blk.origin.note() for blk in subs] == [  # type: ignore[attr-defined]
        f"in O2000, called from main.nc line 2, call {i} of 3" for i in (1, 2, 3)]


def test_m98_shares_the_callers_locals():
    p = P()
    p(assign=[(v(1), Num(3.0))])
    p(control=Call("3000"))
    p(("X", v(1)))
    p(("M", "30"))
    _fanuc_sub(p, 3000, ([], {"assign": [(v(1), b("add", v(1), 1))]}))
    assert words(run(p)) == ["X4.", "M30"]


def test_g65_arguments_open_a_new_level_of_locals():
    p = P()
    p(assign=[(v(3), Num(9.0))])
    p(control=Call("9010", {1: Num(5.0), 2: Num(7.0)}, kind="macro"))
    p(("X", v(1)), ("Y", v(3)))  # the caller's #1 is still vacant, its #3 still 9
    p(("M", "30"))
    _fanuc_sub(p, 9010, ([("G", "0"), ("X", v(1)), ("Y", v(2)), ("Z", v(3))], {}))
    assert words(run(p)) == ["G0 X5. Y7.", "Y9.", "M30"]


def test_g66_calls_after_each_move_until_g67():
    p = P()
    p(control=ModalCall("9020", {26: Num(-5.0)}))
    p(("G", "0"), ("X", "10."))
    p(("S", "1000"))  # no axis word: no call
    p(("X", "20."))
    p(control=ModalCallCancel())
    p(("X", "30."))
    p(("M", "30"))
    _fanuc_sub(p, 9020, ([("G", "1"), ("Z", v(26))], {}), ([("G", "0"), ("Z", "2.")], {}))
    assert words(run(p)) == ["G0 X10.", "G1 Z-5.", "G0 Z2.", "S1000", "X20.", "G1 Z-5.", "G0 Z2.", "X30.", "M30"]


def test_m99_p_returns_to_a_sequence_number_of_the_caller():
    p = P()
    p(control=Call("4000"))
    p(("X", "1."), seq=40)
    p(("X", "2."), seq=50)
    p(("M", "30"))
    p(start=4000)
    p(("Y", "1."))
    p(control=Return(target=Num(50.0)))
    assert words(run(p)) == ["Y1.", "N50 X2.", "M30"]


def test_m99_in_the_main_program_runs_it_again_until_the_bound():
    p = P()
    p(("G", "91"), ("X", "1."))
    p(control=Return(), assign=[(v(1), Binary("add", v(1), Num(1.0)))])  # counts: no run repeats the last
    message = error_of(p, limits=Limits(loop_iterations=3))
    assert message == ("main.nc:2:1: error: return '(statement 2)' exceeds the set-up's bound of 3 loop iterations, "
                       "jumps and calls in total (<Limits loopIterations=\"3\"/>)")


def test_o_word_call_returns_a_value():
    p = P()
    p(control=SubStart("<double>"))
    p(control=Return("<double>", b("mul", v(1), 2)))
    p(control=SubEnd("<double>"))
    p(control=Call("<double>", {1: Num(21.0)}, kind="macro"))
    p(("G", "0"), ("X", Var(name="_value")))
    p(("M", "2"))
    assert words(run(p, host=NgcLike)) == ["G0 X42.", "M2"]


def test_o_word_endsub_returns_a_value():
    """``o<x> endsub [v]`` returns ``v`` as ``return [v]`` does (rs274: ``o100 endsub [5]`` then
    ``(debug, #<_value>)`` prints 5.000000); the value is read in the subprogram's own locals."""
    p = P()
    p(control=SubStart("<double>"))
    p(control=SubEnd("<double>", b("mul", v(1), 2)))
    p(control=Call("<double>", {1: Num(21.0)}, kind="macro"))
    p(("G", "0"), ("X", Var(name="_value")))
    p(("M", "2"))
    assert words(run(p, host=NgcLike)) == ["G0 X42.", "M2"]


def test_library_subprogram_is_read_through_the_dialects_reader(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "O0042.nc").write_text("%\nO0042\nG1 X3. Y4.\n%\n")
    setup = MachineSetup(library=[str(lib)])
    p = P()
    p(control=Call("42"))
    p(("M", "30"))
    out = run(p, setup=setup)
    assert words(out) == ["G1 X3. Y4.", "M30"]
    moved = [blk for blk in out if blk.words and blk.words[0] == ("G", "1")][0]
    assert isinstance(moved, ExecutedBlock) and moved.origin is not None
    assert (moved.origin.file, moved.line) == (str(lib / "O0042.nc"), 3)


# -- errors and bounds -----------------------------------------------------------------------------

def test_endless_while_hits_the_loop_bound():
    p = P()
    p(control=While("1", Binary("ne", v(1), Num(-1.0))))  # tests the count (a fixed test is refused at once)
    p(("X", "1."))
    p(control=EndWhile("1"), assign=[(v(1), Binary("add", v(1), Num(1.0)))])  # counts: no iteration repeats
    assert error_of(p, limits=Limits(loop_iterations=100)) == (
        "main.nc:3:1: error: loop '(statement 3)' exceeds the set-up's bound of 100 loop iterations, jumps "
        "and calls in total (<Limits loopIterations=\"100\"/>)")


def test_recursion_hits_the_call_depth_bound():
    p = P()
    p(control=Call("10", kind="macro"))
    p(("M", "30"))
    p(start=10)
    p(control=Call("10", kind="macro"))
    message = error_of(p, limits=Limits(call_depth=3))
    assert message == ("main.nc:4:1: error: '(statement 4)' exceeds the set-up's bound of 3 nested calls "
                       "(<Limits callDepth=\"3\"/>) (in O0010, called from main.nc line 4; in O0010, called from "
                       "main.nc line 4; in O0010, called from main.nc line 1)")


def test_a_deep_recursion_names_three_calls_at_each_end_of_its_stack():
    """The default bound, 64: the error stands at the call that overflows, and its chain names the innermost
    three calls, how many lie between, and the outermost three (the last from the main program)."""
    p = P()
    p(control=Call("10", kind="macro"))
    p(("M", "30"))
    p(start=10)
    p(control=Call("10", kind="macro"))
    inner = "in O0010, called from main.nc line 4"
    assert error_of(p) == (
        "main.nc:4:1: error: '(statement 4)' exceeds the set-up's bound of 64 nested calls "
        f"(<Limits callDepth=\"64\"/>) ({inner}; {inner}; {inner}; ... 58 more; {inner}; {inner}; "
        "in O0010, called from main.nc line 1)")


def test_a_stack_of_seven_calls_is_named_whole():
    p = P()
    p(control=Call("10", kind="macro"))
    p(("M", "30"))
    p(start=10)
    p(control=Call("10", kind="macro"))
    inner = "in O0010, called from main.nc line 4"
    assert error_of(p, limits=Limits(call_depth=7)).endswith(
        f"({inner}; {inner}; {inner}; {inner}; {inner}; {inner}; in O0010, called from main.nc line 1)")


def test_goto_to_a_missing_label():
    p = P()
    p(control=Goto(Num(70.0)))
    assert error_of(p) == "main.nc:1:1: error: '(statement 1)': no block numbered 70 in main.nc"


def test_missing_subprogram():
    p = P()
    p(control=Call("77"))
    assert error_of(p) == "main.nc:1:1: error: subprogram O0077 not found (called by '(statement 1)')"


def test_division_by_zero_in_the_third_call_names_the_call():
    p = P()
    p(("G", "91"))
    p(control=Call("2000", repeat=Num(3.0)))
    p(("M", "30"))
    p(start=2000)
    p(assign=[(v(100), b("add", v(100), 1))])
    p(("X", b("div", Num(1.0), b("sub", Num(3.0), v(100)))))
    p(control=Return())
    message = error_of(p)
    assert message.startswith("main.nc:6:")
    assert message.endswith("(in O2000, called from main.nc line 2, call 3 of 3)")
    assert "division by zero" in message


def test_integer_address_must_evaluate_to_an_integer():
    p = P()
    p(assign=[(v(1), Num(2.5))])
    p(("G", "1"), ("M", v(1)))
    assert error_of(p) == "main.nc:2:4: error: address M takes an integer, the expression gives 2.5 (M[expr])"


def test_system_variable_is_known_only_to_the_machine():
    p = P()
    p(("X", v(5021)))
    assert error_of(p) == ("main.nc:1:1: error: #5021 (current machine position) is known only to the machine: "
                           "the program cannot be simulated or flattened")


def test_an_unclosed_loop_is_a_located_error():
    p = P()
    p(("X", "1."))
    p(control=While("1", Num(1.0)))
    assert error_of(p) == "main.nc:2:1: error: '(statement 2)' is never closed"


# -- streaming -------------------------------------------------------------------------------------

def test_keep_mode_passes_the_very_same_blocks():
    p = P()
    p(control=While("1", Num(1.0)))
    p(control=EndWhile("1"))
    ctx = Context("main.nc", MachineSetup(), Diagnostics(), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    assert ctx.program_mode == "keep"
    out = list(FanucLike().process(iter(p.blocks), ctx))
    assert all(a is b_ for a, b_ in zip(out, p.blocks)) and len(out) == 2


def _straight(n: int, pulled: list[int]) -> Iterator[Block]:
    for i in range(1, n + 1):
        pulled[0] += 1
        yield Block(i, f"G1 X{i}.", "\n", [("G", "1"), ("X", f"{i}.")])


def test_a_straight_program_streams_without_buffering():
    pulled = [0]
    setup = MachineSetup(limits=Limits(kept_prefix=50))
    ctx = Context("main.nc", setup, Diagnostics(), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    ctx.program_mode = "execute"
    count = 0
    for block in FanucLike().process(_straight(100_000, pulled), ctx):
        count += 1
        assert pulled[0] == count  # each block leaves before the next is read
        assert block.line == count
    assert count == 100_000


class Recording(FanucLike):
    reread: list[int] = []

    def read_lines(self, lines, file, ctx, diagnostics):  # type: ignore[no-untyped-def]
        lines = list(lines)
        type(self).reread.append(len(lines))
        return super().read_lines(lines, file, ctx, diagnostics)


def test_only_the_bounded_prefix_is_kept_for_jumps_back():
    """100k straight blocks, then a jump back to a block that is no longer kept."""
    pulled = [0]
    setup = MachineSetup(limits=Limits(kept_prefix=1000))
    ctx = Context("main.nc", setup, Diagnostics(ErrorLevel.RAISE), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    ctx.program_mode = "execute"
    jump = Block(100_001, "GOTO 1", "\n")
    jump.add(Goto(Num(1.0)))
    first = Block(1, "N1 G1 X0.", "\n", [("N", "1"), ("G", "1"), ("X", "0.")])
    first.add(Sequence(1))

    def program() -> Iterator[Block]:
        yield first
        for blk in _straight(99_999, pulled):
            blk.line += 1
            yield blk
        yield jump

    Recording.reread = []
    out = list(Recording().process(program(), ctx))
    assert len(out) == 100_000
    assert Recording.reread == [1000]  # the store holds the kept 1000 blocks and the jump, no more
    with pytest.raises(ErrorList) as info:
        ctx.diagnostics.check()
    assert str(info.value.errors[0]) == (
        "main.nc:100001:1: error: 'GOTO 1': no block numbered 1 in main.nc after its first 99000 blocks, which "
        "are not kept for jumps back (the set-up keeps the last 1000: <Limits keptPrefix=\"1000\"/>)")


def test_a_jump_back_into_the_kept_prefix_rereads_it():
    ctx = Context("main.nc", MachineSetup(), Diagnostics(ErrorLevel.RAISE), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    ctx.program_mode = "execute"
    lines = ["G91\n", "N10 G1 X1.\n"]
    blocks = list(default_registry().dialect("fanuc").READER(ctx).read(lines))
    counter = Block(3, "#1=#1+1", "\n")
    counter.add(Assign([(v(1), b("add", v(1), 1))]))
    back = Block(4, "IF [#1 LT 3] GOTO 10", "\n")
    back.add(Goto(Num(10.0), b("lt", v(1), 3)))
    out = list(FanucLike().process(iter(blocks + [counter, back]), ctx))
    assert words(out) == ["G91", "N10 G1 X1.", "N10 G1 X1.", "N10 G1 X1."]
    assert [blk.line for blk in out if blk.words] == [1, 2, 2, 2]



class Rereading(FanucLike):
    lines: list[str] = []

    def read_lines(self, lines, file, ctx, diagnostics):  # type: ignore[no-untyped-def]
        type(self).lines = list(lines)
        return super().read_lines(type(self).lines, file, ctx, diagnostics)


def test_the_kept_prefix_is_reread_with_each_line_end_as_written():
    """The step keeps a streamed LF line as the reader's own string, any other end of line with its text,
    and a block without text as an empty line: the reread lines are the source's, byte for byte."""
    ctx = Context("main.nc", MachineSetup(), Diagnostics(ErrorLevel.RAISE), "fanuc")
    ctx.reader = default_registry().dialect("fanuc").READER
    ctx.program_mode = "execute"
    source = ["G91\r\n", "N10 G1 X1.\n", "X2.\r\n", "X3."]
    blocks = list(default_registry().dialect("fanuc").READER(ctx).read(source))
    textless = Block(5, None, "\n")
    counter = Block(6, "#1=#1+1", "\n")
    counter.add(Assign([(v(1), b("add", v(1), 1))]))
    back = Block(7, "IF [#1 LT 2] GOTO 10", "\n")
    back.add(Goto(Num(10.0), b("lt", v(1), 2)))
    out = list(Rereading().process(iter(blocks + [textless, counter, back]), ctx))
    assert Rereading.lines == source + [""]
    assert words(out) == ["G91", "N10 G1 X1.", "X2.", "X3.", "N10 G1 X1.", "X2.", "X3."]

# -- set-up and command line -----------------------------------------------------------------------

LIMITS_XML = (b"<?xml version='1.0' encoding='UTF-8'?>\n<MachineSetup name=\"m\">\n"
              b"  <Limits loopIterations=\"500\" callDepth=\"8\" keptPrefix=\"10\"/>\n"
              b"  <Library path=\"subs\"/>\n  <Library path=\"/opt/macros\"/>\n</MachineSetup>\n")


def test_limits_and_library_load_and_dump_identically(tmp_path):
    from postproc.setup.machine_setup import load_setup
    from postproc.xmlio import to_bytes
    path = tmp_path / "m.xml"
    path.write_bytes(LIMITS_XML)
    setup = load_setup(path)
    assert setup.limits == Limits(loop_iterations=500, call_depth=8, kept_prefix=10)
    assert setup.library_paths() == [tmp_path / "subs", tmp_path.parent / "/opt/macros"]
    assert to_bytes(setup.make_xml_source()) == LIMITS_XML


@pytest.mark.parametrize("body, message, line", [
    ('<Limits callDepth="0"/>', "<Limits> callDepth: Input should be greater than or equal to 1", 2),
    ('<Limits loops="5"/>', "<Limits> loops: unknown parameter", 2),
    ("<Library/>", "<Library> takes one attribute, path (a folder of subprograms)", 2),
])
def test_bad_limits_are_located(tmp_path, body, message, line):
    from postproc.errors import ConfigError
    from postproc.setup.machine_setup import load_setup
    path = tmp_path / "m.xml"
    path.write_text(f'<MachineSetup name="m">\n{body}\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as info:
        load_setup(path)
    assert (info.value.message, info.value.location.line) == (message, line)


def test_lib_option_must_name_a_folder(cli, tmp_path):
    prog = tmp_path / "p.nc"
    prog.write_text("G0 X1.\n")
    result = cli("toolpath", prog, "--dialect", "fanuc", "--lib", tmp_path / "missing")
    assert result.status == 2
    assert result.err == f"postproc: --lib {tmp_path / 'missing'}: no such directory\n"


# -- the neutral step names no family ------------------------------------------------------------------------

class NoFamily(ProgramSyntax):
    """A dialect that forgot its variables: the neutral base brings none of its own."""
    END_CODES = frozenset({("M", 30)})


def test_the_neutral_step_has_no_family_defaults():
    assert (ProgramSyntax.VARIABLES, ProgramSyntax.MACRO_LOCALS) == (None, 0)


def test_a_step_without_variables_refuses_a_program_that_computes_at_its_first_construct():
    p = P()
    p(("G", "0"), ("X", "1."))
    p(assign=[(v(1), Num(2.0))])
    p(("X", v(1)))
    assert error_of(p, host=NoFamily) == ("main.nc:2:1: error: fanuc: NoFamily declares no VARIABLES, so a program "
                                          "that computes cannot be run")


def test_a_step_without_variables_still_streams_a_straight_program():
    p = P()
    p(("G", "0"), ("X", "1."))
    p(("M", "30"))
    assert words(run(p, host=NoFamily)) == ["G0 X1.", "M30"]
