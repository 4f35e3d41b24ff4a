"""The cyclic garbage collector paused for a stretch of work (``gc_paused``): one helper for the three places that
pause it. A streaming run makes blocks with no reference cycles (reference counting frees each one), and loading
the plugins or a command's modules only allocates what lives as long as the process; the collector's generation
scans during either walked everything made so far again and, measured here, outweighed the work itself
(``postproc.reading``, ``postproc.plugins``, ``postproc.commands.command_line`` say what each cost).

In the ground layer (the standard library only) so that every layer that pauses the collector can import it.
"""

from __future__ import annotations

import contextlib
import gc
from typing import Iterator


@contextlib.contextmanager
def gc_paused(*, freeze: bool = False) -> Iterator[None]:
    """Pause the cyclic collector while the block runs, and give it back as it was (a pause inside a pause leaves
    it off). ``freeze``: what the block made is frozen at the end (``gc.freeze``), so later collections in a
    process that goes on do not walk it (the command line's own process: ``command_line.FREEZE_IMPORTS``)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if freeze:
            gc.freeze()
        if enabled:
            gc.enable()
