"""What follows a program's end (M02/M30, or a closing ``%``): never live code in another dialect.

A controller that reads a whole file stops at the end; one that is streamed to (grbl) runs whatever
comes next. So when translating to another dialect, the blocks after the end are written as comments
(with one warning), except subprogram definitions (a Fanuc ``O2000`` ... ``M99``, a LinuxCNC
``o<name> sub`` ... ``endsub``) when the target runs subprograms itself (``Dialect.PROGRAMS``) and reads
that form of definition (``comment_numbered_subs_after_end``: grblHAL reads no ``O2000``).
Back to the same dialect nothing changes: the target reads the end as the source does.

``EndTracker`` is the one rule, shared by the ``comment_after_end`` lowering step and the simulator
(``postproc.simulate.toolpath``), which records the live blocks it does not run there, so ``verify`` can
compare them.
"""

from __future__ import annotations

from typing import Iterator, Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..control import CONTROL, SubEnd, SubStart, Return
from ..dialect import Dialect
from ..ir import Block, Comments, Section, one_line

ENDS: Final = frozenset(("end", "end_rewind"))
"""``ProgramControl`` kinds that end the program."""
INERT: Final = frozenset(("Comments", "TapeMark", "Sequence", "BlockDelete"))
"""Sections that do nothing on a machine: a block of only these is not live code."""


@mypyc_attr(allow_interpreted_subclasses=True)
class EndTracker:
    """Follows a block stream: where the program ends, and what each block after the end is."""

    __slots__ = ("ended", "started", "in_sub")

    def __init__(self) -> None:
        self.ended = False
        self.started = False
        """A block with content has been seen (so a ``%`` now closes the program)."""
        self.in_sub = False
        """Inside a subprogram definition after the end."""

    def before_end(self, sections: dict[str, Section]) -> bool:
        """True while the program runs (this block is before the end, or is the end itself)."""
        if self.ended:
            return False
        if "TapeMark" in sections:
            if self.started:
                self.ended = True
            return True
        if sections:
            self.started = True
            control = sections.get("ProgramControl")
            if control is not None and control.kind in ENDS:  # type: ignore[attr-defined]
                self.ended = True
        return True

    def after_end(self, sections: dict[str, Section]) -> str:
        """What a block after the end is: "inert" (nothing a machine does), "sub" (part of a subprogram
        definition) or "live" (code a streaming controller would run)."""
        control = sections.get(CONTROL)
        if "ProgramStart" in sections or isinstance(control, SubStart):
            self.in_sub = True
            return "sub"
        if self.in_sub:
            if isinstance(control, (SubEnd, Return)):
                self.in_sub = False
            return "sub"
        if sections.keys() <= INERT:
            return "inert"
        return "live"


def comment_after_end(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step (see the module docstring)."""
    if target.NAME == ctx.dialect:
        return blocks
    return _comment_after_end(blocks, ctx, target.PROGRAMS, True)


def comment_numbered_subs_after_end(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step for a target that reads only its own form of subprogram (grblHAL's ``o100 sub``): a
    numbered definition (``O2000`` .. ``M99``) still after the end once the target's own steps ran (none
    called it) is written as comments, as any other code there."""
    if target.NAME == ctx.dialect:
        return blocks
    return _comment_after_end(blocks, ctx, target.PROGRAMS, False)


def _comment_after_end(blocks: Iterator[Block], ctx: Context, keep_subs: bool,
                       keep_numbered: bool) -> Iterator[Block]:
    tracker = EndTracker()
    started = False
    for block in blocks:  # before the end: kept cheap, every block of the program passes here
        sections = block.sections
        if "ProgramControl" in sections or "TapeMark" in sections:
            tracker.started = started
            tracker.before_end(sections)
            yield block
            if tracker.ended:
                break
            started = tracker.started
            continue
        if sections:
            started = True
        yield block
    warned = False
    numbered = False
    """The definition being read opened with a program number (``O2000``), not the target's own form."""
    for block in blocks:
        sections = block.sections
        kind = tracker.after_end(sections)
        if kind == "sub" and ("ProgramStart" in sections or isinstance(sections.get(CONTROL), SubStart)):
            numbered = "ProgramStart" in sections
        if kind == "inert" or (kind == "sub" and keep_subs and (keep_numbered or not numbered)):
            yield block
            continue
        if not warned:
            ctx.diagnostics.warn("blocks after the program end are written as comments (a controller that is "
                                 "streamed to would run them)", ctx.at(block))
            warned = True
        text = one_line(block.text or " ".join(a + n for a, n in block.words)).strip()
        block.sections = {"Comments": Comments([f"AFTER PROGRAM END, LINE {block.line}: {text}"])}
        block.changed()
        yield block
