"""Lowering: pure IR-to-IR transforms chosen from the target dialect's capabilities.

Each transform is a generator over blocks named with a verb (``expand_canned_cycles``, ...). It runs
only where the target lacks a feature, as sqlglot's ``preprocess`` does for SQL dialects.
"""

from __future__ import annotations

from typing import Callable, Iterator

from .dialect import Dialect
from .ir import Block
from .context import Context

Transform = Callable[[Iterator[Block], Context, type[Dialect]], Iterator[Block]]

TRANSFORMS: list[Transform] = []
"""Registered lowering transforms, applied in order; each decides from the target what to do."""


def register_transform(transform: Transform) -> Transform:
    if transform not in TRANSFORMS:
        TRANSFORMS.append(transform)
    return transform


def lower_for(blocks: Iterator[Block], ctx: Context, target: type[Dialect], on_unsupported: str) -> Iterator[Block]:
    """Apply every registered transform the target needs."""
    ctx.on_unsupported = on_unsupported
    stream = blocks
    for transform in TRANSFORMS:
        stream = transform(stream, ctx, target)
    return stream
