"""One block of a program (``Block``): its source line, words and the sections that say what it does;
and how its end of line travels in XML."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import TYPE_CHECKING, Any, ClassVar, Final

from mypy_extensions import i64

from .expr import Expr, expr_from_xml
from ..xmlio import DEFAULT, XFactory, XmlNode, decode, encode, lxml_etree, restore_slots, slot_state, where
from .section import Section

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


@mypyc_attr(allow_interpreted_subclasses=True)
class Block:
    """One block of a program. Not an ``XmlNode`` subclass only to stay lean; it serialises the same way.

    ``text`` is the source line without its end-of-line (``eol``), or None once the block was changed
    and must be generated from its sections. ``words`` are (letter, number text) pairs as written;
    ``values`` the numbers they mean once the reading dialect applied its rules (e.g. Fanuc's decimal
    point rule), keyed by upper-case letter for every address but G and M; a computed word's value is
    its expression (``Expr``, G and M included), serialised as ``<Word kind="expr">`` holding the tree.
    """

    XNAME: ClassVar[str] = "Block"
    __slots__ = ("line", "text", "eol", "_words", "_spelled", "marks", "values", "sections", "canonical")

    def __init__(self, line: int, text: str | None, eol: str = "\n",
                 words: list[tuple[str, str]] | None = None, marks: i64 = 0) -> None:
        self.line = line
        self.text = text
        self.eol = eol
        # (statements, not conditional expressions: compiled, ``marks if .. else 0`` boxed the i64 and unboxed it)
        self._words: list[tuple[str, str]] | None = words
        self._spelled: str | None = None
        """The canonical line ``marks`` point into, until its words are made (``words``)."""
        self.marks: i64 = 0
        if words is None:
            if marks:
                self._spelled = text
                self.marks = marks
            else:
                self._words = []
        """A reader's words not made yet (0: made, ``words`` holds them): where the letters of a canonical line
        (``text``, as read) stand, packed by ``postproc.rs274.canonical_line.scan_marks``. A step that reads the
        block from them (the plain-block lane) makes no word objects; reading ``words`` makes them (the same
        words as the reader's scan) and clears it. Not part of the block's value."""
        self.values: dict[str, float | int | Expr] = {}
        """Address -> what its word reads as (the reader's and block syntax's; no later step changes it,
        so a writer that copies a canonical word checks the section's value against it)."""
        self.sections: dict[str, Section] = {}
        self.canonical = False
        """A reader's hint: ``text`` is its ``words`` joined by single spaces, already in canonical
        spelling (``postproc.numbers``), so a writer may copy it (``WordWriter.straight_move``); whatever
        takes words out of such a block (a call's words into its section) clears it. Not part of the
        block's value (equality, XML)."""

    @property
    def words(self) -> list[tuple[str, str]]:
        """(letter, number text) pairs as written, made at the first reading where the reader left ``marks``
        (a canonical line's words, which most blocks of a long program are never asked for)."""
        words = self._words
        if words is None:
            spelled = self._spelled
            words = self._words = marked_words(spelled if spelled is not None else "", self.marks)
            self._spelled = None
            self.marks = 0
        return words

    @words.setter
    def words(self, words: list[tuple[str, str]]) -> None:
        self._words = words
        self._spelled = None
        self.marks = 0

    def spelled(self) -> str:
        """The line ``marks`` point into (the reader's ``text``; "" once the words are made)."""
        spelled = self._spelled
        return spelled if spelled is not None else ""

    def add(self, section: Section) -> Section:
        self.sections[section.KEY] = section
        return section

    def get(self, key: str) -> Any:
        return self.sections.get(key)

    def changed(self) -> None:
        """Mark the block as rewritten: writers must generate it from its sections."""
        self.text = None

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Block):
            return NotImplemented
        return (self.line, self.text, self.eol, self.words, self.values, self.sections) == (
            other.line, other.text, other.eol, other.words, other.values, other.sections)

    def __getstate__(self) -> dict[str, Any]:
        return slot_state(self)

    def __setstate__(self, state: dict[str, Any]) -> None:
        restore_slots(self, state)

    def __repr__(self) -> str:
        return f"Block(line={self.line}, text={self.text!r}, sections={list(self.sections.values())!r})"

    @classmethod
    def from_xml(cls, el: etree._Element, factory: XFactory | None = None) -> "Block":
        factory = factory or DEFAULT
        text = el.get("text")
        block = cls(int(el.get("line", "0")), text, decode_eol(el.get("eol", "LF")))
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag == "Word":
                letter, num = child.get("letter", ""), child.get("text", "")
                block.words.append((letter, num))
                if child.get("kind") == "expr":
                    kids = [c for c in child if isinstance(c.tag, str)]
                    if len(kids) != 1:
                        from ..errors import ConfigError
                        raise ConfigError("<Word kind=\"expr\"> holds exactly one expression", where(child))
                    block.values[letter.upper()] = expr_from_xml(kids[0])
                elif "value" in child.attrib:
                    block.values[letter.upper()] = decode(float if child.get("kind") == "float" else int,
                                                          child.get("value", ""))
            else:
                section = factory.create(child)
                if not isinstance(section, Section):
                    from ..errors import ConfigError
                    raise ConfigError(f"<{child.tag}> is not a block section", where(child))
                block.add(section)
        return block

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, line=str(self.line))
        if self.text is not None:
            el.set("text", self.text)
        if self.eol != "\n":
            el.set("eol", encode_eol(self.eol))
        seen: set[str] = set()
        for letter, num in self.words:
            w = etree.SubElement(el, "Word", letter=letter, text=num)
            key = letter.upper()
            if key in self.values and key not in seen:
                seen.add(key)
                v = self.values[key]
                if isinstance(v, Expr):
                    w.set("kind", "expr")
                    w.append(v.make_xml_source(base_dir, rel_file, exhibition_only))
                    continue
                w.set("kind", "float" if isinstance(v, float) else "int")
                w.set("value", encode(v))
        for section in self.sections.values():
            el.append(section.make_xml_source(base_dir, rel_file, exhibition_only))
        return el


_EOLS: Final = {"\n": "LF", "\r\n": "CRLF", "\r": "CR", "": "none"}
_EOLS_BACK: Final = {v: k for k, v in _EOLS.items()}


def marked_words(text: str, marks: i64) -> list[tuple[str, str]]:
    """The words of a canonical line from where its letters stand (``marks``: the count in the low
    ``MARK_BITS``, then each letter's position in ``MARK_BITS`` bits): the letter, then its number up to the
    space before the next letter or the end of the line (``canonical_line.scan_marks`` packs them)."""
    count = marks & MARK_MASK
    words: list[tuple[str, str]] = []
    rest = marks >> MARK_BITS
    i: i64 = 0
    while i < count:
        at = rest & MARK_MASK
        rest = rest >> MARK_BITS
        end = (rest & MARK_MASK) - 1 if i + 1 < count else len(text)
        words.append((text[at], text[at + 1:end]))
        i += 1
    return words


MARK_BITS: Final = 8
"""Bits a position (and the count) takes in a block's ``marks``: a line of at most 255 characters."""
MARK_MASK: Final = (1 << MARK_BITS) - 1
MARK_WORDS: Final = 6
"""The most words ``marks`` holds (seven fields of eight bits: a short int, compiled, never a boxed one)."""


def encode_eol(eol: str) -> str:
    return _EOLS[eol]


def decode_eol(name: str) -> str:
    if name not in _EOLS_BACK:
        raise ValueError(f"unknown end of line {name!r}")
    return _EOLS_BACK[name]


def one_line(text: str) -> str:
    """A block's text on one line (a block continued over several lines, ISG's ``\\``, keeps its line
    ends in ``text``), for a comment or a message that quotes it."""
    if "\n" in text or "\r" in text:
        return text.replace("\r\n", " ").replace("\n", " ").replace("\r", " ")
    return text
