"""A progress bar on standard error while a long program streams through a command.

Shown only where a person watches: standard error is a terminal and the input is a regular file of at
least ``MIN_BYTES`` (a short program is done before a bar could say anything; a pipe has no known
length). The bar counts characters read against the file's size, is redrawn at most every
``INTERVAL`` seconds, and is erased before a warning is printed and when the command ends, so what stays
on the screen is only what the command says.
"""

from __future__ import annotations

import os
import sys
import time
from typing import Iterable, Iterator, TextIO

MIN_BYTES = 1 << 20
"""Inputs shorter than this (about 50,000 blocks) get no bar."""
INTERVAL = 0.2
"""Seconds between redraws."""
WIDTH = 30


class Progress:
    """Counts the lines of one input and draws ``postproc: NAME [#####-----]  42% 123,456 lines``."""

    def __init__(self, name: str, size: int, stream: TextIO) -> None:
        self.name = name
        self.size = max(size, 1)
        self.stream = stream
        self.shown = False
        self._next = 0.0

    def lines(self, lines: Iterable[str]) -> Iterator[str]:
        """Pass ``lines`` through, redrawing the bar as they go; erase it when they end."""
        done = 0
        count = 0
        clock = time.monotonic
        try:
            for line in lines:
                done += len(line)
                count += 1
                if count & 1023 == 0 and clock() >= self._next:
                    self.draw(done, count)
                    self._next = clock() + INTERVAL
                yield line
        finally:
            self.clear()

    def draw(self, done: int, count: int) -> None:
        fraction = min(done / self.size, 1.0)
        filled = int(fraction * WIDTH)
        bar = "#" * filled + "-" * (WIDTH - filled)
        self.stream.write(f"\rpostproc: {self.name} [{bar}] {fraction:4.0%} {count:,} lines")
        self.stream.flush()
        self.shown = True

    def clear(self) -> None:
        if self.shown:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.shown = False


class AboveProgress:
    """A text stream for warnings that erases the bar before each write (the bar is redrawn later)."""

    def __init__(self, progress: Progress, stream: TextIO) -> None:
        self.progress = progress
        self.stream = stream

    def write(self, text: str) -> int:
        self.progress.clear()
        return self.stream.write(text)

    def flush(self) -> None:
        self.stream.flush()


def progress_for(path: str, stream: TextIO | None = None) -> Progress | None:
    """A bar for reading ``path``, or None where none is shown (see the module docstring)."""
    stream = stream if stream is not None else sys.stderr
    if path == "-" or not stream.isatty():
        return None
    try:
        size = os.stat(path).st_size
    except OSError:
        return None
    if size < MIN_BYTES:
        return None
    return Progress(os.path.basename(path), size, stream)
