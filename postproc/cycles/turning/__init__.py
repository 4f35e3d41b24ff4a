"""Exact lathe cycle geometry (G70-G76, G90/G92/G94) as pure functions of radius coordinates.

One module per cycle; each function takes the start point (x, z) and the cycle's words already
resolved to absolute radius values, and returns the ``TurnMove`` list the controller makes, ending
where the controller ends the cycle. Errors are ``ProgramError`` without a location (the caller
locates them). The dialect layer reads the words; nothing here spells a code or names a dialect's
parameter storage.
"""

from __future__ import annotations

from .finishing import finishing
from .groove import groove
from .pattern_repeat import pattern_repeat
from .peck_face import peck_face
from .profile import Seg, TurnMove
from .rough_facing import rough_facing
from .rough_turning import rough_turning
from .single_facing import single_facing
from .single_threading import single_threading
from .single_turning import single_turning
from .threading import thread_depths, threading

__all__ = ["Seg", "TurnMove", "finishing", "groove", "pattern_repeat", "peck_face", "rough_facing", "rough_turning",
           "single_facing", "single_threading", "single_turning", "thread_depths", "threading"]
