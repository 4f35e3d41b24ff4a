"""The RS274 family's lathe addresses: what a lathe dialect of the family declares as its incremental axes.

On Fanuc T (G-code system A) and the GSK 980TDc, ``U`` and ``W`` move X and Z by an increment whatever the
distance mode, beside the absolute ``X`` and ``Z`` of the same block (``G01 X40. W-10.``); ``U`` is a
diameter where X is [V for Fanuc system A, K for GSK: DIALECTS.md 1.1 "Lathe specifics (T)" and 1.2]. Whether
Fanuc systems B and C still read U/W beside G91 is not in our sources [?]: they are read as in system A.
A lathe dialect of
the family sets ``Dialect.INCREMENTAL_AXES = LATHE_INCREMENTS``; the neutral core reads the declaration
(``Context.increments``) and spells no letter of its own.
"""

from __future__ import annotations

from typing import Mapping

LATHE_INCREMENTS: Mapping[str, str] = {"U": "X", "W": "Z"}
"""Incremental address -> the axis it moves."""
