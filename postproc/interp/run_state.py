"""The interpreter's run state and its bookkeeping (``postproc.interp.machine`` runs the statements on
it): the frames and bounds of one run (loop iterations, repeated work, call depth), the values of call
arguments and counts, and where an error is located. Kept apart from the statement dispatch so that each
module has one job."""

from __future__ import annotations

from .control import ModalCall
from ..errors import Location, PostprocError, ProgramError
from .evaluation import evaluate, evaluate_number
from ..ir.expr import EvalError, Expr, Value
from ..ir import Block
from ..setup.machine_setup import Limits
from .frame import Frame
from .host import NO_MOVES, Host, Interrupt, MoveCount, Reporter
from .rules import STORED_PROGRAMS, SubprogramRules
from .fixed_condition import condition_is_fixed
from .store import Program, ProgramStore, source_text
from .variables import Snapshots, Variables


def is_number(text: str) -> bool:
    """A word's text is a plain number (not an expression the interpreter evaluates)."""
    try:
        float(text)
    except ValueError:
        return False
    return True


class RunState:
    """One run of a program store: its frames, the bounds it spends, and the located failure that stops it."""

    def __init__(self, store: ProgramStore, host: Host, variables: Variables, limits: Limits,
                 report: Reporter, annotate: bool = False, rules: SubprogramRules | None = None,
                 counts: MoveCount | None = None) -> None:
        self.store = store
        self.host = host
        self.vars = variables
        self.limits = limits
        self.report = report
        self.annotate = annotate
        self.budget = limits.loop_iterations
        self.work = limits.repeated_work
        """Blocks and moves left to run again (``Limits.repeated_work``)."""
        self.counts: MoveCount = counts if counts is not None else NO_MOVES
        self.moves_seen = 0
        """``counts.moves_made`` when the interpreter last looked."""
        self.again = False
        """The block run last had run before: the moves made since are repeated work."""
        self.repeated: tuple[Frame, Block, str] | None = None
        """The last repetition spent (frame, block, what): the one the work bound names."""
        self.frames: list[Frame] = []
        self.modal: tuple[ModalCall, dict[int, Value], int, Block] | None = None
        self.ended = False
        self.rules = rules or STORED_PROGRAMS
        self.called = False
        """The main program runs as a called macro (``--arg``): its plain return ends the run instead of
        going back to its start."""
        self.found: dict[tuple[str, str], int] = {}
        """(file, program number) -> position of the ``O`` block an ``M98`` found (forward search)."""
        self.skip_refused: str | None = None
        """Set: a statement under block delete (``/``) is an error with this explanation: a flattened program
        bakes in what the statement did, so the operator's switch could no longer skip it."""
        self.snapshots: Snapshots | None = variables if isinstance(variables, Snapshots) else None
        """The variables, where they can say all a program reads of them at once (``_endless``)."""
        self.fixed_conditions: dict[tuple[int, int], bool] = {}
        """(id of a program, position of a loop's head) -> whether its test can never change (``_fixed``)."""
        self.vacant_word: str | None = None
        """Set: a word whose value is vacant is an error with this explanation instead of being omitted (the
        check run of a program kept symbolically for a target that would not omit it)."""


    def _fail(self, err: PostprocError, frame: Frame, block: Block, col: int) -> None:
        if err.location is None:
            err.location = self._where(frame, block, col)
        self.report(err)
        raise Interrupt()

    def _where(self, frame: Frame, block: Block, col: int = 1) -> Location:
        origin = frame.origin
        if origin is None:
            return Location(frame.program.file, block.line, col)
        return Location(origin.file, block.line, col, origin.note())

    # -- values ----------------------------------------------------------------------------------
    def _args(self, args: dict[int, Expr]) -> dict[int, Value]:
        limit = self.host.MACRO_LOCALS
        values: dict[int, Value] = {}
        for n, expr in args.items():
            if not 1 <= n <= limit:
                raise ProgramError(f"argument #{n} is outside the locals #1-#{limit}")
            values[n] = evaluate(expr, self.vars)
        return values

    def _name(self, name: str | Expr) -> str:
        if isinstance(name, str):
            return name
        return str(self._integer(name, "the subprogram number"))

    def _integer(self, expr: Expr, what: str) -> int:
        value = evaluate_number(expr, self.vars, what)
        if not value.is_integer():
            raise EvalError(f"{what} must be an integer, {value:g} is not")
        return int(value)

    def _count(self, expr: Expr, what: str) -> int:
        value = self._integer(expr, what)
        if value < 0:
            raise EvalError(f"{what} cannot be negative ({value})")
        return value

    def _out_of_work(self, frame: Frame, block: Block) -> None:
        """Report the work bound (``Limits.repeated_work``), located at the repetition that ran last."""
        n = self.limits.repeated_work
        if self.repeated is not None:
            frame, block, what = self.repeated
            named = f"{what} '{source_text(block)}'"
        else:  # nothing repeated yet: a guard (a block runs again only after a repetition)
            named = f"'{source_text(block)}'"
        self._fail(ProgramError(f"{named} repeats more than {n} blocks and moves in all (the set-up's bound on "
                                f"work run again, <Limits repeatedWork=\"{n}\"/>)"), frame, block, 1)

    def _endless(self, frame: Frame, key: int, block: Block, what: str) -> None:
        """A loop's end, a jump back or a return to the main program's start (``block``; ``key``: where it
        is kept in ``frame.seen``) runs with everything the program can read as when it ran last (the
        variables, the modal call, the frame's counted loops): the run is deterministic, so from here
        each repetition repeats the last and it never ends. Refused now rather than run to the work
        bound (a damaged loop that lost its counter took seconds to reach it)."""
        snapshots = self.snapshots
        if snapshots is None:
            return
        values = snapshots.snapshot()
        if values is None:
            return
        now = (values, self.modal, tuple(sorted(frame.repeats.items())), tuple(sorted(frame.fors.items())))
        if frame.seen.get(key) == now:
            raise ProgramError(f"{what} '{source_text(block)}' never ends: it runs again with every variable as "
                               "the time before, so nothing can change (does the program count its variable?)")
        frame.seen[key] = now

    def _fixed(self, frame: Frame, head: int, end: int, cond: Expr, block: Block) -> None:
        """A loop (blocks ``head`` .. ``end``) runs on because its test ``cond`` (in ``block``) holds: refuse
        it now if the test can never change and nothing in the loop leaves it (``fixed_condition``), rather
        than run it to the work bound (a loop counting a variable it never tests took ten seconds)."""
        snapshots = self.snapshots
        if snapshots is None or self.modal is not None:
            return  # a modal call in force runs a macro after each move
        key = (id(frame.program), head)
        fixed = self.fixed_conditions.get(key)
        if fixed is None:
            fixed = condition_is_fixed(frame.program, head, end, head, cond, snapshots.plain, self._may_end)
            self.fixed_conditions[key] = fixed
        if fixed:
            raise ProgramError(f"loop '{source_text(block)}' never ends: its test reads no variable the loop "
                               "sets and nothing in the loop leaves it (does the program count the variable it "
                               "tests?)")

    def _may_end(self, block: Block) -> bool:
        """The stored ``block`` ends the program, or may: a word of an end code's letter whose number is
        computed (every computed word of a letter that moves no axis, where the host names no end codes)."""
        if self.host.is_program_end(block):
            return True
        codes = getattr(self.host, "END_CODES", None)
        letters = None if codes is None else {letter.upper() for letter, _ in codes}
        values = block.values
        for letter, text in block.words:
            up = letter.upper()
            if isinstance(values.get(up), Expr) and not is_number(text) and (
                    up in letters if letters is not None else up not in self.host.AXIS_LETTERS):
                return True
        return False

    def _spend(self, block: Block, what: str, back: bool = True) -> None:
        """Count a repetition (``back``: it runs blocks again, so the work bound may name it; a jump
        forward skips blocks)."""
        if back:
            self.repeated = (self.frames[-1], block, what)
        self.budget -= 1
        if self.budget < 0:
            n = self.limits.loop_iterations
            raise ProgramError(f"{what} '{source_text(block)}' exceeds the set-up's bound of {n} loop iterations, "
                               f"jumps and calls in total (<Limits loopIterations=\"{n}\"/>)")

    def _within(self, frame: Frame, target: int, block: Block) -> None:
        """Refuse a jump past the end of the running program (the main program's M30, a subprogram's
        last block): the run here would end there silently, but a controller that keeps the blocks after
        the end (Fanuc searches its whole program for the number) runs on from the target, and a
        translation that comments them out (``postproc.lowering.program_end``) jumps nowhere. Where the
        dialect's rules say how its controller runs on (``SubprogramRules.jumps_past_end``), the main
        program's run takes in the blocks up to the next program in the file (or its end): it ends where a
        program end runs."""
        if target >= frame.end and self.rules.jumps_past_end and frame is self.frames[0] \
                and frame.program is self.store.main:
            frame.end = self._next_program(frame.program, target)
        if target >= frame.end:
            blocks = frame.program.blocks
            raise ProgramError(f"'{source_text(block)}' jumps to line {blocks[target].line}, past the end of the "
                               f"program at line {blocks[frame.end - 1].line}: where a controller runs from "
                               "there is not modelled")

    @staticmethod
    def _next_program(program: Program, after: int) -> int:
        """The position of the first program start or tape mark after ``after`` (``len(blocks)``: none)."""
        blocks = program.blocks
        for pos in range(after + 1, len(blocks)):
            sections = blocks[pos].sections
            if "ProgramStart" in sections or "TapeMark" in sections:
                return pos
        return len(blocks)

    def _missing_sequence(self, program: Program, number: int, text: str) -> str:
        message = f"'{text}': no block numbered {number} in {program.file}"
        dropped = self.store.dropped
        if program is self.store.main and dropped:
            n = self.store.kept_limit
            message += (f" after its first {dropped} blocks, which are not kept for jumps back (the set-up keeps "
                        f"the last {n}: <Limits keptPrefix=\"{n}\"/>)")
        return message

    # -- columns (computed only for errors) ------------------------------------------------------
    def _column(self, block: Block, err: EvalError) -> int:
        """The column of the first expression word of ``block`` (where an evaluation error most likely
        is), else 1."""
        for letter, text in block.words:
            if isinstance(block.values.get(letter.upper()), Expr) and not is_number(text):
                return self._word_column(block, letter, text)
        return 1

    @staticmethod
    def _word_column(block: Block, letter: str, text: str) -> int:
        source = block.text or ""
        i = source.find(letter + text)
        return i + 1 if i >= 0 else 1
