"""LinuxCNC reader: the RS274/NGC family reader, naming LinuxCNC in its messages."""

from __future__ import annotations

from postproc.rs274.ngc_lexer import NgcReader


class LinuxcncReader(NgcReader):
    DIALECT = "linuxcnc"
