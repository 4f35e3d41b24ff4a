"""The writer base class: turns a dialect's blocks into text, with the set-up's templates, line format
and output map around every block.

Its own module (re-exported by ``postproc.dialect``) so that the per-block loop ``Writer.write`` is
compiled with the RS274 word writer that subclasses it (``pyproject.toml`` ``[tool.postproc] compiled``).
"""

from __future__ import annotations

import abc
from typing import Any, Callable, ClassVar, Iterable, Protocol, TextIO, Final

from mypy_extensions import mypyc_attr

from ..context import DROPPED_MOVES, Context
from ..cycle_words import CycleWords
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..ir import Block, one_line
from .line_feeds import Batch
from .line_format import LineFormat
from .displacement import Displacement
from .partial_block import write_without_refused

@mypyc_attr(allow_interpreted_subclasses=True)
class WrittenDialect(Protocol):
    """What a writer reads of the dialect it writes: a ``postproc.dialect.Dialect`` subclass (the class
    itself), its name and the capability flags writers read. Declared here so the writers' base needs
    nothing from ``postproc.dialect``, which builds on it (and re-exports ``Writer``)."""

    NAME: str
    LOWER_CASE: bool
    DWELL_UNIT: str
    CYCLE_WORDS: CycleWords | None
    CYCLE_SEMANTICS: str
    MACHINE_TYPES: frozenset[str]

    def family(self) -> str: ...


@mypyc_attr(allow_interpreted_subclasses=True)
class TemplateSource(Protocol):
    """The set-up's templates as the writer meets them (``postproc.lowering.sequences.Sequences``): text to write
    at the header and footer, and whether blocks carry a template's output (``Generated``)."""

    per_block: bool

    def render(self, name: str) -> str: ...


@mypyc_attr(allow_interpreted_subclasses=True)
class _NoTemplates:
    per_block = False

    def render(self, name: str) -> str:
        return ""


_NO_TEMPLATES: Final = _NoTemplates()


def _only_comments(sections: dict[str, Any]) -> bool:
    return len(sections) == 1 and "Comments" in sections


@mypyc_attr(allow_interpreted_subclasses=True)
class Lane:
    """A speed-only shortcut a run installs on its writer (``postproc.fast``): ``write`` writes a block as
    ``write_block`` would, or answers None (the general path writes it). An object, not a
    function: the writer's loop calls it natively (compiled: a bound method's call cost ~200 instructions a
    block)."""

    def __init__(self) -> None:
        self.passes_below = 0
        """A text ``write`` gives that is shorter than this passes the run's line rule as it is (set where the
        run's rule tells so from the length alone, ``postproc.fast.lane``; 0: every text goes to the rule)."""
        self.puts = False
        """The lane also offers ``put`` (read once a run by ``Writer.write``)."""
        self.plain = True
        """The text ``write`` answered last is of the kind ``passes_below`` speaks of (False: an expanded cycle's
        lines, ``postproc.fast.expansion_moves.ExpansionBlocks``, which go to the line rule whatever their length)."""

    def write(self, block: Block) -> str | None:
        raise NotImplementedError

    def put(self, block: Block, out: Batch, below: int) -> bool:
        """Where the text ``write`` answers goes straight to the output (no source map, nothing set aside; no line
        format, or only a line rule it passes as it is when shorter than ``below``, ``passes_below``; 0: no rule) and
        is no blank line (which the writer checks): put it into ``out`` as ``write`` would answer it, in pieces
        (``Batch.write_line``: no string joined for the one block); False: nothing put (the writer asks ``write``,
        then its general path). Asked only of a lane whose ``puts`` is set. A block it puts holds no sections but a
        straight block's (``postproc.fast.straight.STRAIGHT_KEYS``: no tape mark, no template's text, no change of
        distance mode), which ``Writer.write`` offers it before it looks for those, and it raises nothing (a block it
        is not sure of is declined, for the general path to write or refuse)."""
        return False


@mypyc_attr(allow_interpreted_subclasses=True)
class Writer(abc.ABC):
    """Turns blocks into text. Subclasses implement ``write_block``."""

    MAX_BLOCK_NUMBER: ClassVar[int] = 0
    """The largest block number the controller takes (0: any). A larger number of the source is dropped with a
    warning (``SectionWords.sequence_words``); numbering the run makes past it is refused: the set-up's
    (``LineFormat``) before anything is written, ``--renumber``'s at the block it would number."""

    def __init__(self, ctx: Context, source_dialect: str, target: WrittenDialect | None = None) -> None:
        self.ctx = ctx
        self.source_dialect = source_dialect
        self.target = target
        """The dialect written, whose capability flags the writer reads (None: every flag holds)."""
        self.lane: Lane | None = None
        """A speed-only shortcut the run installed (``postproc.fast``): ``write`` offers it every block first;
        it writes what ``write_block`` would, or answers None."""
        self.set_aside: list[str] | None = None
        """Where ``write`` puts each block's text while the writer sets a part of the program aside to write
        it elsewhere (a subprogram the dialect writes after the main program, in ``finish``); None: out."""
        self.opening: bool | None = None
        """Whether the written program opened with a tape mark ('%'): None until ``write`` has written its
        first block that does more than comment, then whether that block was a tape mark (a writer reads
        it while that block is written as the state before it)."""
        self.last_line = 0
        """The source line of the last block ``write`` was given (0: none yet), for ``finish``'s notes."""
        self.displacement: Displacement | None = None
        """With ``--on-unsupported warn``: the axes a dropped move left elsewhere (``postproc.output.displacement``)."""

    def capable(self, flag: str) -> bool:
        """Whether the target has the capability ``flag`` (an UPPER_CASE attribute of ``Dialect``, read by
        name: every flag, not only those ``WrittenDialect`` declares)."""
        return self.target is None or bool(getattr(self.target, flag))

    def write(self, blocks: Iterable[Block], out: TextIO) -> None:
        """Write every block. A block the target cannot express is an error, or with
        ``--on-unsupported warn`` a warning and the source block written as a comment.
        The header goes after an opening tape mark and the footer before the closing one; a block a
        set-up template wrote (``postproc.lowering.sequences``) is written as it is. The texts reach ``out``
        a batch at a time (``postproc.output.line_feeds.Batch``), all of them by the time this returns or
        raises."""
        sink = out if isinstance(out, Batch) else Batch(out)
        try:
            self._write(blocks, sink)
        finally:
            sink.flush()

    def _write(self, blocks: Iterable[Block], out: Batch) -> None:
        write_block = self.write_block
        lane = self.lane
        sequences = self.sequences()
        output_map = self.ctx.run_data.get("output_map")
        put = out.write if output_map is None else output_map.writer(out)
        """A text as it is to the output (through the map)."""
        sink = out if output_map is None else None
        """``put`` as a native call (a block's text: the bound method's call cost ~250 instructions compiled)."""
        target = self.target
        line_format = LineFormat.for_run(self.ctx, None if target is None else target.NAME,
                                         target is None or target.LOWER_CASE, getattr(target, "LINE_RULE", None),
                                         self.MAX_BLOCK_NUMBER, target is not None and target.NAME != self.source_dialect)
        emit = put if line_format is None else line_format.wrap(put)
        """A text formatted (``LineFormat.line``), to the output."""
        passes_below = lane.passes_below if lane is not None and line_format is not None and not line_format.formats \
            else 0
        """A text of the lane shorter than this passes the line rule as it is (``Lane.passes_below``): not looked at."""
        generated = sequences.per_block
        displacement = None
        displaced: set[str] = set()
        """``displacement.axes`` (one set for the run, changed in place), held here: ``Displacement`` runs
        interpreted, and its attribute read cost ~160 instructions a block."""
        dropped: list[int] = []
        """The source lines whose moves a lowering step dropped (``DROPPED_MOVES``, the list the step appends to)."""
        if self.ctx.on_unsupported == "warn":
            displacement = self.displacement = Displacement(self.ctx.increments, self.ctx.axis_words)
            displaced = displacement.axes
            dropped = self.ctx.run_data.setdefault(DROPPED_MOVES, [])
        footer: str | None = None
        started = False
        line = 0
        direct = out if lane is not None and lane.puts and output_map is None \
            and (line_format is None or passes_below > 0) else None
        """Where the lane puts its blocks' texts itself (``Lane.put``): no line format, or only a rule that a text
        shorter than ``passes_below`` passes as it is (``put`` is given that length)."""
        for block in blocks:
            line = block.line
            if started and direct is not None and lane is not None and not displaced and not dropped \
                    and self.set_aside is None and lane.put(block, direct, passes_below):
                # (A block the lane puts is a straight one: no tape mark, no template's text, no change of distance
                # mode, ``Lane.put``; so once the program has started, and while no move is displaced or dropped, it
                # is offered first: the looks for those sections cost ~115 instructions each a block compiled.)
                if self.opening is None and block.sections:
                    self.opening = False
                continue
            tape_mark = "TapeMark" in block.sections
            if not started and not tape_mark:
                started = True
                self._emit_template(emit, output_map, line_format, "header", sequences.render("header"))
            elif started and tape_mark and footer is None:
                footer = sequences.render("footer")
                self._emit_template(emit, output_map, line_format, "footer", footer)
            if generated and "Generated" in block.sections:
                text_of = block.sections["Generated"]
                if line_format is not None:
                    line_format.block, line_format.template = None, getattr(text_of, "template")
                self._emit_template(emit, output_map, line_format, getattr(text_of, "template"), getattr(text_of, "text"))
                continue
            failed = False
            short = 0  # below this length the block's text passes the line rule as it is (the lane's: passes_below)
            if displacement is not None and (displaced or dropped or "DistanceMode" in block.sections) \
                    and _displaced(self, displacement, block, dropped):
                continue  # (the common block, no axis displaced, nothing dropped, is not _displaced's: no call)
            try:
                if direct is not None and self.set_aside is None and lane is not None and lane.put(block, direct,
                                                                                          passes_below):
                    if self.opening is None and block.sections and not _only_comments(block.sections):
                        self.opening = tape_mark
                    continue
                text = lane.write(block) if lane is not None else None
                if text is None:
                    text = write_block(block)
                elif lane is not None and lane.plain:
                    short = passes_below
            except UnsupportedError as err:
                text = self.unsupported_block(block, err)
            except PostprocError as err:
                self.ctx.diagnostics.error(err.located(self.ctx.at(block)))
                text = None
                failed = True
            if self.opening is None and block.sections and not _only_comments(block.sections):
                self.opening = tape_mark
            if failed:
                continue
            set_aside = self.set_aside
            if set_aside is not None:
                if text:
                    set_aside.append(text)
                continue
            if text is not None:
                if (not text or text.isspace()) and block.text is not None and (block.words or block.sections):
                    text = self.nothing_written(block) if not self._failed() else text
                if output_map is not None:
                    output_map.source = block.line
                if line_format is not None:
                    line_format.block, line_format.template = block, None
                    if len(text) >= short:
                        text = line_format.line(text)
                if sink is not None:
                    sink.write(text)
                else:
                    put(text)
        if not started:
            self._emit_template(emit, output_map, line_format, "header", sequences.render("header"))
        self.last_line = line
        tail = self.finish()
        if tail:
            emit(tail)
        if footer is None:
            self._emit_template(emit, output_map, line_format, "footer", sequences.render("footer"))

    @staticmethod
    def _emit_template(emit: Callable[[str], object], output_map: Any, line_format: LineFormat | None, name: str,
                       text: str) -> None:
        if not text:
            return
        if line_format is not None:
            line_format.block, line_format.template = None, name
        if output_map is not None:
            output_map.source = None
            output_map.template = name
        emit(text)
        if output_map is not None:
            output_map.template = None

    def sequences(self) -> "TemplateSource":
        """The translation's templates, which ``translate`` puts in the context (``postproc.lowering.sequences``);
        a writer used on its own writes none."""
        found = self.ctx.run_data.get("sequences")
        return found if found is not None else _NO_TEMPLATES

    def unsupported_block(self, block: Block, err: UnsupportedError) -> str | None:
        """An error; with ``--on-unsupported warn``, the block without what the target cannot express and
        what depends on it (``postproc.output.partial_block``), or, where nothing can be kept, as a comment;
        a move so dropped displaces what follows (``postproc.output.displacement``)."""
        err.located(self.ctx.at(block))
        if self.ctx.on_unsupported == "warn":
            dropped: set[str] = set()
            kept = write_without_refused(self, block, err, dropped)
            if kept is None:
                self.ctx.diagnostics.warn(err.message + "; written as a comment", err.location)
                kept = self.comment_out(block)
                dropped = set(block.sections)
            if self.displacement is not None:
                self.displacement.dropped(block, dropped)
            return kept
        self.ctx.diagnostics.error(err)
        return None

    def _failed(self) -> bool:
        """The run has errors (its output is discarded): a block its reading refused says nothing more."""
        diagnostics = self.ctx.diagnostics
        return bool(diagnostics.errors or diagnostics.consequences)

    def nothing_written(self, block: Block) -> str:
        """A source block whose words all mean nothing to the target (grbl's G64: it runs one path mode) is
        written as a comment with a warning, never as an empty line (a generated block that writes
        nothing, such as an expansion's cycle cancel for grbl, has no source line to keep)."""
        err = PostprocError(f"nothing in this block has a meaning in {self.target.NAME if self.target else 'the target'}"
                            "; written as a comment", self.ctx.at(block))
        self.ctx.diagnostics.warn(err.message, err.location)
        text = (block.text or " ".join(a + n for a, n in block.words)).replace("(", "[").replace(")", "]")
        return f"(LINE {block.line}: {text.strip()})" + (block.eol or "\n")

    def comment_out(self, block: Block) -> str:
        """The source block as a comment line (for ``--on-unsupported warn``)."""
        text = one_line(block.text or " ".join(a + n for a, n in block.words)).replace("(", "[").replace(")", "]")
        return f"(UNSUPPORTED LINE {block.line}: {text.strip()})" + (block.eol or "\n")

    @abc.abstractmethod
    def write_block(self, block: Block) -> str | None:
        """The text of one block (with its end of line), or None to write nothing."""

    def finish(self) -> str:
        """Text to append after the last block (e.g. a footer)."""
        return ""


def _displaced(writer: Writer, displacement: Displacement, block: Block, lowered: list[int]) -> bool:
    """Follow the distance mode; True (an error reported) where ``block`` would move displaced by a
    move dropped before it (``lowered``: the source lines whose moves a lowering step dropped, not yet taken).
    A function, not a method: compiled, a method of a class that plugins subclass is called through Python's
    lookup (~900 instructions a block of every ``--on-unsupported warn`` run)."""
    if "DistanceMode" in block.sections:
        displacement.note(block.sections)
    if lowered:
        displacement.lowered(lowered)  # (the block itself is the comment the step left: it moves nothing)
    if not displacement.axes:
        return False
    problem = displacement.problem(block)
    if problem is None:
        return False
    displacement.axes.clear()  # one error says it: the output is discarded
    writer.ctx.diagnostics.error(ProgramError(problem, writer.ctx.at(block)))
    return True
