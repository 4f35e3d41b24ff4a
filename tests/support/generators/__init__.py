"""Targeted fuzz generators: one module per kind of input that found defects (templates and file names,
macro registers, ISG loops, Fagor patterns, o-word calls across dialects...).

Each module in this package defines ``KIND`` (a short name) and ``cases()``, a hypothesis strategy of
:class:`Case`. ``make fuzz`` (``tests/support/fuzz_main.py``) draws from every module each round, and
``tests/test_fuzz_generators.py`` runs a few cases of each in the suite. A module is found by its file
alone: adding a kind touches no other file.
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from types import ModuleType
from typing import Callable

from hypothesis import strategies as st


@dataclass(frozen=True)
class Case:
    """One fuzz case: ``run(program)`` returns 'ok' or 'refused', or raises AssertionError on a defect.

    ``run`` must accept a reduced ``program`` too (the fuzzer drops lines and words to shrink a failure),
    so everything but the program text is bound in it.
    """

    name: str
    """Names the pair or check (for example 'macro fanuc-linuxcnc'); failures are grouped by it."""
    target: str
    """The dialect written (matched against the known defects of ``tests/support/fuzzing.py``)."""
    program: str
    run: Callable[[str], object]
    setup: object = None


def modules() -> list[ModuleType]:
    """Every generator module of this package, by name."""
    found = [importlib.import_module(f"{__name__}.{info.name}")
             for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name) if not info.ispkg]
    return [m for m in found if hasattr(m, "cases") and hasattr(m, "KIND")]


def strategies() -> dict[str, st.SearchStrategy[Case]]:
    """KIND -> the module's strategy of cases."""
    return {m.KIND: m.cases() for m in modules()}
