"""LinuxCNC's writer of a lathe program: the RS274/NGC lathe words (``postproc.rs274.ngc_lathe_writer``: the
mode line, G96 with its clamp, G33 with K, each rule checked with rs274 2.9) on LinuxCNC's writer. Its own class
(``Linuxcnc.writer_class``), so a mill program keeps the fast lane.
"""

from __future__ import annotations

from postproc.rs274.ngc_lathe_writer import NgcLatheWriting, feed_apart

from .writer import LinuxcncWriter

__all__ = ["LinuxcncLatheWriter", "feed_apart"]


class LinuxcncLatheWriter(NgcLatheWriting, LinuxcncWriter):
    """LinuxCNC's writer for a lathe program: the mode line, G96 with its clamp, G33 with K."""
