"""One running program level of the interpreter: where it runs, how it was called, what it repeats."""

from __future__ import annotations

from ..ir.expr import Value
from ..ir import Block
from ..ir.source_map import CallSite, Origin
from .store import Program


class Frame:
    """One running program level: where it runs, how it was called, what it repeats."""

    __slots__ = ("program", "pc", "end", "origin", "new_level", "call_block", "remaining", "index", "count",
                 "args", "start", "repeats", "modal", "site", "needs_return", "fors", "seen", "back", "flow")

    def __init__(self, program: Program, start: int, end: int, origin: Origin | None, new_level: bool,
                 call_block: Block | None, index: int, count: int, args: dict[int, Value], modal: bool,
                 site: CallSite | None) -> None:
        self.program = program
        self.start = start
        self.pc = start
        self.end = end
        self.origin = origin
        self.new_level = new_level
        self.call_block = call_block
        self.index = index
        self.count = count
        self.args = args
        self.repeats: dict[int, int] = {}
        self.fors: dict[int, tuple[float, float]] = {}
        """Position of a running counted loop -> its (end, step), evaluated when it was entered."""
        self.seen: dict[int, object] = {}
        """Position of a running loop's head (-1 - position of a return to the main program's start; the
        number of blocks + position of a jump back) -> what the program could read when its end (the return,
        the jump) last ran (``RunState._endless``)."""
        self.back = -1
        """The while loop whose end ran last, until its test runs (-1: none): the test then continues it."""
        self.modal = modal
        self.site = site
        self.flow = 0
        """Entries of the controller's flow stack its callers hold, its call among them (``Program.flow_entries``)."""
        self.needs_return = False
        """The body ends only at a return (LinuxCNC's ``O<n>`` ... ``M99``): running off its end is an error."""
