"""A lathe tool's nose: the imaginary tool nose direction (the tip number of the offset register) as a
direction in the ZX plane. Under G41/G42 the compensation (``cutter_radius``) runs the nose centre one nose
radius beside the programmed path; the point the tool offsets measure, and the machine therefore
positions, is the imaginary tool tip: the nose centre moved by the radius in the tip's direction.

Numbers are Fanuc's, as the set-up's ``<Tool tip>`` gives them: the direction from the nose centre to
the imaginary tip [K: Haas lathe operator's manual, "Imaginary Tool Tip and Direction": 1 X+ Z+, 2 X+ Z-,
3 X- Z-, 4 X- Z+, 5 Z+, 6 X+, 7 Z-, 8 X-, 0 and 9 the centre itself; [?] Fanuc T and GSK number them
alike (their manuals' figures, not read here)]. LinuxCNC numbers the same eight directions with X
mirrored (its drawing looks at a front tool post, X+ down): its orientation 2 is Fanuc's 3 [V: LinuxCNC
``interp_queue.cc`` ``latheorigin_x``/``latheorigin_z``: 1, 2, 6 put the origin at X-r; 3, 4, 8 at X+r;
2, 3, 7 at Z-r; 1, 4, 5 at Z+r; and rs274 2.9 run here].
"""

from __future__ import annotations

from ..errors import ProgramError

TIPS: dict[int, tuple[int, int]] = {
    0: (0, 0), 1: (1, 1), 2: (-1, 1), 3: (-1, -1), 4: (1, -1),
    5: (1, 0), 6: (0, 1), 7: (-1, 0), 8: (0, -1), 9: (0, 0),
}
"""Fanuc tip number -> (Z, X) direction from the nose centre to the imaginary tip (signs)."""

MIRRORED: dict[int, int] = {0: 0, 1: 4, 2: 3, 3: 2, 4: 1, 5: 5, 6: 8, 7: 7, 8: 6, 9: 9}
"""Fanuc's tip number <-> the number of the same direction with X mirrored (LinuxCNC's orientation); its
own inverse."""


def tip_offset(tip: int, radius: float) -> tuple[float, float]:
    """(Z, X) from the nose centre to the imaginary tip of a nose of ``radius`` (mm, positive)."""
    direction = TIPS.get(tip)
    if direction is None:
        raise ProgramError(f"tool nose direction {tip} is not one of 0-9")
    return direction[0] * radius, direction[1] * radius


def mirrored(tip: int) -> int:
    """The number of the same direction in the numbering with X mirrored (Fanuc <-> LinuxCNC)."""
    if tip not in MIRRORED:
        raise ProgramError(f"tool nose direction {tip} is not one of 0-9")
    return MIRRORED[tip]
