"""A translation streams in bounded memory with the cyclic collector paused (``postproc.collector.gc_paused``):
that holds only if no block is caught in a reference cycle, which reference counting cannot free. A hole
cycle's lazy expansion once held the block that held it: memory grew with every drilling block (RSS +8 MB
per 900k CAM blocks). Counted here as the garbage the collector finds after a run: the same for 20 cycle
blocks as for 200."""

from __future__ import annotations

import gc
import io

import pytest

from postproc.api import translate

HEAD = "G21 G17 G90\nG0 X0. Y0. Z10.\n"


def _program(holes: int) -> str:
    rows = [f"G99 G83 X{i % 50}. Y{i // 50}. Z-5. R2. Q1. F100.\nG80\n" if i % 2 else
            f"G98 G81 X{i % 50}. Y{i // 50}. Z-3. R1. F120.\nG0 Z10.\n" for i in range(holes)]
    return HEAD + "".join(rows) + "G0 X0. Y0.\nG2 X5. Y0. I2.5 J0. F200.\nM30\n"


def _garbage_after(source: str, target: str, program: str) -> int:
    gc.collect()
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source=source, target=target)
        gc.set_debug(gc.DEBUG_SAVEALL)
        gc.collect()
        found = len(gc.garbage)
    finally:
        gc.set_debug(0)
        gc.garbage.clear()
        if was_enabled:
            gc.enable()
    return found


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_no_block_is_left_in_a_reference_cycle(target: str) -> None:
    _garbage_after("fanuc", target, _program(2))  # what a first run leaves once (lazy imports)
    small = _garbage_after("fanuc", target, _program(20))
    assert _garbage_after("fanuc", target, _program(200)) == small
