"""What the frame evaluator's helper modules (``commands``, ``offset_changes``) use of it, as a protocol: they
take the evaluator (``postproc.frames.lowering.FrameEvaluator``) without importing its module, which imports
them (no circle of imports)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from ..context import Context
    from ..ir.state import ModalState
    from .frame import Frame, Position
    from .run_state import FrameRun


class Evaluation(Protocol):
    """The evaluator where the program stands: its run, frame, position and modal state."""

    ctx: Context
    modal: ModalState
    reached: FrameRun
    frame: Frame | None
    p: Position
    scale: float
    g5x: dict[int, dict[str, float]]

    def frame_for(self, rules: str) -> Frame:
        """The frame in force, made with ``rules`` at the first frame command."""
