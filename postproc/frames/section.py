"""``FrameChange``: a block changes the coordinate frame programmed points are read in.

Neutral, as the rest of the IR: ``kind`` says "local offset" or "rotation", never "G52" or "G68". The
words are those the command takes, by letter, in program units (an angle in degrees): an axis letter
is an offset, a centre or a mirror line on that axis; ``R`` an angle; ``P`` a common scale factor and
``I J K`` per-axis factors. ``rules`` names the rule set the command follows ('layered', 'shared_offset', 'rotate_first' or 'chain',
named after what they do, see ``postproc.frames.frame``; each dialect's reading names its controller's). ``family`` and ``text`` keep the command as written, for a target of the same
family that runs it natively (``postproc.frames.lowering``). ``omitted`` says, in the family's words, where the
controller takes a value the command leaves out (Fanuc: a G68 without R, its angle from a parameter), for the
error that the simulation, which does not know it, gives (empty: nothing to say). ``increment_setting`` names, in
the family's words, what decides whether the first incremental move on an axis a ``chain`` change moved also
travels the change (SINUMERIK: a setting datum), for the error that refuses such a move (empty: "a setting of the
controller").

Kinds (what each does is in ``postproc.frames.frame``):
- ``local``: a local offset (Fanuc G52; LinuxCNC G52, which shares G92's offset);
- ``origin``: the current point gets the programmed coordinates (G92 on a mill);
- ``origin_clear`` / ``origin_suspend`` / ``origin_restore``: LinuxCNC G92.1 / G92.2 / G92.3;
- ``rotate`` / ``rotate_off``: rotation in the active plane about a centre (Fanuc G68 / G69);
- ``scale`` / ``scale_off``: scaling about a centre (Fanuc G51 / G50);
- ``mirror`` / ``mirror_off``: programmable mirror image (Fanuc G51.1 / G50.1);
- ``polar`` / ``polar_off``: polar coordinates in the active plane (Fanuc G16 / G15).

Under the ``chain`` rules (a programmable frame that each command replaces or extends) ``local``,
``rotate``, ``scale`` and ``mirror`` replace the whole programmable frame by one component (no words: the
frame is cleared), and ``local_add``, ``rotate_add``, ``scale_add`` and ``mirror_add`` chain the component
onto the frame in force. Their words: ``local``: X Y Z offsets; ``rotate``: ``R`` (degrees in the active
plane) or one of ``A B C`` (degrees about X, Y or Z); ``scale``: ``I J K`` factors on X, Y, Z; ``mirror``:
the axes whose direction turns over (their values mean nothing).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Final

from ..ir.expr import Expr
from ..ir import Section
from ..xmlio import XFactory, computed_value, lxml_etree

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

KINDS: Final = frozenset(("local", "origin", "origin_clear", "origin_suspend", "origin_restore", "rotate",
                          "rotate_off", "scale", "scale_off", "mirror", "mirror_off", "polar", "polar_off", "local_add",
                          "rotate_add", "scale_add", "mirror_add"))
"""Every kind of frame change the IR models."""
LAYERED: Final = "layered"
"""Mirror, scaling, rotation about their centres, then the local offset and the G92 shift (Fanuc's)."""
SHARED_OFFSET: Final = "shared_offset"
"""One offset G52 and G92 share, with its parameters; each work system's XY rotation (RS274/NGC's)."""
ROTATE_FIRST: Final = "rotate_first"
"""The rotation acts on the programmed coordinates before any offset (ISG's)."""
CHAIN: Final = "chain"
"""A programmable frame each command replaces or extends (SINUMERIK's)."""
RULES: Final = frozenset((LAYERED, SHARED_OFFSET, ROTATE_FIRST, CHAIN))
"""The rule sets a frame change may follow (``postproc.frames.frame``), named after what they do."""


class FrameChange(Section):
    """One frame command (see the module docstring)."""

    XNAME = KEY = "FrameChange"
    __slots__ = ("kind", "words", "rules", "family", "text", "omitted", "increment_setting")

    def __init__(self, kind: str, words: dict[str, float | Expr], rules: str, family: str, text: str,
                 omitted: str = "", increment_setting: str = "") -> None:
        if kind not in KINDS:
            raise ValueError(f"unknown frame change {kind!r}")
        if rules not in RULES:
            raise ValueError(f"unknown frame rules {rules!r}")
        self.kind = kind
        self.words = words
        self.rules = rules
        self.family = family
        self.text = text
        self.omitted = omitted
        self.increment_setting = increment_setting

    def describe(self) -> str:
        return f"{self.text} ({self.kind.replace('_', ' ')})"

    @classmethod
    def from_xml(cls, el: etree._Element) -> "FrameChange":
        words: dict[str, float | Expr] = {}
        for child in el:
            if child.tag == "Words":
                words = {k: float(v) for k, v in child.attrib.items()}
                for value in child:
                    if value.tag == "Value":
                        words[value.get("of", "")] = computed_value(child, value.get("of", ""))
                    elif isinstance(value.tag, str):
                        raise ValueError(f"unexpected <{value.tag}>")
            elif isinstance(child.tag, str):
                raise ValueError(f"unexpected <{child.tag}>")
        return cls(el.get("kind", ""), words, el.get("rules", ""), el.get("family", ""), el.get("text", ""),
                   el.get("omitted", ""), el.get("incrementSetting", ""))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, kind=self.kind, rules=self.rules, family=self.family, text=self.text)
        if self.omitted:
            el.set("omitted", self.omitted)
        if self.increment_setting:
            el.set("incrementSetting", self.increment_setting)
        child = etree.SubElement(el, "Words")
        for k, v in self.words.items():
            if isinstance(v, Expr):
                etree.SubElement(child, "Value", of=k).append(v.make_xml_source())
            else:
                child.set(k, repr(float(v)))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.kind, tuple(sorted(self.words.items(), key=lambda kv: kv[0])), self.rules, self.family, self.text,
                self.omitted, self.increment_setting)

    def __repr__(self) -> str:
        omitted = f", {self.omitted!r}" if self.omitted or self.increment_setting else ""
        setting = f", {self.increment_setting!r}" if self.increment_setting else ""
        return (f"FrameChange({self.kind!r}, {self.words!r}, {self.rules!r}, {self.family!r}, {self.text!r}{omitted}"
                f"{setting})")


def register_frames(factory: XFactory) -> None:
    """Register the frame section with ``factory``; idempotent."""
    FrameChange.reg(factory)
