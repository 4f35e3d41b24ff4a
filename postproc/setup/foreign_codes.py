"""``<ForeignCodes>``: what another controller family's machine-specific M code becomes on this machine.

A machine builder's M code (Haas's chip auger, a part counter) passes verbatim between controllers of one
family and has no neutral meaning elsewhere (``postproc.ir.MachineFunction``). An integrator who moves a
program to a machine of another family decides, per machine, what each such code becomes there:

* a code of this machine (``to="M131"``): a machine function the target's own reader reads back as one
  (LinuxCNC: a user M code M100-M199, which runs the program file of that name in the configuration's
  ``USER_M_PATH``/``PROGRAM_PREFIX``; ISG, Fagor and SINUMERIK: an M function the machine builder configured;
  grbl has none, so nothing but ``omit`` goes there);
* ``to="omit"``: the code is left out and a comment in its block says so, for the operator. Only a code
  that moves nothing and changes no spindle, coolant, feed or tool data (its action ``none``: a chip
  conveyor, an air blast, a door) may be omitted.

Without a declaration the translation refuses the code, naming this element. ``postproc.lowering.machine_functions``
applies the declarations; ``verify`` compares a mapped code with the code it became and lists an omitted one.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from ..errors import ConfigError
from ..records import record
from ..xmlio import where
from .record import camel, pydantic_config, setting, values

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

OMIT = "omit"
"""The ``to`` of a code left out."""
TAG = "ForeignCodes"


@record(frozen=True)
class ForeignCode:
    """``<M family="fanuc" number="31" to="omit"/>``: the family's M31 is left out on this machine."""

    __pydantic_config__: ClassVar[dict[str, Any]] = pydantic_config(camel)
    family: str = setting(pattern=r"^[a-z][a-z0-9_-]{0,31}$")
    """The controller family whose code this is, as ``postproc dialects`` names it (``fanuc``)."""
    number: str = setting(pattern=r"^[0-9]{1,4}$")
    """The code's number in that family (``31``; ``031`` is the same code)."""
    to: str = setting(pattern=r"^(omit|[Mm][0-9]{1,4})$")
    """``omit``, or the M code of this machine it becomes (``M131``)."""

    def key(self) -> tuple[str, str]:
        """``("fanuc", "M31")``: the family and the code as ``MachineFunction.code`` names it."""
        return self.family, "M" + str(int(self.number))

    def becomes(self) -> str:
        """``omit`` or the target code as the target writes it (``M131``)."""
        return OMIT if self.to == OMIT else "M" + str(int(self.to[1:]))


def foreign_codes_from_xml(el: etree._Element) -> list[ForeignCode]:
    """``<ForeignCodes>`` holds ``<M>`` elements; a code declared twice is an error."""
    from .validate import Invalid, validate
    if el.attrib:
        raise ConfigError(f"<{TAG}> takes no attributes, only <M> elements", where(el))
    codes: list[ForeignCode] = []
    seen: set[tuple[str, str]] = set()
    for child in el:
        if not isinstance(child.tag, str):
            continue
        if child.tag != "M":
            raise ConfigError(f"unknown element <{child.tag}> in <{TAG}> (expected <M>: only M codes are mapped; "
                              "a machine G code changes how the path is cut)", where(child))
        if len([c for c in child if isinstance(c.tag, str)]):
            raise ConfigError("<M> takes attributes only", where(child))
        try:
            code = validate(ForeignCode, dict(child.attrib))
        except Invalid as exc:
            field_name, msg = exc.problems[0]
            raise ConfigError(f"<M> {field_name}: {msg}" if field_name else f"<M> {msg}", where(child)) from None
        if code.key() in seen:
            raise ConfigError(f"{code.family} {code.key()[1]} is declared twice", where(child))
        seen.add(code.key())
        codes.append(code)
    return codes


def foreign_codes_to_xml(parent: etree._Element, codes: list[ForeignCode]) -> None:
    """``<ForeignCodes>`` under ``parent`` (none when ``codes`` is empty), as ``config dump`` writes it."""
    if not codes:
        return
    from ..xmlio import lxml_etree
    etree = lxml_etree()
    el = etree.SubElement(parent, TAG)
    for code in codes:
        child = etree.SubElement(el, "M")
        for key, value in values(code, by_alias=True).items():
            child.set(key, str(value))


def foreign_table(codes: list[ForeignCode]) -> dict[tuple[str, str], ForeignCode]:
    """``(family, code)`` -> its declaration."""
    return {code.key(): code for code in codes}


def unknown_families(codes: list[ForeignCode], families: set[str], file: str) -> list[ConfigError]:
    """``config check``: a declaration for a family no installed dialect belongs to would never apply; each is
    located at its element in ``file`` (at the root where a base the file extends declares it)."""
    unknown = [c for c in codes if c.family not in families]
    if not unknown:
        return []
    from ..errors import Location
    from ..xmlio import parse_xml_file
    root = parse_xml_file(file)
    problems = []
    for code in unknown:
        el = next((m for m in root.iter("M") if (up := m.getparent()) is not None and up.tag == TAG
                   and m.get("family") == code.family), root)
        problems.append(ConfigError(f"<{TAG}> family {code.family!r} is no installed dialect's family (the "
                                    f"families: {', '.join(sorted(families))})", Location(file, el.sourceline or 1, 1)))
    return problems
