"""Sections only lathe programs make: spindle speed mode and clamp, coordinate setting, a lathe cycle
and the profile blocks a cycle runs instead of the program.

Neutral, as the rest of the IR: a section says "constant surface speed" or "rough turning cycle", never
"G96" or "G71". Lengths are in program units; X (and an X allowance) is a diameter on a machine that
programs diameters (``Context.diameter``), every depth and relief is a radius.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from .expr import Expr
from . import Section
from ..xmlio import XAttr, XFactory, computed_value, decode, encode, lxml_etree

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


class SpindleMode(Section):
    """'css' (constant surface speed: S is metres or feet per minute) or 'rpm' (S is revolutions)."""

    XNAME = KEY = "SpindleMode"
    __slots__ = ("mode",)
    XATTRS = (XAttr("mode", str),)
    mode: str

    def __init__(self, mode: str) -> None:
        self.mode = mode


class SpindleClamp(Section):
    """The highest spindle speed constant surface speed may reach, in rpm (or the expression a program
    kept symbolically computes it with: ``G50 S#1``)."""

    XNAME = KEY = "SpindleClamp"
    __slots__ = ("rpm",)
    XATTRS = (XAttr("rpm", float),)
    rpm: float | Expr

    def __init__(self, rpm: float | Expr) -> None:
        self.rpm = rpm


class CoordinateSet(Section):
    """The tool's present position is given these coordinates (program units; X as programmed):
    the work coordinate system moves, the tool does not. A value may be an expression (``G50 X#1``, a
    program kept symbolically)."""

    XNAME = KEY = "CoordinateSet"
    __slots__ = ("axes",)

    def __init__(self, axes: dict[str, float | Expr]) -> None:
        self.axes = axes

    @classmethod
    def from_xml(cls, el: etree._Element) -> "CoordinateSet":
        axes: dict[str, float | Expr] = {k: float(v) for k, v in el.attrib.items()}
        for child in el:
            if child.tag == "Value":  # a computed value: <Value of="X">expr</Value>
                axes[child.get("of", "")] = computed_value(el, child.get("of", ""))
        return cls(axes)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        for k, v in self.axes.items():
            if isinstance(v, Expr):
                etree.SubElement(el, "Value", of=k).append(v.make_xml_source())
            else:
                el.set(k, repr(float(v)))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (tuple(sorted(self.axes.items())),)  # by axis: XML gives the numbers, then the expressions


class ThreadLead(Section):
    """The lead of this block's thread move (``Motion`` mode 'thread'), per spindle revolution along the
    thread's major axis (Z where the move's Z travel is at least its X travel as a radius, else X), in
    program units; the block's feed rate F stays what it was. It is what a control writes beside its
    thread code where F is no lead (LinuxCNC's ``G33 K``, which it measures along the path: the reader
    converts it, ``postproc.geometry.thread_lead``); a control whose thread move takes its lead from F (Fanuc
    ``G32 F``) has none."""

    XNAME = KEY = "ThreadLead"
    __slots__ = ("lead",)
    XATTRS = (XAttr("lead", float),)
    lead: float

    def __init__(self, lead: float) -> None:
        self.lead = lead


class XProgramming(Section):
    """From this block on the program writes X as a ``"diameter"`` or a ``"radius"``: a switch inside one
    program (LinuxCNC's ``G7``/``G8``). The IR keeps every X as the set-up's ``xProgramming`` says
    (``Context.diameter``): the reader converts the words it reads in the other mode, so the section only
    says where the controller's mode changes, for a writer that keeps the switches (``postproc.rs274.
    ngc_lathe_writer``); every other target drops it (``postproc.cycles.lathe_lowering``)."""

    XNAME = KEY = "XProgramming"
    __slots__ = ("mode",)
    XATTRS = (XAttr("mode", str),)
    mode: str

    def __init__(self, mode: str) -> None:
        self.mode = mode


class InProfile(Section):
    """This block is part of the profile (ns..nf) of the lathe cycle programmed on line ``cycle``: the
    controller runs it only through the cycle, never when the program reaches it."""

    XNAME = KEY = "InProfile"
    __slots__ = ("cycle",)
    XATTRS = (XAttr("cycle", int),)
    cycle: int

    def __init__(self, cycle: int) -> None:
        self.cycle = cycle


class LatheCycle(Section):
    """One block of a lathe cycle, resolved: every parameter the controller uses, defaults included.

    ``kind`` is the neutral name (``CYCLE_KINDS``); ``form`` says which block this is: 'first' (the first
    block of a two-block cycle: the modal data only), 'second' (the cycle itself), 'one' (the one-block
    form) or 'single' (a cycle that has one block only: G70, G90, G92, G94). ``params`` maps neutral
    parameter names to values (``PARAMS``); the block's motion travels as its ``CompoundMotion``.
    """

    XNAME = KEY = "LatheCycle"
    __slots__ = ("kind", "form", "params")
    XATTRS = (XAttr("kind", str), XAttr("form", str))
    CYCLE_KINDS: ClassVar[tuple[str, ...]] = (
        "turn_finish", "turn_rough", "face_rough", "pattern_repeat", "face_peck", "groove", "thread_multi",
        "turn_single", "thread_single", "face_single",
    )

    def __init__(self, kind: str, form: str, params: dict[str, float | int] | None = None) -> None:
        self.kind = kind
        self.form = form
        self.params: dict[str, float | int] = params if params is not None else {}

    @classmethod
    def from_xml(cls, el: etree._Element) -> "LatheCycle":
        params: dict[str, float | int] = {}
        for child in el:
            if child.tag == "Params":
                params = {k: decode(float if any(c in v for c in ".eEna") else int, v) for k, v in child.attrib.items()}
            elif isinstance(child.tag, str):
                raise ValueError(f"unexpected <{child.tag}>")
        return cls(XAttr("kind").parse(el), XAttr("form").parse(el), params)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, kind=self.kind, form=self.form)
        if self.params:
            child = etree.SubElement(el, "Params")
            for k, v in self.params.items():
                child.set(k, encode(v))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.kind, self.form, tuple(self.params.items()))

    def __repr__(self) -> str:
        return f"LatheCycle({self.kind!r}, {self.form!r}, {self.params!r})"


LATHE_SECTIONS: tuple[type[Section], ...] = (SpindleMode, SpindleClamp, CoordinateSet, ThreadLead, XProgramming,
                                                InProfile, LatheCycle)


def register_lathe_sections(factory: XFactory) -> None:
    """Register the lathe sections with ``factory``; idempotent."""
    for cls in LATHE_SECTIONS:
        cls.reg(factory)
