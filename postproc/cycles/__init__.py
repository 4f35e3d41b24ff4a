"""Milling hole cycles (G73, G74, G76, G81-G89): resolution, exact expansion and lowering.

``CannedCycleResolveSyntax`` turns a cycle block into a ``CannedCycle`` section (the neutral record)
and a ``CompoundMotion`` (the motion the controller makes), one family syntax per cycle family;
``expand_canned_cycles`` (lowering) keeps the cycle native or writes its expansion for a target.

The package loads none of its modules by itself: importing one of them (``postproc.cycles.semantics``, which
every family base that names its cycle rules imports, so every registered dialect) runs this file first, and
with the expansions, the resolve step and their imports it cost ``postproc dialects`` about a twelfth of its
start-up. The names below are imported on first use (``__getattr__``), the XML classes registered by name
(``register``: imported when an element names one), and where a hole cycle ends is told to lowering by a
function that imports the expansions at its first call (no ``CannedCycle`` exists before this package loads).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Callable

from postproc.lowering.point_after import follow_hole_cycles
from postproc.xmlio import XFactory

if TYPE_CHECKING:
    from postproc.ir import Section
    from postproc.xmlio import XmlNode

    from .back_boring import BackBoringExpansion as BackBoringExpansion
    from .boring import BoringExpansion as BoringExpansion
    from .drilling import DrillingExpansion as DrillingExpansion
    from .expansion import CycleExpansion as CycleExpansion
    from .fine_boring import FineBoringExpansion as FineBoringExpansion
    from .hole_ends import hole_cycle_end as hole_cycle_end
    from .manual_boring import ManualBoringExpansion as ManualBoringExpansion
    from .peck_drilling import PeckDrillingExpansion as PeckDrillingExpansion
    from .resolve import CannedCycleResolveSyntax as CannedCycleResolveSyntax
    from .section import CannedCycle as CannedCycle
    from .tapping import TappingExpansion as TappingExpansion

_NAMES = {
    "BackBoringExpansion": "back_boring", "BoringExpansion": "boring", "CannedCycle": "section",
    "CannedCycleResolveSyntax": "resolve", "CycleExpansion": "expansion", "DrillingExpansion": "drilling",
    "FineBoringExpansion": "fine_boring", "ManualBoringExpansion": "manual_boring",
    "PeckDrillingExpansion": "peck_drilling", "TappingExpansion": "tapping", "hole_cycle_end": "hole_ends",
}
"""Each public name -> the module of the package that defines it."""

XML_NAMES = {
    "CannedCycle": "section:CannedCycle", "CannedCycleResolveSyntax": "resolve:CannedCycleResolveSyntax",
    "DrillingSyntax": "drilling:DrillingExpansion", "PeckDrillingSyntax": "peck_drilling:PeckDrillingExpansion",
    "TappingSyntax": "tapping:TappingExpansion", "BoringSyntax": "boring:BoringExpansion",
    "FineBoringSyntax": "fine_boring:FineBoringExpansion", "BackBoringSyntax": "back_boring:BackBoringExpansion",
    "ManualBoringSyntax": "manual_boring:ManualBoringExpansion",
}
"""Element name -> ``module:Class`` in this package, of every XML node class of the package (the section, the
resolve step and ``resolve.EXPANSIONS``; ``XFactory`` checks each class's ``XNAME`` when it imports it, and
tests/test_startup_imports.py that this is every class ``XML_CLASSES`` lists)."""

__all__ = [
    "BackBoringExpansion", "BoringExpansion", "CannedCycle", "CannedCycleResolveSyntax", "CycleExpansion",
    "DrillingExpansion", "FineBoringExpansion", "ManualBoringExpansion", "PeckDrillingExpansion", "TappingExpansion",
    "XML_CLASSES", "XML_NAMES", "hole_cycle_end", "register",
]


def __getattr__(name: str) -> object:
    """A public name of the package, imported from its module on first use (PEP 562)."""
    if name == "XML_CLASSES":
        from .resolve import EXPANSIONS, CannedCycleResolveSyntax
        from .section import CannedCycle
        value: object = (CannedCycle, CannedCycleResolveSyntax, *EXPANSIONS)
    elif name in _NAMES:
        value = getattr(importlib.import_module(f"{__name__}.{_NAMES[name]}"), name)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def register(factory: XFactory | None = None) -> None:
    """Register the package's XML classes with ``factory`` (the default one if None), by name: each imported
    when an element names it (``XFactory.register_lazy``); idempotent."""
    if factory is None:
        from postproc.xmlio import DEFAULT
        factory = DEFAULT
    for xname, target in XML_NAMES.items():
        factory.register_lazy(xname, f"{__name__}.{target}")


_ENDS: list[Callable[[Section], "dict[str, float] | None"]] = []


def _hole_cycle_end(section: Section) -> dict[str, float] | None:
    """``hole_ends.hole_cycle_end``, imported at the first hole cycle lowering follows (importing it registers
    it too, after this one: ``point_after.cycle_end`` asks the first)."""
    if not _ENDS:
        from .hole_ends import hole_cycle_end
        _ENDS.append(hole_cycle_end)
    return _ENDS[0](section)


follow_hole_cycles(_hole_cycle_end)
