"""The program store: what jumps, loops and calls need of a program, and nothing a straight program needs.

A ``Program`` is one file's blocks with their index: sequence numbers -> positions (jump targets),
loop heads <-> ends, if-chains, subprogram definitions. The ``ProgramStore`` holds the main program and
the library programs it loaded, lazily, by subprogram name.

Subprogram names (``postproc.interp.control``): the program number as decimal text (``"2000"``) or the o-word
name with its brackets (``"<probe>"``). A definition is either a ``SubStart`` ... ``SubEnd`` pair
(LinuxCNC; indexed wherever it stands in the file) or a ``ProgramStart`` after the main program's end
(Fanuc ``O2000`` after ``M30``: the body runs to its return, the next program start or a tape mark).
"""

from __future__ import annotations

from typing import Callable

from .control import CONTROL, LABEL
from ..errors import ProgramError
from ..ir import Block
from ..ir.source_map import locate
from .rules import STORED_PROGRAMS, SubprogramRules
from .structure import Structure, source_text

__all__ = ["Program", "ProgramStore", "source_text"]


class Program:
    """One file's blocks, indexed. ``main_end`` is the position after the main program's end block
    (``len(blocks)`` when it has none); blocks past it run only as subprograms."""

    __slots__ = ("file", "blocks", "sequence", "labels", "pairs", "chains", "flow_entries", "subs", "main_end",
                 "first_line", "ran")

    def __init__(self, file: str, blocks: list[Block], is_end: Callable[[Block], bool],
                 rules: SubprogramRules = STORED_PROGRAMS) -> None:
        self.file = file
        self.blocks = blocks
        self.sequence: dict[int, list[int]] = {}
        self.labels: dict[str, list[int]] = {}
        """Named jump label -> positions of the blocks carrying it."""
        self.pairs: dict[int, int] = {}
        """Loop head <-> end, and break/continue -> the head of their loop."""
        self.chains: dict[int, list[int]] = {}
        """Every member of an if-chain -> the chain's positions (if, elseifs, else, endif); a switch ->
        its cases and default, in order."""
        self.flow_entries: dict[int, int] = {}
        """Under a controller's flow stack (``SubprogramRules.flow_stack``): a loop's, condition's or call's
        position -> the entries its body holds in this program or sub (``Structure.entries``)."""
        self.subs: dict[str, tuple[int, int]] = {}
        """Subprogram name -> (position of its first body block, position after its last): an
        ``o<x> sub`` body includes its ``endsub`` (which may return a value); an ``O`` program's runs
        to the block before the next program start or tape mark."""
        self.main_end = len(blocks)
        self.first_line = blocks[0].line if blocks else 1
        self.ran = bytearray(len(blocks))
        """1 at the position of each block that has run (a block run again is work the interpreter counts)."""
        self._index(is_end, rules)

    def _error(self, block: Block, message: str) -> ProgramError:
        return ProgramError(message, locate(self.file, block))

    def _index(self, is_end: Callable[[Block], bool], rules: SubprogramRules) -> None:
        """Sequence numbers, labels and subprograms; the constructs through ``Structure`` (which
        refuses what is malformed)."""
        structure = Structure(self.file, rules, index=True)
        starts: list[tuple[str, int]] = []
        for pos, block in enumerate(self.blocks):
            sections = block.sections
            seq = sections.get("Sequence")
            if seq is not None:
                self.sequence.setdefault(seq.number, []).append(pos)  # type: ignore[attr-defined]
            label = sections.get(LABEL)
            if label is not None:
                self.labels.setdefault(label.name, []).append(pos)  # type: ignore[attr-defined]
            start = sections.get("ProgramStart")
            if start is not None:
                number, name = start.number, start.name  # type: ignore[attr-defined]
                if number is not None:
                    structure.program(number, block)
                if pos >= self.main_end:
                    starts.append((str(number) if number is not None else str(name), pos))
            if pos < self.main_end and is_end(block) and not structure.open:
                self.main_end = pos + 1
            control = sections.get(CONTROL)
            if control is not None:
                structure.statement(control, pos, block)
        structure.finish()
        self.pairs = structure.pairs
        self.chains = structure.chains
        self.flow_entries = structure.entries
        for name, (at, end) in structure.subs.items():
            self.subs[name] = (at + 1, end + 1)  # the body runs its endsub: ``o<x> endsub [v]`` returns v
        for i, (name, pos) in enumerate(starts):
            end = starts[i + 1][1] if i + 1 < len(starts) else len(self.blocks)
            for p in range(pos + 1, end):
                if "TapeMark" in self.blocks[p].sections:
                    end = p
                    break
            self.subs.setdefault(name, (pos + 1, end))

    def find_sequence(self, number: int, after: int) -> int | None:
        """Fanuc's search: the first block numbered ``number`` after ``after``, else the first one."""
        return _first_after(self.sequence.get(number), after)

    def find_label(self, name: str, after: int) -> int | None:
        """The first block labelled ``name`` after ``after``, else the first one."""
        return _first_after(self.labels.get(name), after)


def _first_after(positions: list[int] | None, after: int) -> int | None:
    if not positions:
        return None
    for p in positions:
        if p > after:
            return p
    return positions[0]


Loader = Callable[[str], "Program | None"]
"""Finds and reads the library file of a subprogram name, or None."""


class ProgramStore:
    """The main program and the library programs loaded so far, searched by subprogram name."""

    __slots__ = ("main", "library", "loader", "dropped", "kept_limit")

    def __init__(self, main: Program, loader: Loader, dropped: int = 0, kept_limit: int = 0) -> None:
        self.main = main
        self.dropped = dropped
        """Blocks at the start of the main program no longer held (beyond ``Limits.kept_prefix``)."""
        self.kept_limit = kept_limit
        self.library: dict[str, Program] = {}
        self.loader = loader

    def find(self, name: str) -> tuple[Program, int, int] | None:
        """(program, first body position, end position) of subprogram ``name``: the main program's own
        definitions first, then the library (a library file without a definition of that name is the
        subprogram as a whole)."""
        found = self.main.subs.get(name)
        if found is not None:
            return self.main, found[0], found[1]
        for program in self.library.values():
            found = program.subs.get(name)
            if found is not None:
                return program, found[0], found[1]
        loaded = self.library.get(name) or self.loader(name)
        if loaded is None:
            return None
        self.library[name] = loaded
        found = loaded.subs.get(name)
        if found is not None:
            return loaded, found[0], found[1]
        return loaded, 0, len(loaded.blocks)

    def held(self) -> int:
        """Blocks held in memory (the main program's and the loaded library's)."""
        return len(self.main.blocks) + sum(len(p.blocks) for p in self.library.values())
