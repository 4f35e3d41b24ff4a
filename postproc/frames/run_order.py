"""Where a program kept symbolically runs a frame command in the order of its text.

A program kept symbolically (its loops, jumps and calls written for a target that has them) runs in another
order than its text, and the frame evaluation (``postproc.frames.lowering``) reads the text. A frame command
is still evaluated exactly there when it runs once, where the text has it: outside every construct (no loop
repeats it, no branch skips it, no subprogram holds it) and over no jump (no forward jump pending across it,
no jump back to a target before it), and after no call and no subprogram's text (a subprogram's text is
evaluated where the text has it, under the frame standing there: a frame command after a call, or after a
subprogram's text, would stand in another order in the run). ``RunOrder`` follows the constructs, jumps and
calls of the symbolic part and says which frame command is such; a jump back found after a frame command it
crosses is an error there (the translation's dry run then flattens the program). A jump whose target has not
gone by is taken as forward (its target is pending until a block carries it); one to a target before the
symbolic part (in the part that streamed before the first construct) is not seen here.
"""

from __future__ import annotations

from ..interp.control import (
    Call, Do, DoWhile, EndFor, EndIf, EndRepeat, EndSwitch, EndWhile, For, Goto, GotoLabel, If, ModalCall, Repeat,
    SubEnd, SubStart, Switch, Until, While,
)
from ..errors import ProgramError
from ..ir.expr import Num
from ..ir import Section

_OPENING = (If, While, Do, For, Repeat, Switch, SubStart)
_CLOSING = (EndIf, EndWhile, DoWhile, Until, EndFor, EndRepeat, EndSwitch, SubEnd)
_CALLING = (Call, ModalCall, SubStart)


class RunOrder:
    """The constructs open and the jumps pending in the symbolic part, and the frame commands it ran."""

    __slots__ = ("depth", "pending", "seen", "commands", "called")

    def __init__(self) -> None:
        self.depth = 0
        """Constructs open (loops, conditions, subprogram definitions)."""
        self.pending: dict[str, int] = {}
        """Target of a forward jump -> how many jumps wait for it."""
        self.seen: dict[str, int] = {}
        """Target that went by -> how many frame commands had run then."""
        self.commands = 0
        """Frame commands evaluated in the symbolic part."""
        self.called = False
        """A call, or a subprogram's text, went by in the symbolic part: a frame command after it is refused (a
        subprogram's moves are evaluated where its text stands, under the frame there: the frame of its calls only
        while no frame command comes after either). A G52, G68 or G51 set in an ``M98`` subprogram stays in force
        after its ``M99`` [K: modal codes, Fanuc 0i-MF operator's manual]: evaluated in the text's order, the moves
        after the call came before the subprogram's text and went out unshifted (tests/test_frames_in_calls.py)."""

    def target(self, names: list[str]) -> None:
        """A block carrying the jump targets ``names`` (its label, ``N<number>``)."""
        for name in names:
            self.pending.pop(name, None)
            self.seen[name] = self.commands

    def subprogram(self) -> None:
        """A program's start (a Fanuc ``O`` number) in the symbolic part: a subprogram's text (``called``)."""
        self.called = True

    def control(self, section: Section, symbolic_error: str, plain: bool = True) -> None:
        """A control statement: constructs open and close, a jump waits for its target or goes back, a call or a
        subprogram's definition is noted (``called``). A call while the evaluated frame is not plain is refused:
        the subprogram it runs may not stand in this program's text (a library's, ``--lib``: kept as a call, it
        would run on the target without the frame evaluated here; ``tests/test_frames_in_calls.py``)."""
        if isinstance(section, _CALLING):
            if not plain and isinstance(section, (Call, ModalCall)):
                raise ProgramError(f"{symbolic_error}: a call while the frame is on")
            self.called = True
        if isinstance(section, _OPENING):
            self.depth += 1
        elif isinstance(section, _CLOSING):
            self.depth = max(0, self.depth - 1)
        elif isinstance(section, (Goto, GotoLabel)):
            key = _key(section)
            if key is None:  # a computed target: it may be anywhere
                self.pending["?"] = self.pending.get("?", 0) + 1
                return
            before = self.seen.get(key)
            if before is not None and before < self.commands:
                raise ProgramError(f"{symbolic_error}: a jump back over a frame command, which runs again")
            if before is None or key.startswith("N"):  # a block number may also be carried further on
                self.pending[key] = self.pending.get(key, 0) + 1

    def command(self, symbolic_error: str) -> None:
        """A frame command: refused unless it runs once, where the text has it."""
        if self.depth or self.pending or self.called:
            raise ProgramError(symbolic_error)
        self.commands += 1


def _key(section: Goto | GotoLabel) -> str | None:
    if isinstance(section, GotoLabel):
        return section.label
    target = section.target
    if isinstance(target, Num) and target.value.is_integer():
        return f"N{int(target.value)}"
    return None
