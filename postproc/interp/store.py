"""The program store: what jumps, loops and calls need of a program, and nothing a straight program needs.

A ``Program`` is one file's blocks with their index: sequence numbers -> positions (jump targets),
loop heads <-> ends, if-chains, subprogram definitions. The ``ProgramStore`` holds the main program and
the library programs it loaded, lazily, by subprogram name.

Subprogram names (``postproc.control``): the program number as decimal text (``"2000"``) or the o-word
name with its brackets (``"<probe>"``). A definition is either a ``SubStart`` ... ``SubEnd`` pair
(LinuxCNC; indexed wherever it stands in the file) or a ``ProgramStart`` after the main program's end
(Fanuc ``O2000`` after ``M30``: the body runs to its return, the next program start or a tape mark).
"""

from __future__ import annotations

from typing import Callable

from ..control import (
    CONTROL, LABEL, Break, Case, Continue, Default, Do, DoWhile, Else, ElseIf, EndFor, EndIf, EndRepeat, EndSwitch,
    EndWhile, For, If, Repeat, SubEnd, SubStart, Switch, Until, While,
)
from ..errors import ProgramError
from ..ir import Block, Section, one_line
from ..source_map import locate

_HEADS: dict[type[Section], type[Section]] = {EndWhile: While, DoWhile: Do, EndRepeat: Repeat, EndFor: For,
                                              Until: Do}
"""Each loop end and the head it closes."""
_LOOPS = (While, Do, Repeat, For)


def source_text(block: Block) -> str:
    """The construct as written, for messages (or the block's words when it has no text)."""
    text = one_line(block.text) if block.text is not None else " ".join(a + n for a, n in block.words)
    return text.strip() or type(block.get(CONTROL)).__name__


class Program:
    """One file's blocks, indexed. ``main_end`` is the position after the main program's end block
    (``len(blocks)`` when it has none); blocks past it run only as subprograms."""

    __slots__ = ("file", "blocks", "sequence", "labels", "pairs", "chains", "subs", "main_end", "first_line")

    def __init__(self, file: str, blocks: list[Block], is_end: Callable[[Block], bool]) -> None:
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
        self.subs: dict[str, tuple[int, int]] = {}
        """Subprogram name -> (position of its first body block, position after its last): an
        ``o<x> sub`` body includes its ``endsub`` (which may return a value); an ``O`` program's runs
        to the block before the next program start or tape mark."""
        self.main_end = len(blocks)
        self.first_line = blocks[0].line if blocks else 1
        self._index(is_end)

    def _error(self, block: Block, message: str) -> ProgramError:
        return ProgramError(message, locate(self.file, block))

    def _index(self, is_end: Callable[[Block], bool]) -> None:
        stack: list[tuple[Section, int]] = []
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
            if start is not None and pos >= self.main_end:
                number, name = start.number, start.name  # type: ignore[attr-defined]
                starts.append((str(number) if number is not None else str(name), pos))
            if pos < self.main_end and is_end(block) and not stack:
                self.main_end = pos + 1
            control = sections.get(CONTROL)
            if control is not None:
                self._statement(control, pos, block, stack)
        if stack:
            section, pos = stack[-1]
            raise self._error(self.blocks[pos], f"'{source_text(self.blocks[pos])}' is never closed")
        for i, (name, pos) in enumerate(starts):
            end = starts[i + 1][1] if i + 1 < len(starts) else len(self.blocks)
            for p in range(pos + 1, end):
                if "TapeMark" in self.blocks[p].sections:
                    end = p
                    break
            self.subs.setdefault(name, (pos + 1, end))

    def _statement(self, control: Section, pos: int, block: Block, stack: list[tuple[Section, int]]) -> None:
        if isinstance(control, (*_LOOPS, If, SubStart, Switch)):
            stack.append((control, pos))
            if isinstance(control, (If, Switch)):
                self.chains[pos] = [pos]
            return
        kind = type(control)
        if kind in _HEADS:
            head, at = self._close(stack, _HEADS[kind], control.label, block)  # type: ignore[attr-defined]
            self.pairs[at] = pos
            self.pairs[pos] = at
        elif kind in (ElseIf, Else, EndIf):
            _, at = self._close(stack, If, control.label, block, pop=kind is EndIf)  # type: ignore[attr-defined]
            chain = self.chains[at]
            if kind is not EndIf and isinstance(self.blocks[chain[-1]].get(CONTROL), Else):
                raise self._error(block, f"'{source_text(block)}' after the else branch")
            chain.append(pos)
            self.chains[pos] = chain
        elif kind in (Case, Default, EndSwitch):
            _, at = self._close(stack, Switch, control.label, block, pop=kind is EndSwitch)  # type: ignore[attr-defined]
            chain = self.chains[at]
            if kind is EndSwitch:
                self.pairs[at] = pos
                self.pairs[pos] = at
                return
            if kind is Case and isinstance(self.blocks[chain[-1]].get(CONTROL), Default):
                raise self._error(block, f"'{source_text(block)}' after the default branch")
            chain.append(pos)
        elif kind in (Break, Continue):
            label = control.label  # type: ignore[attr-defined]
            heads = (*_LOOPS, Switch) if kind is Break else _LOOPS
            for section, at in reversed(stack):
                if isinstance(section, heads) and section.label == label:
                    self.pairs[pos] = at
                    return
            raise self._error(block, f"'{source_text(block)}' is not inside loop {label}")
        elif kind is SubEnd:
            _, at = self._close(stack, SubStart, control.name, block)  # type: ignore[attr-defined]
            name = control.name  # type: ignore[attr-defined]
            if name in self.subs:
                raise self._error(self.blocks[at], f"subprogram {name} is defined twice")
            self.subs[name] = (at + 1, pos + 1)  # the body runs its endsub: ``o<x> endsub [v]`` returns v
            self.pairs[at] = pos

    def _close(self, stack: list[tuple[Section, int]], head: type[Section], label: str, block: Block,
               pop: bool = True) -> tuple[Section, int]:
        if stack:
            section, at = stack[-1]
            name = getattr(section, "label", getattr(section, "name", None))
            if isinstance(section, head) and name == label:
                if pop:
                    stack.pop()
                return section, at
        raise self._error(block, f"'{source_text(block)}' does not close an open {head.__name__} {label}")

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
