"""A backplot's points, kept on disk so memory stays flat however long the program.

A picture is scaled to the extent of the whole path, and each view draws rapids and feeds as separate
layers, so the points are read once per view and kind of move after the toolpath has gone past. Asking
the toolpath again would mean running the program again (standard input cannot be read twice, and
``verify`` sees two programs at once); a flat spill file, written once and read in order, costs
25-28 bytes of disk per point and one chunk of memory.
"""

from __future__ import annotations

import math
import struct
import tempfile
from array import array
from typing import BinaryIO, Iterator

from ..errors import UsageError

CHUNK = 16384
"""Points held in memory before they go to the spill file (about 450 kB); a path shorter than this
never touches the disk."""
_HEADER = struct.Struct("<Q")
"""Each spilled chunk: its point count, then the coordinates (three doubles a point), then the tags."""


class PointStore:
    """Points (x, y, z) with a 32-bit tag each, appended in order and read back chunk by chunk."""

    def __init__(self) -> None:
        self.xyz = array("d")
        """The points not yet spilled, three coordinates each."""
        self.tags = array("I")
        self.count = 0
        """Points appended so far."""
        self._file: BinaryIO | None = None
        self._lo = [math.inf] * 3
        self._hi = [-math.inf] * 3

    def append(self, point: tuple[float, float, float], tag: int) -> None:
        self.xyz.extend(point)
        self.tags.append(tag)
        self.count += 1
        if len(self.tags) >= CHUNK:
            self._spill()

    def bounds(self) -> tuple[float, float, float, float, float, float]:
        """(min x, max x, min y, max y, min z, max z) over every point; needs at least one."""
        lo, hi = list(self._lo), list(self._hi)
        if self.tags:
            _widen(lo, hi, self.xyz)
        return lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]

    def chunks(self) -> Iterator[tuple[array[float], array[int]]]:
        """Every point in order, as (coordinates, tags) chunks of at most ``CHUNK`` points."""
        if self._file is not None:
            f = self._file
            f.seek(0)
            while header := f.read(_HEADER.size):
                (n,) = _HEADER.unpack(header)
                xyz, tags = array("d"), array("I")
                xyz.frombytes(f.read(24 * n))
                tags.frombytes(f.read(tags.itemsize * n))
                yield xyz, tags
        if self.tags:
            yield self.xyz, self.tags

    def close(self) -> None:
        """Remove the spill file (it is unlinked from the start, so a crash leaves nothing behind)."""
        if self._file is not None:
            self._file.close()
            self._file = None

    def _spill(self) -> None:
        _widen(self._lo, self._hi, self.xyz)
        try:
            if self._file is None:
                self._file = tempfile.TemporaryFile(prefix="postproc-backplot-")
            f = self._file
            f.seek(0, 2)
            f.write(_HEADER.pack(len(self.tags)))
            f.write(self.xyz.tobytes())
            f.write(self.tags.tobytes())
        except OSError as exc:
            raise UsageError(f"cannot keep the backplot's points in a temporary file: {exc.strerror}") from None
        self.xyz, self.tags = array("d"), array("I")


def _widen(lo: list[float], hi: list[float], xyz: array[float]) -> None:
    """Stretch the running bounds over a chunk of points (as ``min``/``max`` of all of them would)."""
    for axis in range(3):
        values = xyz[axis::3]
        low, high = min(values), max(values)
        if low < lo[axis]:
            lo[axis] = low
        if high > hi[axis]:
            hi[axis] = high
