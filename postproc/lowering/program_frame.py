"""The program's frame on output: ``%`` lines and the main program's number, as the set-up's
``<Output tapeMarks programNumber>`` ask (a lowering step; by default it changes nothing and costs no
step per block).

A controller that stores programs by number needs one (Fanuc ``O1001``), a tape reader or a DNC link
wants the program between ``%`` lines, and a controller without them (grbl) must get neither. Whether a
dialect has them is its ``TAPE_MARKS`` and ``PROGRAM_NUMBERS``; asking a dialect for what it lacks is
an error of the set-up, found before any block is written.
"""

from __future__ import annotations

from ..context import Context
from ..dialect import Dialect
from ..errors import ConfigError, Location
from ..ir import Block, Comments, ProgramStart, TapeMark
from .lower import BlockStep, LoweringStep, Steps


class FrameProgram(LoweringStep):
    """Lowering step: the program's tape marks and number as the set-up's ``<Output>`` asks (the module
    docstring), and an opening ``%`` line's title as a comment where the target's control does not skip it."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        out = ctx.setup.output
        marks, number = out.tape_marks, out.program_number
        title = None if target.LEADER_TITLE else _TitleAsComment()
        if marks == "keep" and number == "keep":
            return title
        where = Location(ctx.setup.source or "<set-up>", 1, 1)
        if marks == "always" and not target.TAPE_MARKS:
            raise ConfigError(f"<Output tapeMarks=\"always\">: the {target.NAME} dialect has no % lines", where)
        if isinstance(number, int) and not target.PROGRAM_NUMBERS:
            raise ConfigError(f"<Output programNumber=\"{number}\">: the {target.NAME} dialect writes no program "
                              "number", where)
        framed = _Framed(marks, number)
        return framed if title is None else Steps([title, framed])


frame_program = FrameProgram()


class _Framed(BlockStep):
    """The tape marks and the program number asked for: every block is its business (a closing mark
    follows the last one)."""

    def __init__(self, marks: str, number: str | int) -> None:
        super().__init__()
        self.marks = marks
        self.number = number
        self.opened = False  # a block other than a tape mark went by
        self.numbered = number == "keep"  # the main program's number is settled
        self.last: Block | None = None

    def take(self, block: Block) -> list[Block] | None:
        marks, number = self.marks, self.number
        made: list[Block] = []
        sections = block.sections
        if "TapeMark" in sections:
            if marks == "never":
                title = getattr(sections["TapeMark"], "title", None)
                if title is not None:  # the % line goes, its title stays (``_TitleAsComment``)
                    made.append(_comment(block.line, title, block.eol))
                return made
            last = self.last
            if marks == "always" and self.opened and last is not None and "TapeMark" in last.sections:
                return made  # one closing mark
        elif not self.opened:
            self.opened = True
            if marks == "always" and self.last is None:
                made.append(_line(block.line, TapeMark()))
        if not self.numbered and "TapeMark" not in sections:
            self.numbered = True
            if "ProgramStart" in sections:
                block = _renumbered(block, number)
            elif isinstance(number, int):
                made.append(_line(block.line, ProgramStart(number)))
        if block.sections:
            self.last = block
            made.append(block)
        return made

    def finish(self) -> list[Block]:
        last = self.last
        if self.marks == "always" and (last is None or "TapeMark" not in last.sections or not self.opened):
            return [_line(last.line if last is not None else 1, TapeMark())]
        return []


class _TitleAsComment(BlockStep):
    """The title of the program's opening ``%`` line (``TapeMark.title``) as a comment line after it, for a
    target whose control does not skip text on its ``%`` line (LinuxCNC refuses ``%O1200(TOKARKA)``: "Bad
    character '%' used" [V: rs274 run here]; the other targets' rules are not at hand [?]): never dropped.
    Only the blocks up to the first that holds anything are looked at (held until it comes); after it,
    nothing is its business."""

    def __init__(self) -> None:
        super().__init__()
        self.head: list[Block] | None = []

    def take(self, block: Block) -> list[Block] | None:
        head = self.head
        if head is None:
            return None
        head.append(block)
        if not block.sections:
            return []
        title = getattr(block.sections.get("TapeMark"), "title", None)
        if title is not None:
            head[-1] = _line(block.line, TapeMark(), block.eol)
            head.append(_comment(block.line, title, block.eol))
        self.head = None
        self.moves = False
        self.passes = True  # (no block is its business any more)
        return head

    def finish(self) -> list[Block]:
        head = self.head
        self.head = None
        return [] if head is None else head


def _comment(line: int, text: str, eol: str) -> Block:
    block = Block(line, None, eol)
    block.add(Comments([text]))
    return block


def _renumbered(block: Block, number: str | int) -> Block:
    """The main program's own line with the number asked for (a name it had stays, for a writer that
    keeps it as a comment), or without it (its comment stays)."""
    block.changed()
    if number == "none":
        del block.sections["ProgramStart"]
    else:
        old = block.sections["ProgramStart"]
        block.sections["ProgramStart"] = ProgramStart(int(number), getattr(old, "name", None))
    return block


def _line(line: int, section: ProgramStart | TapeMark, eol: str = "\n") -> Block:
    block = Block(line, None, eol)
    block.add(section)
    return block
