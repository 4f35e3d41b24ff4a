"""Neutral programs: blocks built from IR sections, with no dialect's spelling, to write with any writer.

A conformance check needs programs no dialect wrote: the writer under test spells them, and what it
spells is read back and compared with what the IR meant. A ``NeutralProgram`` is a recipe (plain data
that hypothesis can shrink and print); ``blocks()`` builds fresh blocks every time, since lowering
rewrites the blocks it is given.
"""

from __future__ import annotations

import io
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Iterator

from ..context import Context
from ..cycles.resolve import EXPANSIONS
from ..cycles.section import CannedCycle
from ..cycles.semantics import semantics_named, semantics_names
from ..dialect import Dialect
from ..errors import Diagnostics, ErrorLevel, ErrorList, PostprocError
from ..ir import (
    Block, Comments, CompoundMotion, Coolant, CycleCancel, DistanceMode, Dwell, Feed, Motion,
    Plane, ProgramControl, ReturnLevel, Section, Sequence, SpindleControl, SpindleSpeed, Units,
)
from ..lowering.lower import lower_for
from ..rs274.cycle_words import NEUTRAL_CYCLE_WORDS
from ..plugins import Registry, default_registry
from ..setup.machine_setup import MachineSetup
from ..simulate.move_record import as_events
from ..simulate.toolpath import TRANSLATE_ONLY, ToolpathTarget, simulate

NEUTRAL = "neutral IR"
"""The reading dialect a neutral program claims: no dialect's name, so every lowering step runs."""

Op = tuple[Any, ...]
"""One step of a recipe: ``(kind, *arguments)``, see ``NeutralProgram.blocks``."""


@dataclass
class NeutralProgram:
    """A program as a list of operations, on a mill (XY plane) or a lathe (ZX plane)."""

    ops: list[Op]
    lathe: bool = False
    numbered: bool = False
    """Blocks carry sequence numbers (N10, N20, ...)."""
    start: dict[str, float] = field(default_factory=dict)

    def blocks(self) -> list[Block]:
        """Fresh blocks: the prologue, one block per operation (two for a cycle and its cancel)."""
        out: list[Block] = []

        def block(*sections: Section) -> Block:
            b = Block(len(out) + 1, None)
            if self.numbered:
                b.add(Sequence(10 * (len(out) + 1)))
            for section in sections:
                b.add(section)
            out.append(b)
            return b

        # a lathe turns in ZX from the start (``Dialect.context``), and a lathe control may have no plane code
        block(*([Units("mm")] + ([] if self.lathe else [Plane("XY")]) + [DistanceMode("absolute")]))
        block(Motion("rapid", dict(self.start)))
        for op in self.ops:
            _add(op, block)
        block(ProgramControl("end_rewind"))
        return out

    def __repr__(self) -> str:
        kind = "lathe" if self.lathe else "mill"
        steps = "\n".join(f"  {op!r}" for op in self.ops)
        return f"NeutralProgram({kind}, numbered={self.numbered}, start={self.start!r},\n{steps})"


def _add(op: Op, block: Callable[..., Block]) -> None:
    kind, args = op[0], op[1:]
    if kind in ("rapid", "linear"):
        axes, feed = args[0], args[1] if len(args) > 1 else None
        sections: list[Section] = [Motion(str(kind), dict(axes))]
        if feed is not None:
            sections.append(Feed(float(feed)))
        block(*sections)
    elif kind == "arc":
        direction, end, center, feed = args
        block(Motion(str(direction), dict(end), dict(center)), Feed(float(feed)))
    elif kind == "dwell":
        block(Dwell(float(args[0])))
    elif kind == "spindle":
        block(SpindleSpeed(float(args[1])), SpindleControl(str(args[0])))
    elif kind == "spindle_stop":
        block(SpindleControl("stop"))
    elif kind == "coolant":
        block(Coolant(str(args[0])))
    elif kind == "comment":
        block(Comments([str(args[0])]))
    elif kind == "section":
        block(*args)
    elif kind == "cycle":  # ("cycle", cycle, *sections of its block before it: a spindle start)
        cycle = args[0]
        assert isinstance(cycle, CannedCycle)
        b = block(ReturnLevel(cycle.return_level), *args[1:], cycle, Feed(cycle.feed or 0.0))
        expand(b)
        block(CycleCancel())
    else:
        raise ValueError(f"unknown neutral operation {kind!r}")


def expand(block: Block) -> None:
    """Give a block with a ``CannedCycle`` the ``CompoundMotion`` a reading pipeline would give it."""
    cycle = block.sections["CannedCycle"]
    assert isinstance(cycle, CannedCycle)
    for expansion in EXPANSIONS:
        if cycle.kind in expansion.KINDS:
            items, _ = expansion().expand(cycle)
            block.add(CompoundMotion(cycle.kind, items))
            return
    raise ValueError(f"no expansion for the {cycle.kind} cycle")


def cycle_rules(dialect: type[Dialect]) -> str:
    """The hole-cycle rules a generated cycle is resolved under: the dialect's own, or, for a dialect without
    rules of its own (it writes no cycle natively), those of the first family modelled, as if the program had
    been read from that controller: its writer must keep or refuse the cycle all the same."""
    return dialect.CYCLE_SEMANTICS if semantics_named(dialect.CYCLE_SEMANTICS) is not None else semantics_names()[0]


def drill_cycle(kind: str, at: dict[str, float], hole: tuple[float, float], *, bottom: float, r: float,
                feed: float, semantics: str, q: float | None = None, dwell: float | None = None) -> CannedCycle:
    """A resolved hole cycle in the XY plane from the tool position ``at``, returning to the initial level."""
    words: dict[str, float | int] = {"X": hole[0], "Y": hole[1], "Z": bottom, "R": r}
    if q is not None:
        words["Q"] = q
    if dwell is not None:
        words["P"] = dwell
    return CannedCycle(kind, call=True, semantics=semantics, return_level="initial", plane="XY",
                       initial=at["Z"], r=r, bottom=bottom, q=q, dwell=dwell, feed=feed, repeat=1,
                       motion="rapid", start=dict(at), position={"X": hole[0], "Y": hole[1]}, words=words,
                       clearance=1.0 if q is not None else None)


@dataclass
class Written:
    """What a writer made of a neutral program: its text, the errors, and the section keys of every
    block that reached the writer (after lowering)."""

    text: str
    errors: list[PostprocError]
    reached: list[tuple[int, frozenset[str]]]
    crash: str | None = None
    """An exception other than a postproc error (a bug in the writer or a lowering step), with the
    line of the last block that reached the writer."""


def neutral_context(target: type[Dialect], setup: MachineSetup, file: str) -> Context:
    ctx = target.context(file, setup, Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000,
                                                  warn_stream=io.StringIO()))
    ctx.dialect = NEUTRAL
    ctx.cycle_words = NEUTRAL_CYCLE_WORDS  # the letters ``drill_cycle`` gives its words, whatever the target's
    return ctx


def write_neutral(blocks: Iterable[Block], target: type[Dialect], setup: MachineSetup, *,
                  file: str = "neutral.nc", registry: Registry | None = None) -> Written:
    """Lower ``blocks`` for ``target`` and write them with its writer, as a translation would."""
    registry = registry or default_registry()
    if target.WRITER is None:
        raise ValueError(f"the {target.NAME} dialect has no writer")
    ctx = neutral_context(target, setup, file)
    reached: list[tuple[int, frozenset[str]]] = []

    def record(stream: Iterator[Block]) -> Iterator[Block]:
        for b in stream:
            reached.append((b.line, frozenset(b.sections)))
            yield b

    out = io.StringIO()
    errors: list[PostprocError] = []
    try:
        target.WRITER(ctx, NEUTRAL, target).write(record(lower_for(iter(blocks), ctx, target, "error",
                                                                   registry.lowerings)), out)
    except ErrorList as errs:
        errors.extend(errs.errors)
    except PostprocError as err:
        errors.append(err)
    except Exception as exc:  # noqa: BLE001 - the suite reports a crashing writer, it does not crash
        where = f"line {reached[-1][0]}" if reached else "before the first block"
        return Written(out.getvalue(), errors, reached, f"{type(exc).__name__}: {exc} (at the neutral program's {where})")
    errors.extend(e for e in ctx.diagnostics.errors if e not in errors)
    return Written(out.getvalue(), errors, reached)


def simulate_neutral(blocks: Iterable[Block], dialect: type[Dialect], setup: MachineSetup, *,
                     registry: Registry | None = None) -> list[dict[str, object]]:
    """The toolpath a neutral program means (the simulator run on the IR itself, no text involved)."""
    registry = registry or default_registry()
    ctx = neutral_context(dialect, setup, "neutral.nc")
    steps = [step for step in registry.lowerings if step not in TRANSLATE_ONLY]
    events: list[dict[str, object]] = list(as_events(simulate(lower_for(iter(blocks), ctx, ToolpathTarget, "error",
                                                                      steps), ctx)))  # (dictionaries already)
    ctx.diagnostics.check()
    return events
