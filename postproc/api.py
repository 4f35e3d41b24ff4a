"""The public API: read a program into the IR, translate it, all as streams (reading itself, and the
collector paused while a program streams, are in ``postproc.reading``)."""

from __future__ import annotations

import copy
import io
from typing import TYPE_CHECKING, Callable, Iterable, Iterator, TextIO

from . import native
native.install()  # the compiled hot path, before any of its modules is imported

from .geometry.arc_end import SPIRAL, TARGET_ARC_END, UNKNOWN_START_TARGET
from .setup.work_offsets import set_up_places
from .lowering.feed_first import check_blocks
from .interp.control import GotoLabel
from .dialect import Dialect
from .errors import Diagnostics, ErrorLevel, PostprocError, UsageError
from .ir import Block
from .lowering.lower import lower_for
from .plugins import Registry, default_registry
from .collector import gc_paused as gc_paused  # public API names
from .reading import READER_FOUND, read_blocks as read_blocks
from .syntaxes.program import HIGHEST_SEQUENCE, RUN_CHECK, SUBPROGRAM_RULES_KEY, TARGET_OMITS_VACANT, ProgramSyntax
from .lowering.sequences import Sequences
from .setup.machine_setup import MachineSetup
from .ir.source_map import OutputMap
from .syntaxes.syntax import Pipeline
from .context import Context
from .frames.lowering import EVALUATE_KEY
from .patterns.lowering import POINT_BY_POINT_KEY
from .transforms import ProgramOptions, program_options, transform_program

if TYPE_CHECKING:
    from .lowering.arcs import ArcOption
    from .lowering.lower import Lowering
    from .transforms.spec import ProgramTransform




def translate(lines: Iterable[str], out: TextIO, *, file: str, source: str, target: str,
              setup: MachineSetup | None = None, registry: Registry | None = None,
              on_unsupported: str = "error", level: ErrorLevel = ErrorLevel.RAISE,
              diagnostics: Diagnostics | None = None, defines: dict[str, str] | None = None,
              output_map: OutputMap | None = None, units: str | None = None,
              transform: str | ProgramTransform | None = None, arcs: ArcOption | None = None) -> Diagnostics:
    """Translate a program from ``source`` to ``target`` dialect, streaming into ``out``.

    ``defines`` are the user variables the set-up's templates see (``--define``); ``output_map``, when
    given, is filled with the source line (or template) of every written line. ``units`` ('mm' or
    'inch') converts the whole program, ``transform`` (``postproc.transforms.spec``'s text, or one parsed)
    moves it (``postproc.transforms``); a program that computes is then flattened where the target can
    take it no other way, and refused where it cannot be flattened. ``arcs`` rewrites every arc after
    that (``postproc.lowering.arcs``; a program that computes is then executed).

    Raises ``ErrorList`` when the program has errors (``out`` then holds a partial result the caller
    must discard); returns the diagnostics (warnings) otherwise.
    """
    with gc_paused():  # (the registry and the dialects' modules load in here too: ``_translate``)
        return _translate(lines, out, file=file, source=source, target=target, setup=setup, registry=registry,
                          on_unsupported=on_unsupported, level=level, diagnostics=diagnostics, defines=defines,
                          output_map=output_map, units=units, transform=transform, arcs=arcs)


def _translate(lines: Iterable[str], out: TextIO, *, file: str, source: str, target: str,
               setup: MachineSetup | None = None, registry: Registry | None = None,
               on_unsupported: str = "error", level: ErrorLevel = ErrorLevel.RAISE,
               diagnostics: Diagnostics | None = None, defines: dict[str, str] | None = None,
               output_map: OutputMap | None = None, units: str | None = None,
               transform: str | ProgramTransform | None = None, arcs: ArcOption | None = None) -> Diagnostics:
    """``translate`` with the cyclic collector paused (by the caller) from the first line: the registry, the two
    dialects' readers and writers and the lowering steps are imported here, allocating what lives as long as
    the process; with the collector on, its collections while they loaded walked everything made before them
    again (four in a one-line translation, between the registry's own pause, ``postproc.plugins``, and the run's)."""
    registry = registry or default_registry()
    setup = setup or MachineSetup()
    diagnostics = diagnostics or Diagnostics(level)
    src, dst = registry.dialect(source), registry.dialect(target)
    options = program_options(units, transform)
    if dst.WRITER is None:
        raise UsageError(f"the {dst.NAME} dialect cannot be written (it is read-only)")
    with gc_paused():
        def prepare(ctx: Context) -> None:
            ctx.on_unsupported = on_unsupported
            ctx.keep_check = _keep_check(src, dst, ctx, registry, options)
            ctx.run_data[RUN_CHECK] = _run_check(src, ctx)
            ctx.run_data[TARGET_OMITS_VACANT] = _OmitsVacantWords(dst, setup)
            ctx.run_data[EVALUATE_KEY] = options.transform is not None
            ctx.run_data[POINT_BY_POINT_KEY] = options.active()
            if src.NAME != dst.NAME:  # (a copy runs as its source does, wherever the machine stands)
                ctx.run_data[UNKNOWN_START_TARGET] = dst.NAME
                if not ctx.lathe:  # (where the set-up places it, the start is known; a lathe is not followed)
                    ctx.state.places = set_up_places(setup)
            target_rule = dst.arc_end_rule(setup)
            if arcs is None and ctx.arc_end.runs == SPIRAL and not target_rule.covers(ctx.arc_end):
                # (a source that moves the centre has its arcs written about the moved one: settle_arc_ends)
                ctx.run_data[TARGET_ARC_END] = (dst.NAME, target_rule)

        moved = setup.travel_limited() and options.transform is not None
        if setup.travel_limited() and not moved:
            from .simulate.toolpath import check_travel
            lines = list(lines)  # read twice: the travel check simulates the source first
            check_travel(lines, file=file, dialect=src, setup=setup, diagnostics=diagnostics,
                         on_unsupported=on_unsupported, registry=registry)
        mode = ("keep" if src.NAME == dst.NAME and not options.active() and arcs is None
                else "auto" if dst.PROGRAMS and arcs is None else "execute")
        from .fast.reading import install_reading  # (imported with the steps' modules, not at start)
        ctx, blocks = read_blocks(lines, file, src, setup, diagnostics, program_mode=mode, prepare=prepare,
                                  lanes=install_reading)
        sequences = Sequences(ctx, src.NAME, dst, defines)
        ctx.run_data["sequences"] = sequences
        if output_map is not None:
            ctx.run_data["output_map"] = output_map
        last = _arc_pass(arcs, ctx, dst)  # after every other step (and the map)
        if options.active():
            lowered = lower_for(sequences.before_lowering(blocks), ctx, dst, on_unsupported, registry.lowerings)
            lowered = transform_program(lowered, ctx, options)
            lowered = lowered if last is None else last(lowered, ctx, dst)
        else:  # (the arc pass in the lowering's loop)
            lowered = lower_for(sequences.before_lowering(blocks), ctx, dst, on_unsupported, registry.lowerings,
                                then=() if last is None else (last,))
        writer_class = dst.writer_class(ctx)
        if writer_class is None:
            raise UsageError(f"the {dst.NAME} dialect cannot write this program (it has no writer for it)")
        writer = writer_class(ctx, src.NAME, dst)
        from .fast.lane import install as install_fast_lane  # (imported with the writer's modules, not at start)
        install_fast_lane(writer)
        from .fast.expansion_moves import install_expansion  # (likewise)
        install_expansion(writer)
        if not moved:
            writer.write(sequences.after_lowering(lowered), out)
        else:  # the travel that matters is the moved program's: it is checked before a line leaves
            text = io.StringIO()
            writer.write(sequences.after_lowering(lowered), text)
            if not diagnostics.errors:
                from .simulate.toolpath import check_travel
                check_travel(io.StringIO(text.getvalue(), newline=""), file=f"{file} (moved by --transform)",
                             dialect=dst, setup=setup, diagnostics=diagnostics, on_unsupported=on_unsupported,
                             registry=registry)
            out.write(text.getvalue())
    diagnostics.check()
    return diagnostics


def _arc_pass(arcs: ArcOption | None, ctx: Context, dst: type[Dialect]) -> Lowering | None:
    """The run's last lowering step: ``--arcs``'s rewrite, or the settle pass where the source's controller and the
    target leave arcs to settle (``ArcEndRule.settles_for``), else None: its module (``postproc.lowering.arcs``,
    compiled, with ``arc_words`` and ``arc_geometry``: ~2.5M instructions) is not imported by a translation from a
    spiral controller (Fanuc...) to one without grbl's R-arc slack (LinuxCNC, ISG, Fagor, a copy)."""
    if arcs is not None:
        from .lowering.arcs import RewriteArcs
        return RewriteArcs(arcs)
    if ctx.arc_end.settles_for(dst.R_ARC_FLOAT_SLACK):
        from .lowering.arcs import settle_arc_ends
        return settle_arc_ends
    return None


def _keep_check(src: type[Dialect], dst: type[Dialect], ctx: Context, registry: Registry,
                options: ProgramOptions) -> Callable[[list[Block]], str | None]:
    """A dry run deciding whether a program that computes can reach ``dst`` symbolically: the rest of
    the program goes through the reading steps after the interpreter step, lowering and ``dst``'s
    writer, from a copy of the modal state where the program stands; the first error found (a
    construct ``dst`` cannot spell, a cycle with computed words it would have to expand...) is the
    reason to flatten instead."""

    program = next((step for step in src.pipeline(ctx.setup).steps if isinstance(step, ProgramSyntax)), None)
    frame_evaluated = dst.NAME != src.NAME or options.transform is not None
    theirs: list[ProgramSyntax | None] = []
    """The target's program step, found when a program that computes is first judged: building the
    target's reading pipeline imports its readers and syntax objects, which a plain translation never uses."""

    def reason(body: list[Block]) -> str | None:
        # (imported where a program that computes is first judged, never by a plain translation)
        from .frames.parameters import frame_parameter_read
        from .interp.jump_targets import jump_past_end, missing_fallthrough
        from .interp.numbers import foreign_number
        from .interp.returns import foreign_return
        if not dst.PROGRAMS:
            return f"the {dst.NAME} dialect has no variables or control flow"
        falls = missing_fallthrough(body)
        if falls is not None:
            target = falls.label if isinstance(falls, GotoLabel) else falls.target
            return f"a jump to {target}, which is missing, goes on with the next block ({dst.NAME} would alarm)"
        past = jump_past_end(body, program.is_program_end) if program is not None and \
            program.SUBPROGRAM_RULES.jumps_past_end else None
        if past is not None:
            target = past.label if isinstance(past, GotoLabel) else past.target
            return f"a jump to {target}, after the program end, where {dst.NAME}'s program keeps no blocks"
        if frame_evaluated and program is not None and program.FRAME_PARAMETERS:
            read = frame_parameter_read(body, program.FRAME_PARAMETERS.__contains__)
            if read is not None:
                return f"it reads its coordinate frame ({read}), which is evaluated into the coordinates here"
        ours_made = None if program is None else type(program).VARIABLES
        if not theirs:
            theirs.append(None if dst.NAME == src.NAME else next(
                (step for step in dst.pipeline(ctx.setup).steps if isinstance(step, ProgramSyntax)), None))
        theirs_made = None if theirs[0] is None else type(theirs[0]).VARIABLES
        if ours_made is not None and theirs_made is not None:
            foreign = foreign_number(body, ours_made, theirs_made, (src.NAME, dst.NAME))
            if foreign is not None:
                return foreign
            assert program is not None and theirs[0] is not None  # (each made its table)
            foreign = foreign_return(body, (ours_made, program.SUBPROGRAM_RULES),
                                     (theirs_made, theirs[0].SUBPROGRAM_RULES), (src.NAME, dst.NAME))
            if foreign is not None:
                return foreign
        dry = Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000, warn_stream=io.StringIO())
        trial = src.context(ctx.file, ctx.setup, dry)
        trial.state = copy.deepcopy(ctx.state)
        trial.frame_run = copy.deepcopy(ctx.frame_run)  # the frame and position the run has reached (frames.lowering)
        trial.on_unsupported = "error"
        trial.run_data["sequences"] = Sequences(trial, src.NAME, dst, enabled=False)  # a dry run renders none
        trial.run_data[EVALUATE_KEY] = options.transform is not None
        trial.run_data[POINT_BY_POINT_KEY] = options.active()
        if HIGHEST_SEQUENCE in ctx.run_data:  # the jumps a target numbers itself start above the program's
            trial.run_data[HIGHEST_SEQUENCE] = ctx.run_data[HIGHEST_SEQUENCE]
        if program is not None:  # (the dry run's steps leave the program step out: its rules come with it)
            trial.run_data[SUBPROGRAM_RULES_KEY] = program.SUBPROGRAM_RULES
        trial.run_data["dry_run"] = True  # what it writes is a part of the program, read back and discarded
        if READER_FOUND in ctx.run_data:  # the subprograms the reader found, as the program's own run sees them
            trial.run_data[READER_FOUND] = ctx.run_data[READER_FOUND]
        steps = [step for step in src.pipeline(ctx.setup).steps if not isinstance(step, ProgramSyntax)]
        blocks = Pipeline(src.NAME, steps).run(body, trial)
        lowered = transform_program(lower_for(blocks, trial, dst, "error", registry.lowerings), trial, options)
        writer_class = dst.writer_class(trial)
        writer = writer_class(trial, src.NAME, dst) if writer_class is not None else None
        text = io.StringIO()
        try:
            if writer is not None:
                writer.write(lowered, text)
        except PostprocError as err:
            return err.message
        if dry.errors:
            return _first(dry)
        # The symbolic output must read back under the target's own rules (labels, nesting...), from the spindle
        # where the program stands (a feed per revolution after an S500 M3 before the first construct is sound).
        back = Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000, warn_stream=io.StringIO())
        standing = ctx.state

        def turning(read: Context) -> None:  # the spindle as the program left it before the text read back
            read.state.spindle, read.state.spindle_rpm = standing.spindle, standing.spindle_rpm

        try:
            for _ in read_blocks(io.StringIO(text.getvalue()), ctx.file, dst, ctx.setup, back, prepare=turning)[1]:
                pass
        except PostprocError as err:
            return f"the {dst.NAME} output would not read back: {err.message}"
        if back.errors:
            return f"the {dst.NAME} output would not read back: {_first(back)}"
        return None

    return reason


def _run_check(src: type[Dialect], ctx: Context) -> Callable[[Iterable[Block]], Iterator[Block]]:
    """The reading steps after the interpreter step over a program's run before it is kept symbolically
    (``ProgramSyntax.RUN_BEFORE_KEEP``), from a copy of the modal state where the program stands: each
    error they find in the run (an arc whose computed end is off its circle, which the symbolic text
    hides from them; a feed move before any feed rate, ``check_blocks``) is reported at its line, as when
    the program is flattened."""

    def later_steps(run: Iterable[Block]) -> Iterator[Block]:
        found = Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000, warn_stream=io.StringIO())
        trial = src.context(ctx.file, ctx.setup, found)
        trial.state = copy.deepcopy(ctx.state)
        trial.on_unsupported = ctx.on_unsupported
        if READER_FOUND in ctx.run_data:  # (as in ``_keep_check``)
            trial.run_data[READER_FOUND] = ctx.run_data[READER_FOUND]
        steps = [step for step in src.pipeline(ctx.setup).steps if not isinstance(step, ProgramSyntax)]

        def forward() -> None:  # errors in the run's order; no warnings (the program's own pass gives those)
            for err in found.errors:
                ctx.diagnostics.error(err)
            found.errors.clear()

        blocks = Pipeline(src.NAME, steps).run(run, trial)
        if trial.state.feed is None:  # no feed rate in force where the program stands: as when flattened,
            blocks = check_blocks(blocks, trial, src)  # a feed move before the run's first F is refused
        for block in blocks:
            forward()
            yield block
        forward()

    return later_steps


class _OmitsVacantWords:
    """Whether ``dialect``'s controller omits a word whose value is vacant (its interpreter step says
    so; a dialect without variables never receives one), as the truth of this object: found when the
    reading first asks (``TARGET_OMITS_VACANT``: a program that computes a word which may be vacant), since
    building the target's reading pipeline imports its readers and syntax objects, which a plain
    translation never uses (tests/test_startup_imports.py)."""

    __slots__ = ("dialect", "setup", "answer")

    def __init__(self, dialect: type[Dialect], setup: MachineSetup) -> None:
        self.dialect = dialect
        self.setup = setup
        self.answer: bool | None = None if dialect.PROGRAMS else True

    def __bool__(self) -> bool:
        if self.answer is None:
            self.answer = next((step.OMITS_VACANT_WORDS for step in self.dialect.pipeline(self.setup).steps
                                if isinstance(step, ProgramSyntax)), False)
        return self.answer


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
