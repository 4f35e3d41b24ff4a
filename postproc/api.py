"""The public API: read a program into the IR, translate it, all as streams (reading itself, and the
collector paused while a program streams, are in ``postproc.reading``)."""

from __future__ import annotations

import copy
import io
from typing import Callable, Iterable, TextIO

from . import native
native.install()  # the compiled hot path, before any of its modules is imported

from .dialect import Dialect
from .errors import Diagnostics, ErrorLevel, PostprocError, UsageError
from .ir import Block
from .lowering.lower import lower_for
from .plugins import Registry, default_registry
from .reading import gc_paused as gc_paused, read_blocks as read_blocks  # public API names
from .syntaxes.program import TARGET_OMITS_VACANT, ProgramSyntax
from .lowering.sequences import Sequences
from .setup.machine_setup import MachineSetup
from .source_map import OutputMap
from .syntax import Pipeline
from .context import Context




def translate(lines: Iterable[str], out: TextIO, *, file: str, source: str, target: str,
              setup: MachineSetup | None = None, registry: Registry | None = None,
              on_unsupported: str = "error", level: ErrorLevel = ErrorLevel.RAISE,
              diagnostics: Diagnostics | None = None, defines: dict[str, str] | None = None,
              output_map: OutputMap | None = None) -> Diagnostics:
    """Translate a program from ``source`` to ``target`` dialect, streaming into ``out``.

    ``defines`` are the user variables the set-up's templates see (``--define``); ``output_map``, when
    given, is filled with the source line (or template) of every written line.

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
        def prepare(ctx: Context) -> None:
            ctx.on_unsupported = on_unsupported
            ctx.keep_check = _keep_check(src, dst, ctx, registry)
            ctx.run_data[TARGET_OMITS_VACANT] = _omits_vacant_words(dst, setup)

        if setup.travel_limited():
            from .simulate.toolpath import check_travel
            lines = list(lines)  # read twice: the travel check simulates the source first
            check_travel(lines, file=file, dialect=src, setup=setup, diagnostics=diagnostics,
                         on_unsupported=on_unsupported, registry=registry)
        mode = "keep" if src.NAME == dst.NAME else "auto" if dst.PROGRAMS else "execute"
        from .fast.reading import install_reading  # (imported with the steps' modules, not at start)
        ctx, blocks = read_blocks(lines, file, src, setup, diagnostics, program_mode=mode, prepare=prepare,
                                  lanes=install_reading)
        sequences = Sequences(ctx, src.NAME, dst, defines)
        ctx.run_data["sequences"] = sequences
        if output_map is not None:
            ctx.run_data["output_map"] = output_map
        lowered = lower_for(sequences.before_lowering(blocks), ctx, dst, on_unsupported, registry.lowerings)
        writer = dst.WRITER(ctx, src.NAME, dst)
        from .fast.lane import install as install_fast_lane  # (imported with the writer's modules, not at start)
        install_fast_lane(writer)
        writer.write(sequences.after_lowering(lowered), out)
    diagnostics.check()
    return diagnostics


def _keep_check(src: type[Dialect], dst: type[Dialect], ctx: Context,
                registry: Registry) -> Callable[[list[Block]], str | None]:
    """A dry run deciding whether a program that computes can reach ``dst`` symbolically: the rest of
    the program goes through the reading steps after the interpreter step, lowering and ``dst``'s
    writer, from a copy of the modal state where the program stands; the first error found (a
    construct ``dst`` cannot spell, a cycle with computed words it would have to expand...) is the
    reason to flatten instead."""

    def reason(body: list[Block]) -> str | None:
        if not dst.PROGRAMS:
            return f"the {dst.NAME} dialect has no variables or control flow"
        dry = Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000, warn_stream=io.StringIO())
        trial = src.context(ctx.file, ctx.setup, dry)
        trial.state = copy.deepcopy(ctx.state)
        trial.on_unsupported = "error"
        trial.run_data["sequences"] = Sequences(trial, src.NAME, dst, enabled=False)  # a dry run renders none
        trial.run_data["dry_run"] = True  # what it writes is a part of the program, read back and discarded
        steps = [step for step in src.pipeline(ctx.setup).steps if not isinstance(step, ProgramSyntax)]
        blocks = Pipeline(src.NAME, steps).run(body, trial)
        lowered = lower_for(blocks, trial, dst, "error", registry.lowerings)
        writer = dst.WRITER(trial, src.NAME, dst) if dst.WRITER is not None else None
        text = io.StringIO()
        try:
            if writer is not None:
                writer.write(lowered, text)
        except PostprocError as err:
            return err.message
        if dry.errors:
            return _first(dry)
        # The symbolic output must read back under the target's own rules (labels, nesting...).
        back = Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000, warn_stream=io.StringIO())
        try:
            for _ in read_blocks(io.StringIO(text.getvalue()), ctx.file, dst, ctx.setup, back)[1]:
                pass
        except PostprocError as err:
            return f"the {dst.NAME} output would not read back: {err.message}"
        if back.errors:
            return f"the {dst.NAME} output would not read back: {_first(back)}"
        return None

    return reason


def _omits_vacant_words(dialect: type[Dialect], setup: MachineSetup) -> bool:
    """Whether ``dialect``'s controller omits a word whose value is vacant (its interpreter step says
    so); a dialect without variables never receives one."""
    if not dialect.PROGRAMS:
        return True
    for step in dialect.pipeline(setup).steps:
        if isinstance(step, ProgramSyntax):
            return step.OMITS_VACANT_WORDS
    return False


def _first(diagnostics: Diagnostics) -> str:
    first = diagnostics.errors[0]
    where = f"line {first.location.line}: " if first.location is not None else ""
    return where + first.message


def read_program(lines: Iterable[str], *, file: str, dialect: str, setup: MachineSetup | None = None,
                 registry: Registry | None = None, level: ErrorLevel = ErrorLevel.RAISE) -> list[Block]:
    """Read a whole program into a list of blocks (for tools and tests; translation streams)."""
    registry = registry or default_registry()
    diagnostics = Diagnostics(level)
    with gc_paused():
        from .fast.reading import install_reading
        _, blocks = read_blocks(lines, file, registry.dialect(dialect), setup or MachineSetup(), diagnostics,
                                lanes=install_reading)
        result = list(blocks)
    diagnostics.check()
    return result
