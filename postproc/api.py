"""The public API: read a program into the IR, translate it, all as streams.

The cyclic garbage collector is paused while a program streams: blocks hold no reference cycles, and
measured here the collector's generation scans, not parsing, dominate object-per-block pipelines.
"""

from __future__ import annotations

import contextlib
import gc
from typing import Iterable, Iterator, TextIO

from .dialect import Dialect
from .errors import Diagnostics, ErrorLevel, UsageError
from .ir import Block
from .lower import lower_for
from .plugins import Registry, default_registry
from .setup import MachineSetup
from .context import Context


@contextlib.contextmanager
def gc_paused() -> Iterator[None]:
    """Pause the cyclic collector for a streaming run (reference counting still frees every block)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def read_blocks(lines: Iterable[str], file: str, dialect: type[Dialect], setup: MachineSetup,
                diagnostics: Diagnostics) -> tuple[Context, Iterator[Block]]:
    """Text -> IR: the dialect's reader, then its syntax pipeline. Returns the run's context too."""
    if dialect.READER is None:
        raise UsageError(f"the {dialect.NAME} dialect cannot be read (it is write-only)")
    ctx = dialect.context(file, setup, diagnostics)
    pipeline = dialect.pipeline(setup)
    blocks = dialect.READER(ctx).read(lines)
    return ctx, pipeline.run(blocks, ctx)


def translate(lines: Iterable[str], out: TextIO, *, file: str, source: str, target: str,
              setup: MachineSetup | None = None, registry: Registry | None = None,
              on_unsupported: str = "error", level: ErrorLevel = ErrorLevel.RAISE,
              diagnostics: Diagnostics | None = None) -> Diagnostics:
    """Translate a program from ``source`` to ``target`` dialect, streaming into ``out``.

    Raises ``ErrorList`` when the program has errors (``out`` then holds a partial result the caller
    must discard); returns the diagnostics (warnings) otherwise.
    """
    registry = registry or default_registry()
    setup = setup or MachineSetup()
    diagnostics = diagnostics or Diagnostics(level)
    src, dst = registry.dialect(source), registry.dialect(target)
    if dst.WRITER is None:
        raise UsageError(f"the {dst.NAME} dialect cannot be written (it is read-only)")
    with gc_paused():
        ctx, blocks = read_blocks(lines, file, src, setup, diagnostics)
        ctx.on_unsupported = on_unsupported
        lowered = lower_for(blocks, ctx, dst, on_unsupported, registry.lowerings)
        writer = dst.WRITER(ctx, src.NAME, dst)
        writer.write(lowered, out)
    diagnostics.check()
    return diagnostics


def read_program(lines: Iterable[str], *, file: str, dialect: str, setup: MachineSetup | None = None,
                 registry: Registry | None = None, level: ErrorLevel = ErrorLevel.RAISE) -> list[Block]:
    """Read a whole program into a list of blocks (for tools and tests; translation streams)."""
    registry = registry or default_registry()
    diagnostics = Diagnostics(level)
    with gc_paused():
        _, blocks = read_blocks(lines, file, registry.dialect(dialect), setup or MachineSetup(), diagnostics)
        result = list(blocks)
    diagnostics.check()
    return result
