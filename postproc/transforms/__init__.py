"""Program transforms the user asks for (issue #27): ``--units mm|inch`` and ``--transform``.

``spec`` reads the transform text into one affine map (``postproc.frames.affine``), ``carry`` moves every
point of a program through it, ``units`` converts every length, ``apply`` runs them on a translation's
lowered blocks; ``postproc.simulate.verify`` compares an output against its source's toolpath moved by the
same map.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .apply import ProgramOptions, program_options, transform_program

if TYPE_CHECKING:
    from .spec import ProgramTransform, parse_transform

__all__ = ["ProgramOptions", "ProgramTransform", "parse_transform", "program_options", "transform_program"]


def __getattr__(name: str) -> Any:
    """``ProgramTransform`` and ``parse_transform``, from ``spec`` when first read: a translation that moves
    nothing (``--transform`` not given) does not import the transform's reading."""
    if name in ("ProgramTransform", "parse_transform"):
        from . import spec
        return getattr(spec, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
