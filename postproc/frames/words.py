"""Words the frame evaluation's modules share (``postproc.frames.lowering``, ``postproc.frames.offset_changes``):
the linear axes, refusals' wording, a command's axis words, and the comment an evaluated command leaves
behind."""

from __future__ import annotations

from typing import Final

from ..ir import AXES, Comments, Section

LINEAR: Final = frozenset("XYZUVW")
COMPUTED: Final = "a computed word under a coordinate frame (the frame is evaluated into the coordinates here)"
SYMBOLIC: Final = ("a coordinate frame in a program kept symbolically (it would be evaluated in the order of the "
                   "text, not of the run)")
LAYERED_FORBIDDEN: Final = "{what} while coordinate rotation, scaling or a mirror image is on cannot be run"
"""[K] Fanuc 0i-MF and Siemens' ISO-dialect manual 3.2: no reference return and no coordinate system command
(local, machine or work coordinates, coordinate setting) in these modes."""
SWAPPED: Final = {"left": "right", "right": "left"}
"""Cutter compensation's side under a mirror of one axis."""


def axes_of(words: dict[str, float]) -> dict[str, float]:
    """The axis words of a frame command's words."""
    return {k: v for k, v in words.items() if k in AXES}


def note(s: dict[str, Section], text: str) -> None:
    """An evaluated command stays in the output as a comment (no block vanishes without a trace)."""
    comments = s.get("Comments")
    s["Comments"] = Comments([*comments.texts, text] if isinstance(comments, Comments) else [text])
