"""A block of zero offset table assignments (ISG ``V.G.NP[2].V.X=10``, Fagor ``V.A.ORGT[2].X=10``), read as
the neutral work offset setting the controller takes at the system's next selection (``STORED_WORK_OFFSET``).

Each dialect gives the pattern of its variable (``ZeroOffsets``); what the family shares is the block's form:
an optional block number, then one or more assignments of plain numbers to axes of one table entry, nothing
else. A block of any other form (a computed value, two entries, an entry no G54-G59 selects, a name that is
not one axis letter) is None here and goes through the family's lexer as before (kept verbatim: an array
element is not modelled).
"""

from __future__ import annotations

import re
from typing import Final

from postproc.errors import Location, ParseError
from postproc.ir.expr import Expr
from postproc.ir import Block, DataSetting, Sequence
from postproc.ir.verbatim import STORED_WORK_OFFSET

_NUMBER: Final = r"[-+]?(?:\d+\.?\d*|\.\d+)"
_AXES: Final = frozenset("XYZABCUVW")


class ZeroOffsets:
    """One dialect's zero offset variable: ``entry`` is a regular expression of one assignment with the
    groups ``index``, ``axis`` and ``value``; entries 1-``count`` are those G54-G59 select."""

    __slots__ = ("family", "assignment", "count")

    def __init__(self, family: str, entry: str, count: int) -> None:
        self.family = family
        self.assignment = re.compile(entry.replace("{NUMBER}", _NUMBER), re.IGNORECASE)
        self.count = count

    def read(self, block: Block, code: str, file: str) -> bool:
        """``code`` (the block without its comments) as a zero offset setting added to ``block``; False when
        it is not one (``code`` is then read as the family reads any block)."""
        text = code.strip()
        number = None
        m = re.match(r"[Nn](\d+)\s+", text)
        if m is not None:
            number, text = m.group(1), text[m.end():]
        index = None
        values: dict[str, float | Expr] = {}
        pos = 0
        while pos < len(text):
            a = self.assignment.match(text, pos)
            if a is None:
                return False
            entry, axis = int(a.group("index")), a.group("axis").upper()
            if axis not in _AXES or not 1 <= entry <= self.count or index not in (None, entry):
                return False
            if axis in values:
                raise ParseError(f"axis {axis} of zero offset {entry} is set twice in one block",
                                 Location(file, block.line, code.find(text) + a.start() + 1))
            index = entry
            values[axis] = float(a.group("value"))
            pos = a.end()
            while pos < len(text) and text[pos] in " \t":
                pos += 1
        if index is None:
            return False
        if number is not None:
            block.words.append(("N", number))
            block.add(Sequence(int(number)))
        block.add(DataSetting(self.family, STORED_WORK_OFFSET, index, values, False, text))
        return True
