"""Random arcs for the frame tests' random programs (``tests/test_isg_frames.py``, ``tests/test_siemens_frames.py``):
the draws that place an arc from where the tool stands, each dialect spelling the words itself. Exact where the
words are rounded: the radius form takes 1.05 to 3 times half the chord, the centre form ends on its circle."""

from __future__ import annotations

import math
import random


def radius_arc(rng: random.Random, x: int, y: int) -> tuple[int, int, float]:
    """An arc from (x, y) given by its radius: its end point (ahead in the second axis) and the radius."""
    ex, ey = x + rng.randint(-15, 15), y + rng.randint(1, 15)
    return ex, ey, math.hypot(ex - x, ey - y) / 2 * rng.uniform(1.05, 3.0)


def centre_arc(rng: random.Random, x: int, y: int) -> tuple[float, float, int, int]:
    """An arc from (x, y) about (x + i, y + j), turned 20 to 300 degrees: its end point, i and j."""
    i, j = rng.randint(-9, 9) or 3, rng.randint(-9, 9)
    turn = math.radians(rng.uniform(20, 300))
    ex = x + i - i * math.cos(turn) + j * math.sin(turn)
    ey = y + j - i * math.sin(turn) - j * math.cos(turn)
    return ex, ey, i, j
