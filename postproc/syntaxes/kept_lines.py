"""The streamed prefix of a program kept for a later backward jump (``Limits.kept_prefix`` lines, the last
ones): ``ProgramSyntax`` appends every line it streams and rereads them when a construct comes.

A ``deque(maxlen=...)`` of the lines held one string object each: about 90 bytes a line, 9 MB for the
default 100,000 lines, per program (``verify`` runs two: most of its peak memory beyond start-up). Here full
chunks of plain lines are joined into one string (a line's own length plus one), and split again only when
they are read back, which happens once, when the program first computes. Lines with an end other than
``\\n``, without text, or holding a ``\\n`` stay as they are, in a chunk of their own kind.
"""

from __future__ import annotations

from typing import Final, Iterator, Union, cast

from mypy_extensions import mypyc_attr

Kept = Union[str, tuple[str, str], None]
"""A streamed line: its text (ending in ``\\n``), its text and another end of line, or None (no text)."""

CHUNK: Final = 256
"""Lines a chunk holds before it is joined."""


@mypyc_attr(allow_interpreted_subclasses=True)
class KeptLines:
    """The last ``maxlen`` lines appended, oldest first (``len``, iteration and ``reversed`` as a deque's)."""

    def __init__(self, maxlen: int) -> None:
        self.maxlen = maxlen
        self.chunks: list[str | list[Kept]] = []
        """Full chunks, oldest first: one joined string of ``CHUNK`` plain lines, or a list."""
        self.open: list[Kept] = []
        """The chunk being filled."""
        self.skip = 0
        """Lines of the oldest chunk already dropped (beyond ``maxlen``)."""
        self.size = 0
        self.plain = True
        """The open chunk holds plain lines only (strings without a ``\\n``), told as each is appended."""

    def append(self, item: Kept) -> None:
        if self.maxlen <= 0:
            return
        lines = self.open
        lines.append(item)
        # A line is told plain as it comes (the string just read, a search of a few dozen characters): not by a
        # pass over the chunk's items and a count of the separators of the joined chunk as it is closed (~500
        # instructions a line, callgrind), which met each line again long after it was read.
        if self.plain and (not isinstance(item, str) or "\n" in item):
            self.plain = False
        self.size += 1
        if len(lines) == CHUNK:
            self._close()
        if self.size > self.maxlen:
            self._drop_oldest()

    def _close(self) -> None:
        lines = self.open
        self.open = []
        self.chunks.append("\n".join(cast("list[str]", lines)) if self.plain else lines)
        self.plain = True

    def _drop_oldest(self) -> None:
        self.size -= 1
        if not self.chunks:
            del self.open[0]
            return
        self.skip += 1
        if self.skip == CHUNK:
            del self.chunks[0]
            self.skip = 0

    def __len__(self) -> int:
        return self.size

    def __bool__(self) -> bool:
        return self.size > 0

    def _lines(self) -> list[Kept]:
        out: list[Kept] = []
        for chunk in self.chunks:
            if isinstance(chunk, str):
                out.extend(chunk.split("\n"))
            else:
                out.extend(chunk)
        out.extend(self.open)
        return out[self.skip:]

    def __iter__(self) -> Iterator[Kept]:
        return iter(self._lines())

    def __reversed__(self) -> Iterator[Kept]:
        return reversed(self._lines())
