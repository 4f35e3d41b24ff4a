"""Where another dialect's subprograms stand in a LinuxCNC file: each after every subprogram that calls it.

rs274 looks for the ``O<n>`` of an ``M98 P<n>`` from the call onward (``postproc.interp.rules``: an
``O<n>`` only before the call is "Failed to find sub 'O<n>' before EOF" [V: rs274 2.9]), where Fanuc
finds a program anywhere in memory. The main program comes first, so its calls find every subprogram;
a subprogram that calls one written before it does not. This lowering step writes the subprograms after
the main program's end in an order where every caller comes before the programs it calls (the source's
order where that holds already). Subprograms that call each other (``M98`` both ways) have no such
order: a located error (a program kept symbolically is then flattened).

Only the subprograms are held back (a construct's look-ahead): the main program streams.
"""

from __future__ import annotations

from typing import Iterator

from postproc.context import Context
from postproc.control import CONTROL, Call
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir import Block
from postproc.rs274.return_level import ReturnLevels

_Group = tuple[str | None, list[Block]]
"""A subprogram's number (None: what stands before the first one) and its blocks, in source order."""


def subprograms_after_callers(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step for LinuxCNC (see the module docstring), which also writes the return level a cycle
    needs as the text comes (``postproc.rs274.return_level``: one loop for both); a LinuxCNC source is
    written as it is."""
    if ctx.dialect == target.NAME:
        yield from blocks
        return
    see = ReturnLevels(target).see
    ended = False
    groups: list[_Group] | None = None
    for block in blocks:
        sections = block.sections
        if "CannedCycle" in sections or "ReturnLevel" in sections:  # most blocks have neither: two tests
            see(block)
        if groups is None:
            if "ProgramStart" in sections or "ProgramControl" in sections:
                number = getattr(sections.get("ProgramStart"), "number", None)
                if ended and number is not None:
                    groups = [(str(int(number)), [block])]
                    continue
                end = sections.get("ProgramControl")
                if end is not None and getattr(end, "kind", None) in ("end", "end_rewind"):
                    ended = True
            yield block
            continue
        if "TapeMark" in sections:
            yield from _ordered(groups, ctx)
            groups = None
            ended = False
            yield block
            continue
        start = sections.get("ProgramStart")
        number = getattr(start, "number", None)
        if number is not None:
            groups.append((str(int(number)), [block]))
        else:
            groups[-1][1].append(block)
    if groups is not None:
        yield from _ordered(groups, ctx)


def _ordered(groups: list[_Group], ctx: Context) -> Iterator[Block]:
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
    callers = {name: 0 for name in names}
    for called in calls:
        for callee in called:
            callers[callee] += 1
    done = [False] * len(groups)
    for _ in groups:
        index = next((i for i, (name, _) in enumerate(groups)
                      if not done[i] and (name is None or callers[name] == 0)), None)
        if index is None:
            _refuse(groups, calls, done, ctx)
            return
        done[index] = True
        for callee in calls[index]:
            callers[callee] -= 1
        yield from groups[index][1]


def _refuse(groups: list[_Group], calls: list[dict[str, Block]], done: list[bool], ctx: Context) -> None:
    """Subprograms left that each wait for a caller: they call each other. The error stands at a call."""
    left = {groups[i][0]: calls[i] for i in range(len(groups)) if not done[i]}
    name, called = next((n, c) for n, c in left.items() if any(callee in left for callee in c))
    callee = next(c for c in called if c in left)
    ctx.diagnostics.error(UnsupportedError(
        f"subprograms O{name} and O{callee} call each other with M98 (through {len(left)} programs): LinuxCNC "
        f"finds an O-number only after the M98 that calls it, so no order of them finds every call",
        ctx.at(called[callee])))
