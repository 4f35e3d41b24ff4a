"""Words the frame evaluation's modules share (``postproc.frames.lowering``, ``postproc.frames.offset_changes``):
the linear axes, two refusals' wording, and the comment an evaluated command leaves behind."""

from __future__ import annotations

from typing import Final

from ..ir import Comments, Section

LINEAR: Final = frozenset("XYZUVW")
COMPUTED: Final = "a computed word under a coordinate frame (the frame is evaluated into the coordinates here)"
SYMBOLIC: Final = ("a coordinate frame in a program kept symbolically (it would be evaluated in the order of the "
                   "text, not of the run)")


def note(s: dict[str, Section], text: str) -> None:
    """An evaluated command stays in the output as a comment (no block vanishes without a trace)."""
    comments = s.get("Comments")
    s["Comments"] = Comments([*comments.texts, text] if isinstance(comments, Comments) else [text])
