"""A typed part of a block (``Section``), the axis letters a motion carries and how axis words travel in
XML: the base every section of the IR extends."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import TYPE_CHECKING, Any, ClassVar

from .expr import Expr
from ..xmlio import XmlNode, computed_value, lxml_etree

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


AXES = ("X", "Y", "Z", "A", "B", "C", "U", "V", "W")
"""Axis letters a neutral motion may carry, in output order."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Section(XmlNode):
    """A typed part of a block. ``KEY`` is its slot in ``Block.sections`` (one of each per block)."""

    __slots__ = ()
    KEY: ClassVar[str] = ""


def axes_from_xml(el: etree._Element) -> dict[str, Any]:
    """Axis words from XML: numbers as attributes, computed values as ``<Value of="X">expr</Value>``."""
    axes: dict[str, Any] = {k: float(v) for k, v in el.attrib.items()}
    for child in el:
        if child.tag == "Value":
            axis = child.get("of", "")
            axes[axis] = computed_value(el, axis)
        elif isinstance(child.tag, str):
            raise ValueError(f"unexpected <{child.tag}>")
    return axes


def axes_to_xml(parent: etree._Element, tag: str, axes: dict[str, Any]) -> None:
    """Numbers as attributes (``X="1.0"``), computed values as ``<Value of="X">expr</Value>``."""
    etree = lxml_etree()
    child = etree.SubElement(parent, tag)
    for k, v in axes.items():
        if isinstance(v, Expr):
            etree.SubElement(child, "Value", of=k).append(v.make_xml_source())
        else:
            child.set(k, repr(float(v)))
