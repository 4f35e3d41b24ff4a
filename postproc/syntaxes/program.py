"""The streaming step: a straight program passes untouched; a program that computes is stored and run.

``ProgramSyntax`` goes first in a dialect's reading pipeline, right after the reader. With
``ctx.program_mode == "keep"`` it hands the reader's stream on as it is (the constructs travel
symbolically to a target that has them). With ``"execute"`` it streams the blocks until the first
parametric one (an ``Assign`` or ``Control`` section, or an expression value), keeping the text of the
last ``Limits.kept_prefix`` blocks for backward jumps; from there it reads the rest of the program into
a ``ProgramStore`` and yields the blocks the interpreter executes, with a comment block before each call,
loop iteration and jump taken.

A dialect subclasses ``ProgramSyntax`` with its data (class attributes below: its family's ``VARIABLES``
above all, which the base does not choose) and, if it needs to, its ``spell_evaluated``.
"""

from __future__ import annotations

import io
from typing import TYPE_CHECKING, Callable, ClassVar, Iterable, Iterator

from mypy_extensions import mypyc_attr

from ..interp.control import ASSIGN, CONTROL, Call, ModalCall
from ..errors import ConfigError, Diagnostics, ErrorLevel, PostprocError
from ..ir.expr import Expr, Var
from ..ir import AXES, Block, Sequence
from ..ir.keys import only_move
from ..context import Context
from .syntax import Syntax
from .kept_lines import Kept, KeptLines
from ..interp.spelling import spell_integer, spell_number
from ..interp.rules import STORED_PROGRAMS, SubprogramRules
from ..interp.variables import RUN_INTERPRETER_KEY, RUN_VARIABLES_KEY, Variables, VariablesFactory

if TYPE_CHECKING:
    from pathlib import Path  # annotations only: a start makes no path object (pathlib imports urllib.parse)
    from ..interp.host import Reporter
    from ..interp.store import Program
    from ..interp.structure import StreamCheck

ENCODING = {"encoding": "utf-8", "errors": "surrogateescape", "newline": ""}
TARGET_OMITS_VACANT = "target_omits_vacant"
"""``ctx.run_data`` key: whether the translation's target omits a word whose value is vacant
(``ProgramSyntax.OMITS_VACANT_WORDS`` of its step; absent: it does, nothing is checked)."""
RUN_CHECK = "run_check"
"""``ctx.run_data`` key: the reading steps after this one, as a function of the blocks a run yields
(``RUN_BEFORE_KEEP``): what they refuse in the run (an arc whose computed end is not on its circle) is
reported at its line, as the flattened program's would be (absent: the run alone is checked)."""
HIGHEST_SEQUENCE = "highest_sequence"
"""``ctx.run_data`` key: the highest block number of a program kept symbolically (``ProgramSyntax``, when it
decides to keep it): a target that spells a construct as jumps to block numbers of its own (Fanuc's
``IF .. ELSE``, ``postproc.rs274.macro_jumps``) numbers them above it, so they never meet the program's."""
SUBPROGRAM_RULES_KEY = "subprogram_rules"
"""``ctx.run_data`` key: the reading dialect's ``SubprogramRules`` (its interpreter step's ``SUBPROGRAM_RULES``), set as
the step starts a run, so that a later step or the writer reads the source's rules from the run itself (grblHAL's
writer its bound of nested calls) and not from a registry."""
ARGUMENTS_KEY = "macro_arguments"
"""``ctx.run_data`` key of the locals a program run on its own starts with (``--arg A=30``: {1: 30.0})."""
"""What the step keeps of a streamed block, for a backward jump (``ProgramSyntax._reread``): its text
(ending ``\n``), its text and end of line, or None (a block without text). Most blocks keep the reader's
own string: no object per block."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ProgramSyntax(Syntax):
    """The interpreter step. Class attributes are the reading dialect's data."""

    XNAME = "ProgramSyntax"
    __slots__ = ()

    SEQUENCE_LETTER: ClassVar[str] = "N"
    """Address of block numbers."""
    AXIS_LETTERS: ClassVar[frozenset[str]] = frozenset(AXES)
    """Addresses that move an axis (a modal call follows a block with one)."""
    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset()
    """Addresses whose evaluated value must be an integer (written without a decimal point)."""
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset()
    """Words that end the program (nothing after them runs), e.g. ``("M", 30)``."""
    MACRO_LOCALS: ClassVar[int] = 0
    """Highest local variable a call argument may set (0: calls pass no numbered arguments)."""
    FRAME_PARAMETERS: ClassVar[frozenset[int]] = frozenset()
    """The numbers of the family's parameters read from the frame evaluation (LinuxCNC's offsets #5210-#5390
    and current position #5420-#5428): a program that reads one is flattened where its frame is evaluated
    (``postproc.frames.parameters``); none here."""
    VARIABLES: ClassVar[VariablesFactory | None] = None
    """The variable model (and vacancy rules) of the dialect's family, e.g. ``postproc.rs274.variables``'
    ``MacroBVariables``; None: the dialect runs no program that computes (one is a located error)."""
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}", "{name}.nc")
    """File names tried in each library folder for a subprogram (``{name}``: its name, brackets
    removed; ``{number}``: the name as an int, for ``{number:04d}``-style patterns)."""
    PROGRAM_LABEL: ClassVar[str] = "{name}"
    RUN_BEFORE_KEEP: ClassVar[bool] = False
    """Run a program before keeping it symbolically for another dialect, and refuse it where the run
    fails: for a dialect whose run-time errors (an unset variable read) are values in the targets."""
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = STORED_PROGRAMS
    """How numbered subprograms are found and ended (``postproc.interp.rules``)."""
    OMITS_VACANT_WORDS: ClassVar[bool] = False
    """A word whose value is a vacant variable is omitted, as if absent (Custom Macro B). A program kept
    symbolically for a target without this rule (which reads such a word as 0, or refuses it) is run
    first, and flattened when one of its words is vacant there."""
    """How messages name a subprogram (``O{number:04d}``, ``o{name}``)."""

    def build(self, block: Block, ctx: Context) -> None:
        """Unused: the step streams (``process``)."""

    def variables(self, ctx: Context, increment: Callable[[], float]) -> Variables:
        """The run's variables (``VARIABLES``); a dialect whose variables depend on the set-up (a
        controller variant's numbers) overrides it."""
        make: VariablesFactory | None = type(self).VARIABLES
        if make is None:
            raise ConfigError(f"{ctx.dialect}: {type(self).__name__} declares no VARIABLES, so a program that "
                              "computes cannot be run")
        return make(increment)

    # -- the host protocol (postproc.interp.host.Host) -----------------------------------------
    def spell_evaluated(self, letter: str, value: float) -> str:
        if letter in self.INTEGER_ADDRESSES:
            return spell_integer(letter, value)
        return spell_number(value)

    def program_label(self, name: str) -> str:
        return _format(self.PROGRAM_LABEL, name)

    def is_program_end(self, block: Block) -> bool:
        ends = self.END_CODES
        for letter, text in block.words:
            if text.isdigit() and (letter.upper(), int(text)) in ends:
                return True
        return False

    # -- reading ---------------------------------------------------------------------------------
    def read_lines(self, lines: Iterable[str], file: str, ctx: Context, diagnostics: Diagnostics) -> list[Block]:
        """Blocks of ``lines`` through the dialect's own reader (reporting into ``diagnostics``)."""
        from .lines import checked_lines
        reader = ctx.reader
        if reader is None:
            return []
        sub = Context(file, ctx.setup, diagnostics, ctx.dialect)
        sub.reader = reader
        blanks: str = getattr(reader, "BLANKS", "")  # Reader.BLANKS (ctx.reader is typed as any callable)
        return list(reader(sub).read(checked_lines(lines, sub, blanks)))

    def library_file(self, name: str, ctx: Context) -> Path | None:
        for folder in ctx.setup.library_paths():
            for pattern in self.LIBRARY_FILES:
                path = folder / _format(pattern, name)
                if path.is_file():
                    return path
        return None

    def load(self, name: str, ctx: Context) -> Program | None:
        """The library program of subprogram ``name``, read through the dialect's reader, or None."""
        path = self.library_file(name, ctx)
        if path is None:
            return None
        try:
            with open(path, "r", **ENCODING) as src:  # type: ignore[call-overload]
                blocks = self.read_lines(src, str(path), ctx, ctx.diagnostics)
        except OSError as exc:
            raise ConfigError(f"cannot read {path}: {exc.strerror}") from None
        from ..interp.store import Program
        return Program(str(path), blocks, self.is_program_end, self.SUBPROGRAM_RULES)

    # -- the stream ------------------------------------------------------------------------------
    def process(self, blocks: Iterable[Block], ctx: Context) -> Iterator[Block]:
        """Every mode checks the program's structure and expressions as it streams
        (``postproc.interp.structure``): a program kept symbolically is refused where its run would be
        (an unclosed loop, a subprogram defined twice, ``SQRT[-4]``)."""
        ctx.run_data[SUBPROGRAM_RULES_KEY] = self.SUBPROGRAM_RULES
        if ctx.program_mode == "keep":
            return self._checked(iter(blocks), ctx)
        return self._execute(iter(blocks), ctx)

    def structure_check(self, ctx: Context) -> StreamCheck:
        from ..interp.structure import StreamCheck  # loaded by the first construct or program number
        return StreamCheck(ctx.file, self.SUBPROGRAM_RULES, ctx.diagnostics.error)

    def _checked(self, blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
        check: StreamCheck | None = None
        control, assign, start, sequence = CONTROL, ASSIGN, "ProgramStart", "Sequence"
        for block in blocks:
            sections = block.sections
            size = len(sections)  # (most blocks have no section but their block number: one look-up, not three;
            # most others a move and that number, ``only_move``: two)
            if size and (size > 1 or sequence not in sections) and not only_move(sections) and (
                    control in sections or start in sections or assign in sections) or (
                    block.values and not block.canonical and _computes(block)):
                if check is None:
                    check = self.structure_check(ctx)
                check.see(block)
            yield block
        if check is not None:
            check.end()

    def _execute(self, blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
        limit = ctx.setup.limits.kept_prefix
        kept = KeptLines(limit)  # compact: one string a chunk of lines (postproc.syntaxes.kept_lines)
        seen = 0
        check: StreamCheck | None = None
        # locals: a compiled module looks another module's names up per use
        control, assign, start, sequence = CONTROL, ASSIGN, "ProgramStart", "Sequence"
        highest = -1
        for block in blocks:
            sections = block.sections
            numbered = sections.get(sequence)
            # (most blocks have no section but their block number, and no value yet: three look-ups saved)
            others = len(sections) > (0 if numbered is None else 1)
            if others or block.values:
                if control in sections or assign in sections or (block.values and _computes(block)):
                    break
            if numbered is not None:
                number = _number(numbered)
                if number > highest:
                    highest = number
            if others and start in sections:
                if check is None:
                    check = self.structure_check(ctx)
                check.see(block)
            text = block.text
            eol = block.eol
            kept.append(text if text is None or eol == "\n" else (text, eol))  # mostly the reader's own string
            seen += 1
            yield block
        else:
            return
        if check is None:
            check = self.structure_check(ctx)
        if ctx.program_mode == "auto":
            body = [block]
            body.extend(blocks)
            ctx.run_data[HIGHEST_SEQUENCE] = max([highest] + [_number(b.sections[sequence]) for b in body
                                                              if sequence in b.sections])
            if not _sound(body, check):
                return  # its errors are reported: nothing is kept or run
            reason = self._keep_reason(body, ctx, kept)
            if reason is None:
                reason = self._vacancy_reason(body, ctx, kept, seen)
            if reason is None:
                if self.RUN_BEFORE_KEEP:
                    self._check_runs(body, ctx, kept, seen)
                yield from body
                return
            ctx.diagnostics.warn(f"the program is flattened (its evaluated motion is written): {reason}",
                                 ctx.at(block))
            block, blocks = body[0], iter(body[1:])
            check = None  # checked
        yield from self._run(block, blocks, ctx, kept, seen, check, flattening=True)

    def _check_runs(self, body: list[Block], ctx: Context, kept: KeptLines, seen: int) -> None:
        """Run fresh copies of the program to its end, reporting the interpreter's first error (located in
        the program) and what the later reading steps refuse in the run (``RUN_CHECK``: an arc whose
        computed end is off its circle): a program kept symbolically then fails to translate where it
        fails to run."""
        copies = self._copies(body, ctx, kept)
        if not copies:
            return
        run = self._run(copies[0], iter(copies[1:]), ctx, kept, seen)
        later: Callable[[Iterable[Block]], Iterator[Block]] | None = ctx.run_data.get(RUN_CHECK)
        for _ in run if later is None else later(run):
            pass

    def _copies(self, body: list[Block], ctx: Context, kept: KeptLines) -> list[Block]:
        """Fresh blocks of ``body``, read as the program reads them: after the lines of the streamed
        prefix the reader needs for that (``reading_context``), which are left out again."""
        lead = self.reading_context(kept)
        copies = self.read_lines(_physical(lead + [(b.text or "") + b.eol for b in body]), ctx.file, ctx, _quiet())
        copies = copies[len(lead):] if len(copies) == len(lead) + len(body) else copies
        for original, copy in zip(body, copies):
            copy.line = original.line
        return copies

    def reading_context(self, kept: KeptLines) -> list[str]:
        """The last lines of the streamed prefix (``kept``, oldest first) that change how the reader reads
        the lines after them (ISG: an open ``#VAR`` block), each ending in its end of line; none here."""
        return []

    def _vacancy_reason(self, body: list[Block], ctx: Context, kept: KeptLines, seen: int) -> str | None:
        """Why ``body`` cannot travel symbolically to a target that does not omit vacant words: the first
        error of a run on fresh copies where a vacant word is an error (a vacant word, or an error that
        hides whether one follows: the flattening run then reports it). None: no word can be vacant."""
        if not self.OMITS_VACANT_WORDS or ctx.run_data.get(TARGET_OMITS_VACANT, True):
            return None
        if not _may_be_vacant(body):
            return None
        copies = self._copies(body, ctx, kept)
        found: list[PostprocError] = []

        def report(err: PostprocError) -> None:
            found.append(err)

        for _ in self._run(copies[0], iter(copies[1:]), ctx, kept, seen, report=report,
                           vacant_word="this controller omits the word, the target would not"):
            if found:
                break
        if not found:
            return None
        where = found[0].location
        return (f"line {where.line}: " if where is not None else "") + found[0].message

    def _keep_reason(self, body: list[Block], ctx: Context, kept: KeptLines) -> str | None:
        """Why ``body`` (the program from its first construct on) cannot travel symbolically, through
        ``ctx.keep_check`` on fresh copies (the check runs the later steps, which change blocks)."""
        check = ctx.keep_check
        if check is None:
            return "the target's spelling of the program's constructs was not checked"
        return check(self._copies(body, ctx, kept))

    def _run(self, first: Block, rest: Iterator[Block], ctx: Context, kept: KeptLines,
             seen: int, check: StreamCheck | None = None, report: Reporter | None = None,
             vacant_word: str | None = None, flattening: bool = False) -> Iterator[Block]:
        """Run the program from ``first`` on; ``check``: the structure check of what streamed before it,
        to finish on the rest (None: the rest was checked); ``report``: where its errors go (the
        diagnostics); ``vacant_word``: a vacant word is an error saying so (``Interpreter.vacant_word``);
        ``flattening``: the run is written, so a statement under block delete is an error
        (``Interpreter.skip_refused``)."""
        dropped = seen - len(kept)
        prefix = self._reread(kept, ctx, first_line=first.line - len(kept))
        body = prefix + [first]
        body.extend(rest)
        if check is not None and not _sound(body[len(prefix):], check):
            return
        from ..interp.machine import Interpreter  # loaded only when a program computes
        from ..interp.store import Program, ProgramStore
        if ctx.diagnostics.errors:
            return  # a line was refused: what would run is not the program written, and nothing is written
        try:
            main = Program(ctx.file, body, self.is_program_end, self.SUBPROGRAM_RULES)
        except PostprocError as err:
            ctx.diagnostics.error(err)
            return
        store = ProgramStore(main, lambda name: self.load(name, ctx), dropped=dropped,
                             kept_limit=ctx.setup.limits.kept_prefix)
        increment = ctx.setup.input.increment
        state = ctx.state
        try:
            variables = self.variables(ctx, lambda: increment(state.units))
        except PostprocError as err:
            ctx.diagnostics.error(err.located(ctx.at(first)))
            return
        arguments: dict[int, float] | None = ctx.run_data.get(ARGUMENTS_KEY)
        for key, value in (arguments or {}).items():
            variables.write(key, value)  # --arg: the main program run as a macro called with them
        ctx.run_data[RUN_VARIABLES_KEY] = variables  # a later step evaluates words kept as written there
        interpreter = Interpreter(store, self, variables, ctx.setup.limits, report or ctx.diagnostics.error,
                                  annotate=True, rules=self.SUBPROGRAM_RULES, counts=ctx)
        interpreter.called = arguments is not None
        ctx.run_data[RUN_INTERPRETER_KEY] = interpreter  # a later step runs a subprogram there (a lathe cycle's profile)
        interpreter.vacant_word = vacant_word
        if flattening:  # the run's output is written: a statement the switch may skip cannot be baked in
            interpreter.skip_refused = ("the program is flattened, which writes what the statement did, so the "
                                        "block delete switch could no longer skip it")
        closing = _closing_mark(body)
        last_was_mark = False
        try:
            for block in interpreter.run(start=len(prefix)):
                last_was_mark = "TapeMark" in block.sections
                yield block
        finally:  # a run ended (or given up) no longer stands anywhere a later step could run a subprogram or read
            # its parameters: after a trial run (``_check_runs``, ``_vacancy_reason``) the program may be kept as
            # written, and a step would then evaluate its words with the values that run ended with
            if ctx.run_data.get(RUN_INTERPRETER_KEY) is interpreter:
                del ctx.run_data[RUN_INTERPRETER_KEY]
            if ctx.run_data.get(RUN_VARIABLES_KEY) is variables:
                del ctx.run_data[RUN_VARIABLES_KEY]
        if closing is not None and not last_was_mark:
            yield closing  # the run ended at M30/M2: the tape closes as the source's did

    def _reread(self, kept: KeptLines, ctx: Context, first_line: int) -> list[Block]:
        """The kept prefix as fresh blocks (the streamed ones were changed by the later steps). Its
        errors were reported when it streamed, so they are not reported again."""
        if not kept:
            return []
        lines = [kept_line(item) for item in kept]
        blocks = self.read_lines(_physical(lines), ctx.file, ctx, _quiet())
        offset = first_line - 1
        for block in blocks:
            block.line += offset
        return blocks


def _closing_mark(body: list[Block]) -> Block | None:
    """The source's closing tape mark (a '%' line after the program, when one opened it too), which a run
    that ends at the program's end never reaches: a tape reader or rs274 ("percent sign missing from end
    of file") wants the written program closed as it was opened."""
    marks = [block for block in body if "TapeMark" in block.sections]
    last = next((block for block in reversed(body) if block.sections), None)
    if len(marks) < 2 or last is not marks[-1]:
        return None
    return last


def _physical(texts: list[str]) -> list[str]:
    """Block texts as the physical lines a reader takes: a continued block's text holds several (read as
    one line, its continuation was lost), split as the program file was (``ENCODING``: newline="");
    every other text is its line as it is (an empty one for a block without text)."""
    lines: list[str] = []
    for text in texts:
        body = text.rstrip("\r\n")
        if "\n" in body or "\r" in body:
            lines.extend(io.StringIO(text, newline=""))
        else:
            lines.append(text)
    return lines


def _quiet() -> Diagnostics:
    """Diagnostics for text read again: its errors and warnings were reported when it was first read."""
    return Diagnostics(ErrorLevel.IGNORE, warn_stream=io.StringIO())


def _sound(blocks: list[Block], check: StreamCheck) -> bool:
    """Show the check the rest of the program, and end it: True when the program is sound."""
    control, assign, start = CONTROL, ASSIGN, "ProgramStart"
    for block in blocks:
        sections = block.sections
        if control in sections or start in sections or assign in sections or (block.values and _computes(block)):
            check.see(block)
    return check.end()


def kept_line(item: Kept) -> str:
    """A kept item's text as a line (ending in its end of line)."""
    if item is None:
        return ""
    if isinstance(item, str):
        return item + "\n"
    return item[0] + item[1]


def _may_be_vacant(body: list[Block]) -> bool:
    """A word of ``body`` is a bare variable (vacant when unset), or it calls a subprogram that is not in
    it (a library program, whose words are not seen here)."""
    defined = set()
    for block in body:
        start = block.sections.get("ProgramStart")
        number = getattr(start, "number", None)
        if number is not None:
            defined.add(str(number))
    for block in body:
        for value in block.values.values():
            if isinstance(value, Var):
                return True
        control = block.sections.get(CONTROL)
        if isinstance(control, (Call, ModalCall)) and (not isinstance(control.name, str) or control.name not in defined):
            return True
    return False


def _number(section: object) -> int:
    """A ``Sequence`` section's block number."""
    if isinstance(section, Sequence):
        return section.number  # (compiled: a field read, not a look-up by name)
    number: int = getattr(section, "number")
    return number


def _computes(block: Block) -> bool:
    for value in block.values.values():
        if isinstance(value, Expr):
            return True
    return False


def _format(pattern: str, name: str) -> str:
    bare = name[1:-1] if name.startswith("<") and name.endswith(">") else name
    number = int(bare) if bare.isdigit() else 0
    return pattern.format(name=bare, number=number, raw=name)
