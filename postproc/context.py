"""The run's context: what every step of one run shares, and word columns for error locations.

What a step offers the run's speed-only shortcuts is here too (``BlockLane``, ``HoleLane``): a step that
reads one way (the block syntax, the cycle resolver) asks the lane the run installed (``postproc.fast``)
first and reads the block itself when the lane answers no; it knows only these two interfaces, and
compiled each is a direct method call on every block.
"""

from __future__ import annotations

import abc
import re
from typing import Any, Callable, Final, Mapping

from mypy_extensions import mypyc_attr

from .geometry.arc_end import NEUTRAL_ARC_END, ArcEndRule
from .cycle_words import CycleWords
from .errors import Diagnostics, Location
from .ir import Block
from .setup.machine_setup import MachineSetup
from .ir.move_words import MoveWords
from .ir.source_map import locate
from .ir.state import ModalState


NOT_SET: Any = object()
"""A ``Context`` attribute a step has not initialised yet."""


ASSUMED_START: Final = "simulation.assumed_start"
"""``Context.run_data`` key, set by a simulation (``postproc.simulate.toolpath``): the run models a machine that
starts where the set-up says, so a read of the current position before the program places an axis is that
start, as the simulated moves assume (``postproc.frames.parameters``); a translation leaves it unset (the
machine's own point is unknown to it)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class BlockLane(abc.ABC):
    """Reads the commonest blocks of a word block syntax, as its general path reads them."""

    __slots__ = ()

    @abc.abstractmethod
    def read(self, block: Block, ctx: Context, words: list[tuple[str, str]]) -> bool:
        """Give ``block`` its sections and return True, or return False leaving it as it was (the step
        then reads it)."""

    def read_marked(self, block: Block, ctx: Context) -> bool:
        """``read`` of a block whose words the reader left unmade (``Block.marks``), from its line: False
        here (the step then reads its words)."""
        return False


@mypyc_attr(allow_interpreted_subclasses=True)
class HoleLane(abc.ABC):
    """Resolves a block that moves an active hole cycle to its next hole, as the cycle resolver does."""

    __slots__ = ()

    @abc.abstractmethod
    def repeat(self, block: Block, ctx: Context) -> bool:
        """Resolve ``block`` and return True, or return False leaving it as it was (the resolver then
        resolves it from its words and calls ``resolved``)."""

    @abc.abstractmethod
    def resolved(self, block: Block, ctx: Context) -> None:
        """The resolver resolved ``block`` from its words (after ``repeat`` said False)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Context:
    """What every step of one run shares: file name, set-up, diagnostics, modal state, and what the
    reading dialect tells the neutral steps about its words."""

    __slots__ = ("file", "setup", "diagnostics", "state", "dialect", "cycle_words", "on_unsupported",
                 "program_mode", "keep_check", "reader", "stops_before_motion", "feed_before_units", "cutter_rules", "length_at_axis", "path_at_start", "lathe_turret",
                 "run_data",
                 "point_mix", "lathe", "increments", "axis_words", "diameter", "one_block", "peck_clearance_mm", "moves_made",
                 "block_lane", "hole_lane", "arc_end", "move_words", "frame_run")

    def __init__(self, file: str, setup: MachineSetup, diagnostics: Diagnostics, dialect: str,
                 cycle_words: CycleWords | None = None) -> None:
        self.file = file
        self.setup = setup
        self.diagnostics = diagnostics
        self.state = ModalState()
        self.dialect = dialect
        self.cycle_words = cycle_words
        """The reading dialect's hole-cycle letters and names (None: it reads no canned cycles)."""
        self.on_unsupported = "error"
        """'error' or 'warn': what a construct the target cannot express does."""
        self.program_mode = "keep"
        """What the interpreter step does with a program that computes: 'keep' its constructs (for a
        target that has them) or 'execute' them (toolpath, verify, flattening), or 'auto': keep them when
        ``keep_check`` finds nothing the target cannot express, else execute them; see ``postproc.interp``."""
        self.reader: Callable[["Context"], Any] | None = None
        """The reading dialect's reader class (``Reader``), for steps that read more text (a library
        subprogram, a jumped-back prefix) the way the program was read."""
        self.stops_before_motion = True
        """Whether the reading dialect flags stops it makes before the motion (``Dialect.STOPS_BEFORE_MOTION``;
        True unless the dialect says otherwise, so a step never skips flags it was not told are absent)."""
        self.feed_before_units = False
        """An F in a block that changes units is in the old units (``Dialect.FEED_BEFORE_UNITS``)."""
        self.length_at_axis = False
        """A tool length change moves nothing until the length axis is next programmed absolutely
        (``Dialect.LENGTH_AT_PROGRAMMED_AXIS`` of the reading dialect)."""
        self.path_at_start = "cutting"
        """The path control mode in force before the program sets one (``Dialect.PATH_CONTROL_AT_START``)."""
        self.lathe_turret = True
        """On a lathe the reading dialect's T indexes the turret with its offset (``Dialect.LATHE_TURRET``)."""
        self.cutter_rules: Any = None
        """The reading dialect's cutter compensation rules (``Dialect.CUTTER_RULES``; None: not modelled)."""
        self.arc_end: ArcEndRule = NEUTRAL_ARC_END
        """How far the reading controller lets an I/J/K arc end off its circle, and the path it then runs
        (``Dialect.ARC_END``, ``postproc.geometry.arc_end``)."""
        self.point_mix: Any = NOT_SET
        """A reading step's tracker of words written with and without a decimal point
        (``postproc.rs274.point_mix``): ``NOT_SET`` until it starts, None once it has nothing left to look
        for (a slot, not ``run_data``: the hot path tests it on every block)."""
        self.run_data: dict[str, Any] = {}
        """What a reading step keeps between the blocks of one run besides the modal state (its own key:
        a resolved table, what it has already warned about)."""
        self.peck_clearance_mm: float | None = None
        """The reading dialect's fixed G73 retract and G83 clearance in mm (``Dialect.PECK_CLEARANCE_MM``);
        None: the set-up's ``<Cycles peckRetract peckClearance>``."""
        self.lathe = False
        """The program is read with lathe meanings (``Dialect.reads_lathe``): G70-G76 lathe cycles, G98/G99
        feed modes, the ZX plane at start, the dialect's ``increments``."""
        self.increments: Mapping[str, str] = {}
        """Addresses that move an axis by an increment whatever the distance mode -> that axis
        (``Dialect.INCREMENTAL_AXES`` on a lathe: ``U`` -> ``X``); empty on a mill."""
        self.axis_words: frozenset[str] = frozenset(setup.machine.axes)
        """The set-up's axes (``<Machine axes>``): a move may program these and their increments
        (``increments``). The simulator refuses any other (``postproc.simulate.moves``); the modal-state
        step refuses it at reading, so ``translate`` never writes a word the machine has no axis for."""
        self.diameter = False
        """Lathe X words (and the increments of X) are diameters (the set-up's ``xProgramming`` on a dialect that has it)."""
        self.one_block = False
        """Lathe cycles G71-G73/G76 are read in their one-block form (the set-up's ``latheCycleFormat`` on
        a dialect that has it)."""
        self.moves_made = 0
        """Moves the expansions of this run have made: each step that bounds a block's moves by
        ``<Limits movesPerBlock>`` adds its count, and the interpreter charges those of the blocks it
        runs again to its work bound (``Limits.executed_blocks``)."""
        self.keep_check: Callable[[list[Block]], str | None] | None = None
        """For 'auto': given the program from its first construct on, the reason it cannot be kept
        symbolically for the target (None: it can)."""
        self.block_lane: BlockLane | None = None
        """The run's plain-block lane (``postproc.fast.reading``): the block syntax offers it a block first."""
        self.hole_lane: HoleLane | None = None
        """The run's next-hole lane (``postproc.fast.reading``): the cycle resolver offers it a block that
        repeats the active cycle first."""
        self.move_words = MoveWords()
        """The run's reader of a plain move's X, Y and Z (``postproc.ir.move_words``): one for the reading's modal
        state and the lowering steps that follow the point, so the second reader of a move finds it read. A slot,
        not ``run_data``: found on every block (a look-up by key there cost ~140 instructions a block compiled)."""
        self.frame_run: object | None = None
        """What the frame evaluation has reached (``postproc.frames.run_state.FrameRun``, made by its first step;
        None: no evaluation runs): the frame and the program position, which the frame parameters a program
        reads are read from, and a translation's dry run starts from (``postproc.api`` copies it). A slot, not
        ``state.extra``: that stays empty in most runs, so a step's test of it on every block finds nothing."""

    def at(self, block: Block, col: int = 1) -> Location:
        """Where ``block`` (column ``col``) is, through the source map: the one way to locate a block."""
        return locate(self.file, block, col)

    def word_at(self, block: Block, letter: str | None) -> Location:
        """Where ``block``'s first word with ``letter`` is (None: the block's start)."""
        return self.at(block) if letter is None else self.at(block, self.column_of(block, letter))

    def column_of(self, block: Block, letter: str, number: str | None = None, nth: int = 1) -> int:
        """Column of the ``nth`` word with ``letter`` (and, if given, exactly that number text) in the
        block's text, comments skipped. Computed only when reporting an error."""
        want = letter.upper()
        for col, found, num in word_columns(block.text or ""):
            if found.upper() == want and (number is None or num == number):
                nth -= 1
                if nth == 0:
                    return col
        return 1


DROPPED_MOVES: Final = "dropped_moves"
"""``Context.run_data`` key: the blocks whose moves a lowering step dropped with ``--on-unsupported warn``
(written as comments), which the writer then treats as displacing what follows (``postproc.output.displacement``)."""

# A pattern text, not a compiled pattern: compiled where first used (``re``'s cache), so a start that
# reports no error compiles none (each ``re.compile`` at import costs every start ~0.3-1M instructions).
_WORD_AT: Final = r"([A-Za-z:])[ \t]*([-+]?(?:\d+\.?\d*|\.\d+))"
_COMMENT_AT: Final = r"\([^()]*\)|\([^()]*$|;.*$"


def word_columns(text: str) -> list[tuple[int, str, str]]:
    """(1-based column, letter, number text) of every word outside comments."""
    masked = re.sub(_COMMENT_AT, lambda m: " " * len(m.group(0)), text)
    return [(m.start() + 1, m.group(1), m.group(2)) for m in re.finditer(_WORD_AT, masked)]
