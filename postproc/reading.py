"""Text -> IR: a dialect's reader and its syntax pipeline, as a stream (``read_blocks``). Its callers pause the
cyclic garbage collector while a program streams (``postproc.collector.gc_paused``): blocks hold no reference
cycles, and measured here the collector's generation scans, not parsing, dominate object-per-block pipelines.

Below ``postproc.api`` so that the simulator and the sequences read programs without importing the API.
"""

from __future__ import annotations

from itertools import chain
from typing import Callable, Final, Iterable, Iterator, Mapping

from .context import Context
from .dialect import Dialect
from .errors import Diagnostics, Location, UsageError
from .ir import Block
from .syntaxes.lines import checked_lines
from .setup.machine_setup import MachineSetup
from .syntaxes.syntax import Pipeline

READER_FOUND: Final = "reader.found"
"""``ctx.run_data`` key: what the dialect's reader found in the program as it read it, under the reader's own keys
(LinuxCNC on a lathe: each subprogram's blocks as written, the profiles of its G70-G72). A dry run of the steps
after the reader on a context of its own (``postproc.api``: whether a program that computes can be kept, what its
run refuses) is given the same, as the program's own run has it: without it a cycle found no profile the reader
had read ("no subprogram o100 is defined before the cycle"), the reason given for flattening the program."""


def read_blocks(lines: Iterable[str], file: str, dialect: type[Dialect], setup: MachineSetup,
                diagnostics: Diagnostics, *, program_mode: str = "keep",
                prepare: Callable[[Context], None] | None = None,
                lanes: Callable[[Pipeline, Context], None] | None = None) -> tuple[Context, Iterator[Block]]:
    """Text -> IR: the dialect's reader, then its syntax pipeline. Returns the run's context too.

    ``program_mode`` says what the interpreter step does with a program that computes ('keep',
    'execute' or 'auto', see ``Context.program_mode``); it is set before the pipeline is built, as is
    whatever ``prepare`` adds to the context, so the steps choose their path once. ``lanes`` installs the
    run's speed-only shortcuts for the pipeline (``postproc.fast.reading.install_reading``, passed by the
    commands above the fast lane); None: every block takes the steps' general path."""
    if dialect.READER is None:
        raise UsageError(f"the {dialect.NAME} dialect cannot be read (it is write-only)")
    ctx = dialect.context(file, setup, diagnostics)
    ctx.program_mode = program_mode
    if prepare is not None:
        prepare(ctx)
    pipeline = dialect.pipeline(setup)
    if lanes is not None:
        lanes(pipeline, ctx)
    blocks = dialect.READER(ctx).read(checked_lines(lines, ctx, dialect.READER.BLANKS))
    return ctx, pipeline.run(_warn_if_empty(blocks, ctx), ctx)


def macro_arguments(dialect: type[Dialect], arguments: Mapping[str, float]) -> Callable[[Context], None]:
    """A ``prepare`` for ``read_blocks``: the program is a macro file run on its own, as called with
    ``arguments`` (``--arg A=30``: address -> value), which set the locals the dialect's argument
    specification gives them (``Dialect.MACRO_ARGUMENTS``; the interpreter step starts with them). An
    address the dialect does not take is wrong usage."""
    from .syntaxes.program import ARGUMENTS_KEY
    table = dialect.MACRO_ARGUMENTS
    if not table:
        raise UsageError(f"--arg: the {dialect.NAME} dialect has no macro call arguments")
    found: dict[int, float] = {}
    for letter, value in arguments.items():
        local = table.get(letter.upper())
        if local is None:
            raise UsageError(f"--arg {letter}: not an argument address of the {dialect.NAME} dialect (it takes "
                             f"{' '.join(sorted(table))})")
        found[local] = value

    def prepare(ctx: Context) -> None:
        ctx.run_data[ARGUMENTS_KEY] = found

    return prepare


_INERT = frozenset(("Comments", "TapeMark"))


def _warn_if_empty(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    """Pass the reader's blocks on; a program with none that does anything (no file, only comments or
    ``%``) gets a warning: an empty output is then no surprise. The check ends at the first such block,
    and the rest passes on with no step per block."""
    blocks = iter(blocks)
    return chain(_until_something(blocks, ctx), blocks)


def _until_something(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    for block in blocks:
        yield block
        if block.marks or block.words or not block.sections.keys() <= _INERT:  # (marks: words, not made)
            return
    if not ctx.diagnostics.errors:
        ctx.diagnostics.warn("the program is empty: no line in it programs anything", Location(ctx.file, 1, 1))
