"""Lowering: pure IR-to-IR transforms chosen from the target dialect's capabilities.

Each step is a generator over blocks named with a verb (``expand_canned_cycles``, ...) that runs only
where the target lacks a feature, as sqlglot's ``preprocess`` does for SQL dialects. Two sources of
steps, applied in this order:

* generic steps, contributed by plugins through the ``postproc_register_lowerings`` hook (the core
  contributes ``expand_canned_cycles``); each decides from the target's capabilities what to do;
* the target dialect's own steps (``Dialect.LOWERING``): rewrites only that target needs, such as
  grbl's manual tool change, owned by the dialect that needs them.
"""

from __future__ import annotations

from typing import Callable, Iterator, Sequence

from ..context import Context
from ..dialect import Dialect
from ..ir import Block

Lowering = Callable[[Iterator[Block], Context, type[Dialect]], Iterator[Block]]
"""A lowering step: ``step(blocks, ctx, target)`` -> blocks, a pure block-stream transform."""
Transform = Lowering

TRANSFORMS: list[Lowering] = []
"""The generic steps of the default registry (``postproc.plugins.default_registry``), in order."""


def register_transform(transform: Lowering) -> Lowering:
    """Add a generic step to ``TRANSFORMS`` (idempotent)."""
    if transform not in TRANSFORMS:
        TRANSFORMS.append(transform)
    return transform


def lower_for(blocks: Iterator[Block], ctx: Context, target: type[Dialect], on_unsupported: str,
              steps: Sequence[Lowering] | None = None) -> Iterator[Block]:
    """Apply the generic steps (``steps``, by default the default registry's), then the target's own."""
    ctx.on_unsupported = on_unsupported
    stream = blocks
    for transform in TRANSFORMS if steps is None else steps:
        stream = transform(stream, ctx, target)
    for transform in target.LOWERING:
        stream = transform(stream, ctx, target)
    return stream
