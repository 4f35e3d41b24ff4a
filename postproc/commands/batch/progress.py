"""The batch's progress bar on standard error: files done, blocks/s, and the time left.

Drawn only when standard error is a terminal, redrawn at most every ``INTERVAL`` seconds, erased before
each message and at the end (as the single-file bar, ``postproc.commands.progress``). The time left is
estimated from bytes, not files: one large program among small ones would make a count of files lie.
"""

from __future__ import annotations

import time
from typing import Callable, TextIO

from ..progress import INTERVAL, WIDTH


class BatchProgress:
    """``postproc: [#####-----] 1,234/10,000 files  56,789 blocks/s  ETA 0:42``."""

    def __init__(self, files: int, total_bytes: int, stream: TextIO,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.files = files
        self.total_bytes = max(total_bytes, 1)
        self.stream = stream
        self.clock = clock
        self.started = clock()
        self.shown = False
        self._next = 0.0
        self.done = self.blocks = self.bytes = 0

    def advance(self, files: int, blocks: int, size: int) -> None:
        """Count finished files; redraw if the last drawing is old enough."""
        self.done += files
        self.blocks += blocks
        self.bytes += size
        now = self.clock()
        if now >= self._next:
            self.draw(now)
            self._next = now + INTERVAL

    def line(self, now: float) -> str:
        elapsed = max(now - self.started, 1e-9)
        fraction = min(self.bytes / self.total_bytes, 1.0)
        filled = int(fraction * WIDTH)
        bar = "#" * filled + "-" * (WIDTH - filled)
        eta = _clock_time(elapsed * (1 - fraction) / fraction) if fraction > 0 else "-:--"
        return (f"postproc: [{bar}] {self.done:,}/{self.files:,} files  {self.blocks / elapsed:,.0f} blocks/s  "
                f"ETA {eta}")

    def draw(self, now: float | None = None) -> None:
        self.stream.write("\r\033[K" + self.line(self.clock() if now is None else now))
        self.stream.flush()
        self.shown = True

    def message(self, text: str) -> None:
        """Print a line above the bar (the bar comes back at the next redraw)."""
        self.clear()
        self.stream.write(text + "\n")
        self.stream.flush()
        self._next = 0.0

    def clear(self) -> None:
        if self.shown:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.shown = False


class Messages:
    """Where a batch without a bar prints: standard error, line by line."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream

    def advance(self, files: int, blocks: int, size: int) -> None:
        pass

    def message(self, text: str) -> None:
        self.stream.write(text + "\n")

    def clear(self) -> None:
        self.stream.flush()


def _clock_time(seconds: float) -> str:
    """``0:42``, ``12:05``, ``3:02:10``."""
    whole = int(seconds + 0.5)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02}:{secs:02}" if hours else f"{minutes}:{secs:02}"


def progress_for(files: int, total_bytes: int, stream: TextIO) -> BatchProgress | Messages:
    """A bar where a person watches (``stream`` is a terminal), plain messages otherwise."""
    return BatchProgress(files, total_bytes, stream) if stream.isatty() else Messages(stream)
