"""Coordinate frames (issue #27): local offsets, G92 origins, rotation, scaling and mirror images.

``section`` holds the IR node (``FrameChange``), ``affine`` the maps, ``frame`` the frame in force and
each command's rule, ``reading`` how an RS274-family reader makes the node, and ``lowering`` the step
that keeps the commands for their own dialect or evaluates them into every point (the simulation
included).
"""

from __future__ import annotations

from .lowering import evaluate_frames
from .section import FrameChange, register_frames

__all__ = ["FrameChange", "evaluate_frames", "register_frames"]
