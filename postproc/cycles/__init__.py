"""Milling hole cycles (G73, G74, G76, G81-G89): resolution, exact expansion and lowering.

``CannedCycleResolveSyntax`` turns a cycle block into a ``CannedCycle`` section (the neutral record)
and a ``CompoundMotion`` (the motion the controller makes), one family syntax per cycle family;
``expand_canned_cycles`` (lowering) keeps the cycle native or writes its expansion for a target.
"""

from __future__ import annotations

from postproc.xmlio import XFactory, XmlNode

from .back_boring import BackBoringExpansion
from .boring import BoringExpansion
from .drilling import DrillingExpansion
from .expansion import CycleExpansion
from .fine_boring import FineBoringExpansion
from .hole_ends import hole_cycle_end  # lowering follows a hole cycle's end through it
from .manual_boring import ManualBoringExpansion
from .peck_drilling import PeckDrillingExpansion
from .resolve import EXPANSIONS, CannedCycleResolveSyntax
from .section import CannedCycle
from .tapping import TappingExpansion

XML_CLASSES: tuple[type[XmlNode], ...] = (CannedCycle, CannedCycleResolveSyntax, *EXPANSIONS)
"""Every XML node class of the package."""

__all__ = [
    "BackBoringExpansion", "BoringExpansion", "CannedCycle", "CannedCycleResolveSyntax", "CycleExpansion",
    "DrillingExpansion", "FineBoringExpansion", "ManualBoringExpansion", "PeckDrillingExpansion", "TappingExpansion",
    "XML_CLASSES", "hole_cycle_end", "register",
]


def register(factory: XFactory | None = None) -> None:
    """Register the package's XML classes with ``factory`` (the default one if None); idempotent."""
    for cls in XML_CLASSES:
        cls.reg(factory)
