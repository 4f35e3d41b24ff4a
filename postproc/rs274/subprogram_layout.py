"""Where another dialect's numbered subprograms stand in a file for a reader that finds a subprogram only
after the call to it (RS274/NGC's rs274: ``postproc.interp.rules``): each after every subprogram that calls
it, fused with the return level a native cycle needs (``return_level.ReturnLevels``: one loop for both).

The main program comes first, so its calls find every subprogram; a subprogram that calls one written before
it does not. ``subprograms_after_callers`` writes the subprograms after the main program's end in an order
where every caller comes before the programs it calls (the source's order where that holds already).
Subprograms that call each other have no such order: a located error, worded by the dialect (``refusal``).
Only the subprograms are held back (a construct's look-ahead): the main program streams.

In the core and compiled with the hot path because it sees every block of a translation to its dialect (a
plugin's step runs interpreted); the dialect's plugin names it in its ``LOWERING`` with its wording.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Callable, Iterator

from ..context import Context
from ..interp.control import CONTROL, Call
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir import Block
from .return_level import ReturnLevels
from ..lowering.lower import BlockStep, LoweringStep

Group = tuple[str | None, list[Block]]
"""A subprogram's number (None: what stands before the first one) and its blocks, in source order."""
Refusal = Callable[[str, str, int], str]
"""The message for subprograms that call each other: (a caller's number, the number it calls, how many
programs are left unordered) -> text."""


@mypyc_attr(allow_interpreted_subclasses=True)
class SubprogramsAfterCallers(LoweringStep):
    """Lowering step (see the module docstring), which also writes the return level a cycle needs as the
    text comes; a source of the target's own dialect is written as it is. ``refusal`` words the error."""

    def __init__(self, refusal: Refusal) -> None:
        self.refusal = refusal

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME:
            return None
        return _Layout(ctx, target, self.refusal)


@mypyc_attr(allow_interpreted_subclasses=True)
class _Layout(BlockStep):
    """One run: the main program streams (a block that is only a move is none of its business), the
    subprograms after its end are held (then every block is)."""

    def __init__(self, ctx: Context, target: type[Dialect], refusal: Refusal) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.refusal = refusal
        self.levels = ReturnLevels(target)
        self.ended = False
        self.groups: list[Group] | None = None

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if "CannedCycle" in sections or "ReturnLevel" in sections:  # most blocks have neither: two tests
            self.levels.see(block)
        groups = self.groups
        if groups is None:
            if "ProgramStart" in sections or "ProgramControl" in sections:
                number = getattr(sections.get("ProgramStart"), "number", None)
                if self.ended and number is not None:
                    self.groups = [(str(int(number)), [block])]
                    self.moves = True
                    return []
                end = sections.get("ProgramControl")
                if end is not None and getattr(end, "kind", None) in ("end", "end_rewind"):
                    self.ended = True
            return None
        if "TapeMark" in sections:
            made = list(_ordered(groups, self.ctx, self.refusal))
            self.groups = None
            self.moves = False
            self.ended = False
            made.append(block)
            return made
        number = getattr(sections.get("ProgramStart"), "number", None)
        if number is not None:
            groups.append((str(int(number)), [block]))
        else:
            groups[-1][1].append(block)
        return []

    def finish(self) -> list[Block]:
        groups = self.groups
        return [] if groups is None else list(_ordered(groups, self.ctx, self.refusal))


def _ordered(groups: list[Group], ctx: Context, refusal: Refusal) -> Iterator[Block]:
    """The groups' blocks, each subprogram after all its callers (stably: the first ready in source order)."""
    names = {name for name, _ in groups}
    calls: list[dict[str, Block]] = []
    for name, body in groups:
        called: dict[str, Block] = {}
        for block in body:
            control = block.sections.get(CONTROL)
            if isinstance(control, Call) and control.kind == "sub" and isinstance(control.name, str) \
                    and control.name.isdigit() and str(int(control.name)) in names and str(int(control.name)) != name:
                called.setdefault(str(int(control.name)), block)
        calls.append(called)
    callers: dict[str | None, int] = {name: 0 for name in names}
    for called in calls:
        for callee in called:
            callers[callee] += 1
    done = [False] * len(groups)
    for _ in groups:
        index = -1
        for i, (name, _body) in enumerate(groups):
            if not done[i] and (name is None or callers[name] == 0):
                index = i
                break
        if index < 0:
            _refuse(groups, calls, done, ctx, refusal)
            return
        done[index] = True
        for callee in calls[index]:
            callers[callee] -= 1
        yield from groups[index][1]


def _refuse(groups: list[Group], calls: list[dict[str, Block]], done: list[bool], ctx: Context,
            refusal: Refusal) -> None:
    """Subprograms left that each wait for a caller: they call each other. The error stands at a call."""
    left = {groups[i][0]: calls[i] for i in range(len(groups)) if not done[i]}
    name, called = next((n, c) for n, c in left.items() if any(callee in left for callee in c))
    callee = next(c for c in called if c in left)
    ctx.diagnostics.error(UnsupportedError(refusal(str(name), callee, len(left)), ctx.at(called[callee])))
