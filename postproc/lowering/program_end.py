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

from typing import Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..interp.control import CONTROL, SubEnd, SubStart, Return
from ..dialect import Dialect
from ..ir import Block, Comments, Section, one_line
from .lower import BlockStep, LoweringStep

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


@mypyc_attr(allow_interpreted_subclasses=True)
class CommentAfterEnd(LoweringStep):
    """Lowering step (see the module docstring): ``comment_after_end``. With ``keep_numbered`` False,
    ``comment_numbered_subs_after_end``: for a target that reads only its own form of subprogram (grblHAL's
    ``o100 sub``), a numbered definition (``O2000`` .. ``M99``) still after the end once the target's own
    steps ran (none called it) is written as comments, as any other code there."""

    def __init__(self, keep_numbered: bool) -> None:
        self.keep_numbered = keep_numbered

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if target.NAME == ctx.dialect:
            return None
        return _AfterEnd(ctx, target.PROGRAMS, self.keep_numbered)


comment_after_end = CommentAfterEnd(True)
comment_numbered_subs_after_end = CommentAfterEnd(False)


@mypyc_attr(allow_interpreted_subclasses=True)
class _AfterEnd(BlockStep):
    """One run: before the end it only follows the program (a move once the program has started is none
    of its business); after it, every block is."""

    def __init__(self, ctx: Context, keep_subs: bool, keep_numbered: bool) -> None:
        super().__init__()
        self.ctx = ctx
        self.keep_subs = keep_subs
        self.keep_numbered = keep_numbered
        self.tracker = EndTracker()
        self.started = False
        self.ended = False
        self.warned = False
        self.numbered = False
        """The definition being read opened with a program number (``O2000``), not the target's own form."""

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        tracker = self.tracker
        if not self.ended:  # before the end: kept cheap, every block of the program passes here
            if "ProgramControl" in sections or "TapeMark" in sections:
                tracker.started = self.started
                tracker.before_end(sections)
                if tracker.ended:
                    self.ended = True
                    self.moves = True
                else:
                    self.started = tracker.started
                    self.moves = not self.started
                return None
            if sections:
                self.started = True
                self.moves = False
            return None
        kind = tracker.after_end(sections)
        if kind == "sub" and ("ProgramStart" in sections or isinstance(sections.get(CONTROL), SubStart)):
            self.numbered = "ProgramStart" in sections
        if kind == "inert" or (kind == "sub" and self.keep_subs and (self.keep_numbered or not self.numbered)):
            return None
        ctx = self.ctx
        if not self.warned:
            ctx.diagnostics.warn("blocks after the program end are written as comments (a controller that is "
                                 "streamed to would run them)", ctx.at(block))
            self.warned = True
        text = one_line(block.text or " ".join(a + n for a, n in block.words)).strip()
        block.sections = {"Comments": Comments([f"AFTER PROGRAM END, LINE {block.line}: {text}"])}
        block.changed()
        return None
