"""The program's frame on output: ``%`` lines and the main program's number, as the set-up's
``<Output tapeMarks programNumber>`` ask (a lowering step; by default it changes nothing and costs no
step per block).

A controller that stores programs by number needs one (Fanuc ``O1001``), a tape reader or a DNC link
wants the program between ``%`` lines, and a controller without them (grbl) must get neither. Whether a
dialect has them is its ``TAPE_MARKS`` and ``PROGRAM_NUMBERS``; asking a dialect for what it lacks is
an error of the set-up, found before any block is written.
"""

from __future__ import annotations

from itertools import chain
from typing import Iterable, Iterator

from ..context import Context
from ..dialect import Dialect
from ..errors import ConfigError, Location
from ..ir import Block, Comments, ProgramStart, TapeMark


def frame_program(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    out = ctx.setup.output
    marks, number = out.tape_marks, out.program_number
    if not target.LEADER_TITLE:
        blocks = _title_as_comment(blocks)
    if marks == "keep" and number == "keep":
        return blocks
    where = Location(ctx.setup.source or "<set-up>", 1, 1)
    if marks == "always" and not target.TAPE_MARKS:
        raise ConfigError(f"<Output tapeMarks=\"always\">: the {target.NAME} dialect has no % lines", where)
    if isinstance(number, int) and not target.PROGRAM_NUMBERS:
        raise ConfigError(f"<Output programNumber=\"{number}\">: the {target.NAME} dialect writes no program "
                          "number", where)
    return _framed(blocks, marks, number)


def _framed(blocks: Iterator[Block], marks: str, number: str | int) -> Iterator[Block]:
    opened = False  # a block other than a tape mark went by
    numbered = number == "keep"  # the main program's number is settled
    last: Block | None = None
    for block in blocks:
        sections = block.sections
        if "TapeMark" in sections:
            if marks == "never":
                title = getattr(sections["TapeMark"], "title", None)
                if title is not None:  # the % line goes, its title stays (``_title_as_comment``)
                    yield _comment(block.line, title, block.eol)
                continue
            if marks == "always" and opened and last is not None and "TapeMark" in last.sections:
                continue  # one closing mark
        elif not opened:
            opened = True
            if marks == "always" and last is None:
                yield _line(block.line, TapeMark())
        if not numbered and "TapeMark" not in sections:
            numbered = True
            if "ProgramStart" in sections:
                block = _renumbered(block, number)
            elif isinstance(number, int):
                yield _line(block.line, ProgramStart(number))
        if block.sections:
            last = block
            yield block
    if marks == "always" and (last is None or "TapeMark" not in last.sections or not opened):
        yield _line(last.line if last is not None else 1, TapeMark())


def _title_as_comment(blocks: Iterator[Block]) -> Iterator[Block]:
    """The title of the program's opening ``%`` line (``TapeMark.title``) as a comment line after it, for a
    target whose control does not skip text on its ``%`` line (LinuxCNC refuses ``%O1200(TOKARKA)``: "Bad
    character '%' used" [V: rs274 run here]; the other targets' rules are not at hand [?]): never dropped.
    Only the blocks up to the first that holds anything are looked at, when the run reaches them (a chain
    after them: no step per block)."""
    return chain.from_iterable(_opening_then_rest(blocks))


def _opening_then_rest(blocks: Iterator[Block]) -> Iterator[Iterable[Block]]:
    head: list[Block] = []
    for block in blocks:
        head.append(block)
        if block.sections:
            title = getattr(block.sections.get("TapeMark"), "title", None)
            if title is not None:
                head[-1] = _line(block.line, TapeMark(), block.eol)
                head.append(_comment(block.line, title, block.eol))
            break
    yield head
    yield blocks


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
