"""LinuxCNC's active comments, which do something when the program runs: ``(MSG,text)`` shows the operator
a message, ``(DEBUG,..)`` and ``(PRINT,..)`` print text with parameter values, ``(LOG..)`` write a log
file, ``(PROBEOPEN ..)``/``(PROBECLOSE)`` record probe points, ``(ABORT,..)`` stops the program and
``(PY,..)`` runs Python. ``COMMENTS`` is LinuxCNC's comment syntax with them (``postproc.syntaxes.comments``): a
comment written from another dialect, or a template's value, never makes one. Every other dialect reads them as inert
comments: a translation keeps their text and warns, naming each one with its location (once per source
comment, however often a loop runs it). Between LinuxCNC programs they are kept as they are.
"""

from __future__ import annotations

from postproc.syntaxes.comments import CommentSyntax
from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir import Block, Comments
from postproc.lowering.lower import BlockStep, LoweringStep

WORDS = ("MSG", "DEBUG", "PRINT", "LOGOPEN", "LOGAPPEND", "LOGCLOSE", "LOG", "PROBEOPEN", "PROBECLOSE", "ABORT", "PY")
"""The keywords LinuxCNC looks for at the start of a ``( )`` comment (in any case, after blanks, a whole word)
[V: rs274 of linuxcnc-uspace 2.9 acts on ``( MSG,`` ``(msg,`` ``(DEBUG,`` ``(PRINT,`` ``(LOG,`` ``(LOGOPEN,``
``(LOGAPPEND,`` ``(LOGCLOSE)``, ``(ABORT,`` (the program stops) and ``(PY,`` (embedded Python); K for
``PROBEOPEN``/``PROBECLOSE``, from the LinuxCNC G-code manual]. A ``;`` comment never acts [V]."""
COMMENTS = CommentSyntax(parens=True, nested=False, semicolon=True, active_words=WORDS)
"""``( )`` comments, which do not nest (rs274: "Nested comment found" [V]), and ``;`` to the end of the line
[V]; the active ones above."""


def semicolon_comment(comments: Comments) -> str | None:
    """A LinuxCNC line's ``;`` comment (the last of its comments: ``Comments.semicolon``) as a ``;`` comment, to end
    the line the writer writes from its words (a generated block's comments are its last words, ``SECTION_ORDER``; a
    normalised one's too); None where the line has none. rs274 acts on the last ``( )`` comment of a line only and
    never on a ``;`` one [V: rs274 2.9 run here: ``G1 X2 (msg, two) (note)`` shows no message, ``G1 X2 (msg, kept)
    ; note`` shows it, ``G1 X1. ( msg, hello)`` shows " hello", ``G1 X1 ; msg, hello`` nothing]: written in
    parentheses, as it was by ``--normalize``, ``--renumber``, ``--units`` or ``--transform``, the ``;`` comment
    became the one that acts, silencing the line's message or showing its own."""
    texts = comments.texts
    if not comments.semicolon or not texts:
        return None
    return ";" + texts[-1]


LOST = {
    "MSG": "the operator no longer sees the message",
    "DEBUG": "its text is no longer printed",
    "PRINT": "its text is no longer printed",
    "LOG": "nothing is logged",
    "LOGOPEN": "no log file is opened",
    "LOGAPPEND": "no log file is opened",
    "LOGCLOSE": "no log file is closed",
    "PROBEOPEN": "probe points are no longer recorded",
    "PROBECLOSE": "probe points are no longer recorded",
    "ABORT": "the program no longer aborts here",
    "PY": "its Python no longer runs",
}
"""What the operator loses when the comment becomes inert."""


class WarnActiveComments(LoweringStep):
    """A generic lowering step (it must see every translation from LinuxCNC, whatever the target), taking the blocks
    one at a time in the run's loop (``postproc.lowering.lower.run_blocks``): as a generator of its own it cost every
    LinuxCNC block read for another target (``verify``'s of each translation to LinuxCNC) a resumption in Python."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect != "linuxcnc" or target.NAME == "linuxcnc":
            return None
        return _Warn(ctx, target.NAME)


warn_active_comments = WarnActiveComments()


class _Warn(BlockStep):
    """Warns of each active comment once per source comment (a loop runs one several times)."""

    def __init__(self, ctx: Context, target: str) -> None:
        super().__init__()
        self.moves = False  # a block that is only a move has no comment
        self.ctx = ctx
        self.target = target
        self.warned: set[tuple[int, int]] = set()

    def take(self, block: Block) -> list[Block] | None:
        comments = block.sections.get("Comments")
        if comments is None:
            return None
        ctx, warned, rule = self.ctx, self.warned, COMMENTS.rule
        for text in comments.texts:  # type: ignore[attr-defined]
            head = rule.head(text)
            if head is None:
                continue
            col = block.text.find("(" + text + ")") + 1 if block.text is not None else 1
            if col < 1 or (block.line, col) in warned:
                continue  # a ';' comment: not active (a block the program computed has no text: column 1)
            warned.add((block.line, col))
            key = head.upper()
            lost = LOST[key]
            if key in ("DEBUG", "PRINT") and "#" in text:
                lost = "the parameter values it prints are lost"
            ctx.diagnostics.warn(f"LinuxCNC active comment ({key},...) is an inert comment in {self.target}: {lost}",
                                 ctx.at(block, col))
        return None
