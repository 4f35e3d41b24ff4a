"""``SemicolonCommentWriter``: the word writer of a controller whose comments are ``;`` to the end of the
block and whose parentheses are no comment (Fagor 8070, SINUMERIK: their dialects' ``COMMENTS``). Every
comment it writes (a comment section, a source block commented out under ``--on-unsupported warn``, a
block that means nothing to the target) is one ``;`` comment on the block's one line, its text's white space
folded to single spaces (a line break would end it)."""

from __future__ import annotations

from ..ir import Block
from .writer import WordWriter


class SemicolonCommentWriter(WordWriter):
    """``WordWriter`` with ``;`` comments (see the module)."""

    def comment(self, text: str) -> str:
        return ";" + " ".join(text.splitlines())

    def comment_out(self, block: Block) -> str:
        return f";UNSUPPORTED LINE {block.line}: {_source_text(block)}" + (block.eol or "\n")

    def nothing_written(self, block: Block) -> str:
        super().nothing_written(block)  # the warning
        return f";LINE {block.line}: {_source_text(block)}" + (block.eol or "\n")


def _source_text(block: Block) -> str:
    """The source block's text (else its words) on one line, its white space folded."""
    return " ".join((block.text or " ".join(a + n for a, n in block.words)).split())
