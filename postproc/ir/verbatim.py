"""Sections kept verbatim for their own controller family: a construct with no neutral meaning
(``NativeCode``), a machine builder's function (``MachineFunction``) and programmable data input
(``DataSetting``)."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import TYPE_CHECKING, Any, Final

from .expr import Expr
from ..xmlio import XAttr, lxml_etree
from .section import Section, axes_from_xml, axes_to_xml

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


@mypyc_attr(allow_interpreted_subclasses=True)
class NativeCode(Section):
    """A construct with no neutral meaning, kept verbatim for its own dialect (e.g. ISG ``#CYL``).

    It round-trips unchanged within ``dialect`` and is an unsupported construct everywhere else. An
    ``inert`` one does nothing a tool path shows (an ISG STRING variable's declaration): the simulation
    passes it; every other one stops the simulation, naming it.
    """

    XNAME = "NativeCode"

    KEY = "NativeCode"
    __slots__ = ("dialect", "what", "text", "inert")
    XATTRS = (XAttr("dialect"), XAttr("what"), XAttr("text"), XAttr("inert", bool, False))

    def __init__(self, dialect: str, what: str, text: str, inert: bool = False) -> None:
        self.dialect = dialect
        self.what = what
        self.text = text
        self.inert = inert


@mypyc_attr(allow_interpreted_subclasses=True)
class MachineFunction(Section):
    """A machine-specific code (an M code of the machine builder, a machine G code such as a smoothing
    setting) with the words it takes, as written (``text``). It passes verbatim between controllers of
    ``family`` and has no equivalent anywhere else; the simulation runs its ``action`` (one of
    ``postproc.setup.machine_setup.MachineCode``'s). ``declared``: the set-up or the family's defaults know it."""

    XNAME = "MachineFunction"

    KEY = "MachineFunction"
    __slots__ = ("family", "code", "action", "name", "text", "declared")
    XATTRS = (XAttr("family"), XAttr("code"), XAttr("action", str, "none"), XAttr("name", str, ""),
              XAttr("text"), XAttr("declared", bool, True))
    family: str
    code: str
    action: str
    name: str
    text: str
    declared: bool

    def __init__(self, family: str, code: str, text: str, action: str = "none", name: str = "",
                 declared: bool = True) -> None:
        self.family = family
        self.code = code
        self.text = text
        self.action = action
        self.name = name
        self.declared = declared

    def describe(self) -> str:
        """``M31 (part counter)``, for messages."""
        return f"{self.code} ({self.name})" if self.name else self.code


STORED_WORK_OFFSET: Final = "work_offset_stored"
"""``DataSetting.table`` of a work offset the controller writes into its table and takes at the work system's
next selection (a family's offset variables: ISG ``V.G.NP[n]``...), where ``work_offset`` (G10 L2) acts at once
on the active system [K: LinuxCNC g-code.adoc "G10 L2": an active system's new offset takes effect at once;
V: rs274 run here, tests/test_work_offset_variables.py]. Set for a system that is not the active one, the two are one meaning."""


@mypyc_attr(allow_interpreted_subclasses=True)
class DataSetting(Section):
    """Programmable data input (``G10 L2 P1 X.. Y..`` of the RS274 family): write ``values`` (key -> value in
    program units) into entry ``index`` of a controller table. ``table`` is neutral: 'work_offset' (index 1 = the
    first work system, 0 = the offset common to all), 'work_offset_stored' (``STORED_WORK_OFFSET``),
    'work_offset_extended', 'tool_length', 'tool_length_wear', 'cutter_offset', 'cutter_offset_wear', a whole tool
    table entry by tool number 'tool_entry' (and 'tool_entry_at_point', 'tool_entry_at_point_9': the entry set so
    that the current point reads the values, in the current work system or the ninth), a lathe tool offset's
    'lathe_offset' and 'lathe_offset_wear' (``postproc.compensation.tool_table``). The keys are axis letters or 'R'
    (the radius), except a lathe offset's, which are keyed by meaning, not by a family's letters (``LATHE_VALUES``:
    'x', 'x_increment', 'z', 'z_increment', 'radius', 'radius_increment'; ``LATHE_TIP``: 'tip'). ``incremental``:
    the values are added to the entry. ``text`` is the block's setting as written, passed verbatim within
    ``family``. A value may be an expression (``X[#1+1]``, a program kept symbolically); the table and the entry are
    numbers (a computed ``L`` or ``P`` keeps the block verbatim)."""

    XNAME = "DataSetting"

    KEY = "DataSetting"
    __slots__ = ("family", "table", "index", "values", "incremental", "text")

    def __init__(self, family: str, table: str, index: int, values: dict[str, float | Expr], incremental: bool,
                 text: str) -> None:
        self.family = family
        self.table = table
        self.index = index
        self.values = values
        self.incremental = incremental
        self.text = text

    def describe(self) -> str:
        return f"{self.text} (setting {self.table.replace('_', ' ')} {self.index})"

    @classmethod
    def from_xml(cls, el: etree._Element) -> "DataSetting":
        values: dict[str, float | Expr] = {}
        for c in el:
            if c.tag == "Values":
                values = axes_from_xml(c)
            elif isinstance(c.tag, str):
                raise ValueError(f"unexpected <{c.tag}>")
        return cls(el.get("family", ""), el.get("table", ""), int(el.get("index", "0")), values,
                   el.get("incremental") == "true", el.get("text", ""))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, family=self.family, table=self.table, index=str(self.index))
        if self.incremental:
            el.set("incremental", "true")
        el.set("text", self.text)
        axes_to_xml(el, "Values", self.values)
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.family, self.table, self.index, self.values, self.incremental, self.text)
