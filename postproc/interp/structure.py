"""The nesting of a program's constructs, checked as its blocks come: the one place that decides whether
loops, conditions, switches and subprogram definitions are well formed, for ``translate``, ``toolpath``
and ``verify`` alike.

``Structure`` takes the control statements and program starts of one file in order and raises a located
``ProgramError`` for a closer that closes nothing open (``END1`` without ``WHILE``), a branch after the
``else``, a ``break`` outside its loop, a subprogram defined twice (``o100 sub`` twice; two ``O2000`` where
the dialect's ``SubprogramRules`` give each number one program), and, at the end, for a construct never
closed (``WHILE [..] DO1`` without ``END1``: Fanuc's DO and END must pair one to one, alarm PS0124 [K]).
The streaming step (``ProgramSyntax``) runs it over every program that is read, with one more check
(``StreamCheck``): an expression a part of which fails whatever the program does (``1/0``, ``SQRT[-4]``,
``LN[0]``, ``#1/0``: its operands constants, ``postproc.interp.evaluation.certain_failure``) is refused where it
is read, not kept symbolically for a controller to alarm on; the program store
(``Program``) also keeps what it matched (``pairs``, ``chains``) to run the program. It holds only the
open constructs and the names defined, never the blocks.
"""

from __future__ import annotations

from typing import Callable, Iterator

from .control import (
    ASSIGN, CONTROL, Assign, Break, Call, Case, Continue, ControlSection, Default, Do, DoWhile, Else, ElseIf,
    EndFor, EndIf, EndRepeat, EndSwitch, EndWhile, For, If, IfThen, ModalCall, Repeat, SubEnd, SubStart, Switch,
    Until, While,
)
from ..errors import Location, PostprocError, ProgramError
from ..ir.expr import Expr
from ..ir import Block, Section, one_line
from ..ir.source_map import locate
from .rules import SubprogramRules

_HEADS: dict[type[Section], type[Section]] = {EndWhile: While, DoWhile: Do, EndRepeat: Repeat, EndFor: For,
                                              Until: Do}
"""Each loop end and the head it closes."""
LOOPS = (While, Do, Repeat, For)


def source_text(block: Block) -> str:
    """The construct as written, for messages (or the block's words when it has no text)."""
    text = one_line(block.text) if block.text is not None else " ".join(a + n for a, n in block.words)
    return text.strip() or type(block.get(CONTROL)).__name__


def flow_overflow(block: Block, entry: int, limit: int) -> str:
    """The message for a construct that would hold entry ``entry`` of a flow stack of ``limit``."""
    return (f"'{source_text(block)}' would hold entry {entry} of the controller's flow control stack, which has "
            f"{limit} (each open loop, condition and call takes one): it stops there (stack overflow)")


class _Open:
    """An open construct: its head, where it stands, and (for an if or a switch) its members so far."""

    __slots__ = ("head", "pos", "block", "chain", "last")

    def __init__(self, head: Section, pos: int, block: Block) -> None:
        self.head = head
        self.pos = pos
        self.block = block
        self.chain = [pos]
        self.last: Section = head


class Structure:
    """Checks one file's constructs in order. ``index``: keep the matches (``pairs``, ``chains``) for a
    run; else only check (a streamed program)."""

    __slots__ = ("file", "rules", "index", "stack", "pairs", "chains", "subs", "programs", "failed", "uses",
                 "body_use", "entries")

    def __init__(self, file: str, rules: SubprogramRules, index: bool = False) -> None:
        self.file = file
        self.rules = rules
        self.index = index
        self.stack: list[_Open] = []
        self.pairs: dict[int, int] = {}
        """Loop head <-> end, switch <-> its end, break/continue -> the head of their loop (``index``)."""
        self.chains: dict[int, list[int]] = {}
        """Every member of an if-chain -> the chain's positions; a switch -> its cases and default (``index``)."""
        self.subs: dict[str, tuple[int, int]] = {}
        """``o<x> sub`` name -> (its position, its end's position)."""
        self.programs: dict[int, int] = {}
        """Program number -> the line of its ``O`` (``ProgramStart``)."""
        self.failed = False
        """An error was raised: the program is not run."""
        self.uses: dict[str, int] = {}
        """Sub name -> the most entries of the flow stack its body opens, with what it calls (``flow_stack``)."""
        self.body_use: list[int] = []
        """For each ``o<x> sub`` open, the most entries its body has opened so far."""
        self.entries: dict[int, int] = {}
        """Position of a loop, condition or call -> the entries of the flow stack its body holds once it is open
        (those open around it in its sub's body, or the main program's, and itself; ``index`` only): a run adds
        its callers' (``Interpreter``), which reaches what the text cannot show, a sub calling itself."""

    def _error(self, block: Block, message: str) -> ProgramError:
        self.failed = True
        return ProgramError(message, locate(self.file, block))

    @property
    def open(self) -> bool:
        """A construct is open (a program's end inside a loop is not its end)."""
        return bool(self.stack)

    def program(self, number: int, block: Block) -> None:
        """A program start ``O<number>``: a second one of the same number is refused unless the rules let
        the first one after a call win (LinuxCNC)."""
        if self.rules.forward_search:
            return
        first = self.programs.setdefault(number, block.line)
        if first != block.line:
            raise self._error(block, f"program {number} is defined twice (first on line {first}): a subprogram "
                                     f"call could not tell them apart")

    def statement(self, control: Section, pos: int, block: Block) -> None:
        """The control statement of the block at ``pos``."""
        limit = self.rules.flow_stack
        if limit is not None:
            self._flow(control, pos, block, limit)
        if isinstance(control, (*LOOPS, If, SubStart, Switch)):
            opened = _Open(control, pos, block)
            self.stack.append(opened)
            if self.index and isinstance(control, (If, Switch)):
                self.chains[pos] = opened.chain
            return
        kind = type(control)
        if kind in _HEADS:
            at = self._close(_HEADS[kind], control.label, block).pos  # type: ignore[attr-defined]
            self._pair(at, pos)
        elif kind in (ElseIf, Else, EndIf):
            opened = self._close(If, control.label, block, pop=kind is EndIf)  # type: ignore[attr-defined]
            if kind is not EndIf and isinstance(opened.last, Else):
                raise self._error(block, f"'{source_text(block)}' after the else branch")
            self._member(opened, control, pos, chained=True)
        elif kind in (Case, Default, EndSwitch):
            opened = self._close(Switch, control.label, block, pop=kind is EndSwitch)  # type: ignore[attr-defined]
            if kind is EndSwitch:
                self._pair(opened.pos, pos)
                return
            if kind is Case and isinstance(opened.last, Default):
                raise self._error(block, f"'{source_text(block)}' after the default branch")
            self._member(opened, control, pos, chained=False)
        elif kind in (Break, Continue):
            label = control.label  # type: ignore[attr-defined]
            heads = (*LOOPS, Switch) if kind is Break else LOOPS
            for opened in reversed(self.stack):
                if isinstance(opened.head, heads) and opened.head.label == label:
                    if self.index:
                        self.pairs[pos] = opened.pos
                    return
            raise self._error(block, f"'{source_text(block)}' is not inside loop {label}")
        elif kind is SubEnd:
            name = control.name  # type: ignore[attr-defined]
            opened = self._close(SubStart, name, block)
            if self.body_use:
                self.uses[str(name)] = self.body_use.pop()
            if name in self.subs:
                raise self._error(opened.block, f"subprogram {name} is defined twice")
            self.subs[name] = (opened.pos, pos)
            self._pair(opened.pos, pos)

    def _flow(self, control: Section, pos: int, block: Block, limit: int) -> None:
        """The controller's flow stack (``SubprogramRules.flow_stack``): a loop, condition or call opens one entry
        over those open around it in its body; a call adds what its sub's body opens (a sub defined before
        it: the controller finds no other). Counted where the text nests, so a construct in a branch never
        taken counts too (stricter than the controller, which opens none in a skipped branch)."""
        if isinstance(control, SubStart):
            self.body_use.append(0)
            return
        if not isinstance(control, (*LOOPS, If, Switch, Call)):
            return
        used = self.held() + 1
        if self.index:
            self.entries[pos] = used
        if isinstance(control, Call) and isinstance(control.name, str):
            used += self.uses.get(control.name, 0)
        if used > limit:
            raise self._error(block, flow_overflow(block, used, limit))
        if self.body_use:
            self.body_use[-1] = max(self.body_use[-1], used)

    def held(self) -> int:
        """The constructs open around the next statement in its sub's body (or the main program's)."""
        around = 0
        for opened in reversed(self.stack):
            if isinstance(opened.head, SubStart):
                break
            around += 1
        return around

    def finish(self) -> None:
        """The end of the file: a construct still open is an error (the innermost one is named)."""
        if self.stack:
            opened = self.stack[-1]
            raise self._error(opened.block, f"'{source_text(opened.block)}' is never closed")

    def _pair(self, at: int, pos: int) -> None:
        if self.index:
            self.pairs[at] = pos
            self.pairs[pos] = at

    def _member(self, opened: _Open, control: Section, pos: int, chained: bool) -> None:
        opened.last = control
        opened.chain.append(pos)
        if self.index and chained:
            self.chains[pos] = opened.chain

    def _close(self, head: type[Section], label: str, block: Block, pop: bool = True) -> _Open:
        stack = self.stack
        if stack:
            opened = stack[-1]
            section = opened.head
            name = getattr(section, "label", getattr(section, "name", None))
            if isinstance(section, head) and name == label:
                if pop:
                    stack.pop()
                return opened
        raise self._error(block, f"'{source_text(block)}' does not close an open {head.__name__} {label}")


class StreamCheck:
    """A streamed program's ``Structure`` and expressions: each block with a control statement, an
    assignment, a computed word or a program start is shown to it (``see``) as it passes, and errors are
    reported, not raised (``report``), so the rest of the program is still read; after a structure error
    the structure is not checked further (what is open is unknown)."""

    __slots__ = ("structure", "report", "failed")

    def __init__(self, file: str, rules: SubprogramRules, report: Callable[[PostprocError], None]) -> None:
        self.structure = Structure(file, rules)
        self.report = report
        self.failed = False
        """An expression fails whatever the program does."""

    def see(self, block: Block) -> None:
        for expr, col in _expressions(block):
            # (the evaluator imported at a program's first expression: a CAM program has none, and its byte
            # code, with ``long_double``'s, was ~1M instructions of every start)
            from .evaluation import certain_failure
            err = certain_failure(expr)
            if err is not None:
                self.failed = True
                self.report(ProgramError(f"{err.message}: it fails wherever it runs (its operands are constants)",
                                         Location(self.structure.file, block.line, col)))
                break
        structure = self.structure
        if structure.failed:
            return
        sections = block.sections
        try:
            start = sections.get("ProgramStart")
            if start is not None and start.number is not None:  # type: ignore[attr-defined]
                structure.program(start.number, block)  # type: ignore[attr-defined]
            control = sections.get(CONTROL)
            if control is not None:
                structure.statement(control, 0, block)
        except ProgramError as err:
            self.report(err)

    def end(self) -> bool:
        """The end of the program: True when its structure is sound."""
        structure = self.structure
        if not structure.failed:
            try:
                structure.finish()
            except ProgramError as err:
                self.report(err)
        return not (structure.failed or self.failed)


def _expressions(block: Block) -> Iterator[tuple[Expr, int]]:
    """Every expression of ``block`` and the column it stands at (1 when not a word's)."""
    text = block.text or ""
    for letter, number in block.words:
        value = block.values.get(letter.upper())
        if isinstance(value, Expr):
            at = text.find(letter + number)
            yield value, at + 1 if at >= 0 else 1
    sections = block.sections
    assign = sections.get(ASSIGN)
    if isinstance(assign, Assign):
        yield from _assigned(assign)
    control = sections.get(CONTROL)
    if isinstance(control, ControlSection):
        for role in control.ROLES:
            expr = getattr(control, role)
            if isinstance(expr, Expr):
                yield expr, 1
        if isinstance(control, (Call, ModalCall)):
            if isinstance(control.name, Expr):
                yield control.name, 1
            for expr in control.args.values():
                yield expr, 1
            if control.repeat is not None:
                yield control.repeat, 1
        elif isinstance(control, IfThen):
            yield from _assigned(control.assign)


def _assigned(assign: Assign) -> Iterator[tuple[Expr, int]]:
    for var, value in assign.items:
        yield var, 1
        yield value, 1
