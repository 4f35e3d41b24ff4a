"""An arc carried by a linear map (``postproc.frames.carried_arc``), the one computation of a frame's evaluation and a
``--transform``: hand-derived images of an arc's centre offsets, radius and direction."""

from __future__ import annotations

import pytest

from postproc.frames.affine import Affine, diagonal, rotation
from postproc.frames.carried_arc import carried_arc
from postproc.ir import Motion
from postproc.ir.expr import Binary, Num, Var

END: dict[str, float | object] = {"X": 1.0, "Y": 2.0}


def _arc(m: Motion, fmap: Affine, plane: str = "XY") -> Motion:
    arc = carried_arc(fmap, plane, m, dict(END), str(m.mode))  # type: ignore[arg-type]
    assert arc is not None
    return arc


def test_a_quarter_turn_turns_the_centre_offsets_and_keeps_the_direction() -> None:
    # (I, J) = (3, 4) turned 90 degrees counter-clockwise: (-4, 3)
    arc = _arc(Motion("cw", {}, {"X": 3.0, "Y": 4.0}), Affine(rotation(("X", "Y"), 90.0)))
    assert (arc.mode, arc.center, arc.radius, arc.axes) == ("cw", {"X": -4.0, "Y": 3.0}, None, END)


def test_a_mirror_turns_the_direction_over() -> None:
    arc = _arc(Motion("ccw", {}, {"X": 3.0, "Y": 4.0}), Affine(diagonal((-1.0, 1.0, 1.0))))
    assert (arc.mode, arc.center) == ("cw", {"X": -3.0, "Y": 4.0})


def test_a_radius_is_scaled_by_the_factor_in_the_plane() -> None:
    arc = _arc(Motion("cw", {}, None, 5.0), Affine(diagonal((2.0, 2.0, 1.0))))
    assert (arc.mode, arc.center, arc.radius) == ("cw", None, 10.0)


def test_an_arc_in_the_zx_plane_turns_with_its_plane() -> None:
    # in ZX (first axis Z, second X) a rotation by 90 degrees takes (K, I) = (1, 0) to (0, 1)
    arc = _arc(Motion("ccw", {}, {"Z": 1.0, "X": 0.0}), Affine(rotation(("Z", "X"), 90.0)), "ZX")
    assert arc.center == {"Z": 0.0, "X": 1.0}


def test_a_computed_offset_stays_an_expression() -> None:
    arc = _arc(Motion("cw", {}, {"X": Var("#1"), "Y": 0.0}), Affine(diagonal((2.0, 2.0, 1.0))))
    assert arc.center == {"X": Binary("mul", Num(2.0), Var("#1")), "Y": 0.0}


@pytest.mark.parametrize("m", [diagonal((2.0, 1.0, 1.0)), rotation(("Y", "Z"), 30.0)])
def test_unequal_scaling_or_a_turn_out_of_the_plane_makes_no_arc(m: tuple[float, ...]) -> None:
    assert carried_arc(Affine(m), "XY", Motion("cw", {}, {"X": 1.0}), {}, "cw") is None  # type: ignore[arg-type]
