"""Numbered subprograms (``M98 P<n> L<k>``, ``O<n>`` .. ``M99`` after the main program's end: Fanuc, and
LinuxCNC's Fanuc-style ones) as grblHAL's o-word subs, on a build with expressions: a program with
subprograms reaches grblHAL as calls instead of its every repetition.

grblHAL's rules, from ``ngc_flowctrl.c`` (github.com/grblHAL/core, stored commit f80fc34) [V]: the flow
registers ``o<n> sub`` when it passes the definition and skips its body; ``o<n> call`` finds only a sub it has
registered (else "flow control syntax error"); a numeric label above 65535 (``NGC_MAX_PARAM_ID``) names a string
parameter, not a number; ``o<k> repeat [L]`` runs its body L times. So the subprograms are written before the
first call: the main program streams up to its first call, is held from there to its end while the
subprograms are read, and follows them. ``M98 P<n> L<k>`` is ``o<n> call`` (in ``o<k> repeat [k]`` ..
``endrepeat`` for k > 1, with a label no subprogram has), ``M99`` at a subprogram's end its ``o<n> endsub``.

An ``M98`` call shares its caller's locals, an o-word call opens its own: alike only in a program that computes
nothing. So this step takes programs whose only statements are the calls and returns; anything else (an
assignment, a computed word, another statement, ``M99`` with a target or in the main program, code after a
subprogram's ``M99``, a subprogram number above 65535, a call of a number no subprogram has) is an
``UnsupportedError``: the program is then flattened, as before.
"""

from __future__ import annotations

from typing import Iterator

from postproc.context import Context
from postproc.interp.control import ASSIGN, CONTROL, Call, EndRepeat, Repeat, Return, SubEnd, SubStart
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir.expr import Expr, Num
from postproc.ir import Block
from postproc.lowering.lower import BlockStep, LoweringStep

CONVERTED = "grblhal_subprograms"
"""``ctx.run_data`` key: this step wrote the program's subprograms as o-word subs (the writer then writes the
statements it made, whatever the source's family)."""
LAST_LABEL = 65535
"""``NGC_MAX_PARAM_ID``: a higher o-word label is a string parameter's id (a named sub) [V: ngc_params.h]."""
CALL_LEVELS = 10
"""Nested calls grblHAL runs (``NGC_MAX_CALL_LEVEL`` 10, ``ngc_call_push``) [V: ngc_params.c]. A call here is at
most two open o-word constructs (its repeat and itself): 20 at 10 levels, which ``NGC_STACK_DEPTH`` (20,
``ngc_flowctrl.c``) holds."""
_CODE = frozenset(("Comments", "ProgramStart"))
"""Sections that are no code (a block of only these may stand after a subprogram's ``M99``)."""


class SubprogramsAsSubs(LoweringStep):
    """Lowering step for grblHAL (module docstring); a program without subprogram calls streams through, and
    on a build without expressions, or from grblHAL itself, the step is not in the stream at all."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if not ctx.setup.controller.expressions or ctx.dialect == target.NAME:
            return None
        return _AsSubs(ctx)


subprograms_as_subs = SubprogramsAsSubs()


class _AsSubs(BlockStep):
    """One run: the blocks stream up to the first call; from there the main program is held to its end
    (``held``), then its subprograms (``subs``) and what follows them (``tail``), all given back at the end."""

    def __init__(self, ctx: Context) -> None:
        super().__init__()
        self.ctx = ctx
        self.computes: Block | None = None
        """The first block before the first call that computes (an error once a call is found)."""
        self.held: list[Block] | None = None
        self.ended = False
        """The held main program reached its end (M2/M30): what follows is subprograms and the tail."""
        self.subs: list[tuple[int, list[Block]]] = []
        self.tail: list[Block] = []

    def take(self, block: Block) -> list[Block] | None:
        held = self.held
        if held is None:
            control = block.sections.get(CONTROL)
            if isinstance(control, Call) and control.kind == "sub":
                if self.computes is not None:
                    raise UnsupportedError("a program that computes, with subprograms (an M98 subprogram shares "
                                           "its caller's locals, a grblHAL call opens its own)",
                                           self.ctx.at(self.computes))
                self.held = [block]
                return []
            if self.computes is None and (control is not None or ASSIGN in block.sections
                                          or any(isinstance(value, Expr) for value in block.values.values())):
                self.computes = block
            return None
        if not self.ended:
            held.append(block)
            self.ended = _ends_main(block)
            return []
        subs, tail = self.subs, self.tail
        start = block.sections.get("ProgramStart")
        number = getattr(start, "number", None)
        if "TapeMark" in block.sections:
            tail.append(block)
        elif number is not None and not tail:
            subs.append((int(number), [block]))
        elif subs and not tail:
            subs[-1][1].append(block)
        else:
            tail.append(block)
        return []

    def finish(self) -> list[Block]:
        held, ctx = self.held, self.ctx
        if held is None:
            return []
        if not self.ended:
            raise UnsupportedError("a subprogram call in a program without an end (M2/M30), after which its "
                                   "subprograms stand", ctx.at(held[0]))
        subs = self.subs
        numbers = {number for number, _ in subs}
        labels = (label for label in range(1, LAST_LABEL + 1) if label not in numbers)
        ordered = list(_callees_first(subs, ctx))
        _check_nesting(ordered, held, ctx)
        ctx.run_data[CONVERTED] = True
        made: list[Block] = []
        for number, body in ordered:
            made.extend(_sub(number, body, ctx, numbers, labels))
        for block in held:
            made.extend(_main_block(block, ctx, numbers, labels))
        made.extend(self.tail)
        return made


def _callees_first(subs: list[tuple[int, list[Block]]], ctx: Context) -> Iterator[tuple[int, list[Block]]]:
    """The subprograms, each after those it calls (the source's order where that holds): a call in a sub's
    body then stands after its callee's definition too, the rule the reader and the writer check. Subprograms
    that call each other (or themselves) have no such order: an ``UnsupportedError``."""
    numbers = {number for number, _ in subs}
    calls = [{number for block in body if (number := _called(block)) in numbers} for _, body in subs]
    left = list(range(len(subs)))
    done: set[int | None] = set()
    while left:
        ready = next((i for i in left if calls[i] <= done), None)
        if ready is None:
            number, body = subs[left[0]]
            raise UnsupportedError(f"subprogram O{number} calls itself or is in a loop of calls (grblHAL finds a "
                                   "sub only once the program has passed its definition)", ctx.at(body[0]))
        left.remove(ready)
        done.add(subs[ready][0])
        yield subs[ready]


def _check_nesting(ordered: list[tuple[int, list[Block]]], main: list[Block], ctx: Context) -> None:
    """grblHAL's bound on nested calls (``CALL_LEVELS``), over the deepest chain of calls from the main program
    (``ordered``: callees first)."""
    deepest: dict[int | None, int] = {}
    """A subprogram's deepest chain of calls, its own call included."""
    for number, body in [*ordered, (None, main)]:
        deepest[number] = max((deepest.get(_called(block), 0) + 1 for block in body if _called(block) is not None),
                              default=0)
    if deepest[None] > CALL_LEVELS:
        raise UnsupportedError(f"subprograms nested {deepest[None]} calls deep: grblHAL runs {CALL_LEVELS} nested "
                               "calls", ctx.at(main[0]))


def _called(block: Block) -> int | None:
    control = block.sections.get(CONTROL)
    return _number(control.name) if isinstance(control, Call) else None


def _ends_main(block: Block) -> bool:
    end = block.sections.get("ProgramControl")
    return end is not None and getattr(end, "kind", None) in ("end", "end_rewind")


def _sub(number: int, body: list[Block], ctx: Context, numbers: set[int], labels: Iterator[int]) -> Iterator[Block]:
    """``o<n> sub``, the body, ``o<n> endsub`` (at its ``M99``, or at its end where it has none)."""
    head = body[0]
    if number > LAST_LABEL:
        raise UnsupportedError(f"subprogram O{number}: grblHAL's o-word labels go to {LAST_LABEL}", ctx.at(head))
    name = str(number)
    start = Block(head.line, None, head.eol)
    for key, section in head.sections.items():
        if key != "ProgramStart":
            start.sections[key] = section
    start.sections[CONTROL] = SubStart(name)
    yield start
    returned = False
    for block in body[1:]:
        control = block.sections.get(CONTROL)
        if returned:
            if not _CODE.issuperset(block.sections):
                raise UnsupportedError(f"code after subprogram O{number}'s M99 (it never runs there; on grblHAL it "
                                       "would run before the main program)", ctx.at(block))
            yield block  # a comment (dead code the reading steps turned into one)
            continue
        if isinstance(control, Return):
            _whole(block, ctx)
            if control.target is not None or control.value is not None:
                raise UnsupportedError("an M99 that continues at a sequence number (no grblHAL o-word return does)",
                                       ctx.at(block))
            yield from _without_control(block, SubEnd(name))
            returned = True
            continue
        yield from _main_block(block, ctx, numbers, labels)
    if not returned:
        end = Block(body[-1].line, None, body[-1].eol)
        end.sections[CONTROL] = SubEnd(name)
        yield end


def _main_block(block: Block, ctx: Context, numbers: set[int], labels: Iterator[int]) -> Iterator[Block]:
    """A block of a program that computes nothing, its ``M98`` as an o-word call (module docstring)."""
    if ASSIGN in block.sections or any(isinstance(value, Expr) for value in block.values.values()):
        raise UnsupportedError("a program that computes, with subprograms (an M98 subprogram shares its caller's "
                               "locals, a grblHAL call opens its own)", ctx.at(block))
    control = block.sections.get(CONTROL)
    if control is None:
        yield block
        return
    if not isinstance(control, Call) or control.kind != "sub" or control.args:
        raise UnsupportedError(f"{type(control).__name__} in a program with subprograms for grblHAL (only M98 "
                               "calls and a subprogram's closing M99 are written as o-words)", ctx.at(block))
    number = _number(control.name)
    if number is None or number not in numbers:
        raise UnsupportedError(f"a call of a subprogram not in this program ({block.text}): grblHAL finds a sub "
                               "only in the file it runs", ctx.at(block))
    count = _number(control.repeat) if control.repeat is not None else 1
    if count is None:
        raise UnsupportedError("a computed repeat count", ctx.at(block))
    _whole(block, ctx)
    call = Call(str(number), {}, None, "macro")
    if count == 1:
        yield from _without_control(block, call)
        return
    if count < 1:  # L0: the subprogram does not run, the rest of the block does
        yield from _without_control(block, None)
        return
    label = str(next(labels))
    yield from _without_control(block, Repeat(label, Num(float(count))))
    inner = Block(block.line, None, block.eol)
    inner.sections[CONTROL] = call
    yield inner
    end = Block(block.line, None, block.eol)
    end.sections[CONTROL] = EndRepeat(label)
    yield end


def _whole(block: Block, ctx: Context) -> None:
    """Refuses a call or return the operator's block delete may skip: its o-word lines would be split from the
    block (whether grblHAL's ``/`` skips an o-word line is not in the sources read [?])."""
    if "BlockDelete" in block.sections:
        raise UnsupportedError("a subprogram call or return under block delete (/)", ctx.at(block))


def _without_control(block: Block, statement: SubEnd | Call | Repeat | None) -> Iterator[Block]:
    """The block's other sections, if any, then ``statement`` (if any) in a block of its own."""
    rest = {key: section for key, section in block.sections.items() if key != CONTROL}
    if rest:
        before = Block(block.line, None, block.eol)
        before.sections.update(rest)
        yield before
    if statement is None:
        return
    alone = Block(block.line, None, block.eol)
    alone.sections[CONTROL] = statement
    yield alone


def _number(value: str | Expr | None) -> int | None:
    """A whole number written as a label or a constant; None otherwise."""
    if isinstance(value, str) and value.isdigit():
        return int(value)
    if isinstance(value, Num) and value.value.is_integer() and value.value >= 0:
        return int(value.value)
    return None
