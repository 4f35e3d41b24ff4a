"""The fields of an arc-end rule its arithmetic reads (``arc_end_math``), as a protocol: ``arc_end.ArcEndRule`` (a
record of an interpreted module) imports ``arc_end_math``, which could not import the record back without a circle.
Not compiled: a protocol is only a type (``tests/test_native.py`` holds compiled classes to mypyc's rules)."""

from __future__ import annotations

from typing import Protocol


class ArcEndLimits(Protocol):
    """The fields of a rule ``arc_end_math`` reads (``arc_end.ArcEndRule``, a record of an interpreted module: its
    fields are read by name). A protocol rather than an import of the record, which imports ``arc_end_math``."""

    @property
    def metric(self) -> float: ...
    @property
    def inch(self) -> float: ...
    @property
    def relative(self) -> float: ...
    @property
    def ceiling(self) -> float: ...
    @property
    def of_start(self) -> bool: ...
    @property
    def of_centre_shift(self) -> bool: ...
    @property
    def runs(self) -> str: ...
