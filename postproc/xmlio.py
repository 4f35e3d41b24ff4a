"""The one XML factory registry and the one safe lxml parser.

Every IR section and every syntax object is an ``XmlNode``: it has an element name (``XNAME``), a
constructor from an lxml element (``from_xml``), ``make_xml_source(base_dir, rel_file, exhibition_only)``
and an idempotent ``reg(factory)``. Simple nodes declare their attributes with ``XAttr`` descriptors
(as python-docx's oxml does) instead of hand-writing ``el.get(...)`` in every class.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

import importlib
import os
import re
from typing import TYPE_CHECKING, Any, Callable, ClassVar, Iterator, TypeVar

from .errors import ConfigError, Location

if TYPE_CHECKING:  # annotations only: lxml is imported on first use (lxml_etree)
    from pathlib import Path  # annotations only: a start makes no path object (pathlib imports urllib.parse)
    from lxml import etree

_etree: Any = None
_parser: etree.XMLParser | None = None


def lxml_etree() -> Any:
    """The ``lxml.etree`` module, imported on first use: it costs a start-up ~5 ms, and a command that
    reads and writes no XML (``postproc dialects``) never needs it. What reads or writes XML starts
    with ``etree = lxml_etree()``: a function-local ``from lxml import etree`` costs every call an
    import (0.2 µs as Python, more compiled), paid by each block and section an IR dump writes."""
    global _etree
    if _etree is None:
        from lxml import etree
        _etree = etree
    return _etree


def parser() -> etree.XMLParser:
    """The one lxml parser, built on first use: no entity resolution, no network, no DTD, no huge
    trees, so hostile XML cannot reach out or blow up."""
    global _parser
    if _parser is None:
        _parser = lxml_etree().XMLParser(
            resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False,
            huge_tree=False, remove_comments=False, remove_blank_text=True,
        )
    return _parser


MAX_XML_BYTES = 64 * 1024 * 1024
MAX_ELEMENTS = 10_000
"""Elements in a configuration file (set-up, pipeline); dumped programs pass their own bound."""
MAX_ATTRIBUTES = 64
"""Attributes of one element (no postproc element has a tenth of that): lxml reads attributes in
quadratic time, so 200,000 of them took minutes before any check could run."""
MAX_VALUE_CHARS = 1 << 20
"""Characters of one attribute value or text (a template renders at most as much)."""


def parse_xml_bytes(data: bytes, file: str, max_elements: int | None = None,
                    max_bytes: int | None = None) -> etree._Element:
    """Parse untrusted XML into an element, or raise a located ``ConfigError``.

    Bounded: ``MAX_XML_BYTES``, ``max_elements`` (default ``MAX_ELEMENTS``), ``MAX_ATTRIBUTES`` per
    element and ``MAX_VALUE_CHARS`` per value, so what reads the tree next does bounded work."""
    etree = lxml_etree()
    max_bytes = MAX_XML_BYTES if max_bytes is None else max_bytes
    if len(data) > max_bytes:
        raise ConfigError(f"XML file is larger than {max_bytes} bytes", Location(file, 1, 1))
    try:
        tree = etree.ElementTree(etree.fromstring(data, parser(), base_url=file))
    except etree.XMLSyntaxError as exc:
        line, col = exc.position if exc.position else (1, 1)
        msg = re.sub(_LIBXML_POSITION, "", exc.msg or "")  # the location already says where
        raise ConfigError(f"malformed XML: {msg}", Location(file, line or 1, max(col or 1, 1))) from None
    if tree.docinfo.doctype:
        where_ = _offset_location(data, data.find(b"<!DOCTYPE"), file)
        raise ConfigError("a DOCTYPE is not allowed in postproc XML", where_)
    root = tree.getroot()
    for el in root.iter():
        if isinstance(el, etree._Entity):
            raise ConfigError("entity references are not allowed", Location(file, el.sourceline or 1, 1))
    _check_bounds(root, file, MAX_ELEMENTS if max_elements is None else max_elements)
    return root


def _check_bounds(root: etree._Element, file: str, max_elements: int) -> None:
    """One linear pass: element count, attributes per element, length of every value and text."""
    count = 0
    for el in root.iter():
        count += 1
        if count > max_elements:
            raise ConfigError(f"more than {max_elements} XML elements", where(el, file))
        texts = [el.text, el.tail]
        if isinstance(el.tag, str):
            attrib = el.attrib
            if len(attrib) > MAX_ATTRIBUTES:
                raise ConfigError(f"<{el.tag}> has more than {MAX_ATTRIBUTES} attributes", where(el, file))
            texts.extend(attrib.values())
        if any(t is not None and len(t) > MAX_VALUE_CHARS for t in texts):
            raise ConfigError(f"a value or text longer than {MAX_VALUE_CHARS} characters", where(el, file))


_LIBXML_POSITION = r", line \d+, column \d+$"
"""Compiled where first used (an XML error), not at every start."""
"""libxml2 repeats the position at the end of its messages; its columns are already 1-based."""


def _offset_location(data: bytes, offset: int, file: str) -> Location:
    if offset < 0:
        return Location(file, 1, 1)
    line_start = data.rfind(b"\n", 0, offset) + 1
    return Location(file, data.count(b"\n", 0, offset) + 1, offset - line_start + 1)


def parse_xml_file(path: str | Path, max_elements: int | None = None,
                   max_bytes: int | None = None) -> etree._Element:
    """The XML file ``path``, named in its messages (and its elements' ``where``) as ``path_text`` spells it."""
    file = path_text(path)
    max_bytes = MAX_XML_BYTES if max_bytes is None else max_bytes
    try:
        with open(file, "rb") as f:
            data = f.read(max_bytes + 1)  # never more than the bound, whatever the file is
    except OSError as exc:
        raise ConfigError(f"cannot read {file}: {exc.strerror}", Location(file, 1, 1)) from None
    return parse_xml_bytes(data, file, max_elements, max_bytes)


def path_text(path: str | Path) -> str:
    """``str(pathlib.PurePath(path))``: the path without empty and ``.`` parts (``./m.xml`` is ``m.xml``, ``a//b/`` is
    ``a/b``), as the messages about a file have always named it, on the path's text where paths are POSIX ones: a
    set-up file's load (``postproc.setup.load``) makes no path object, as ``pathlib`` (with ``urllib.parse``,
    ``ipaddress`` and ``fnmatch``, which it imports) is no module a run needs otherwise. ``tests/test_setup_paths.py``
    holds it to ``PurePath`` on random paths."""
    text = os.fspath(path)
    if os.name != "posix":  # (drives, two separators: PurePath's own parsing)
        from pathlib import PurePath
        return str(PurePath(text))
    root = "//" if text.startswith("//") and not text.startswith("///") else "/" if text.startswith("/") else ""
    return root + "/".join(part for part in text.split("/") if part and part != ".") or "."


def to_bytes(el: etree._Element) -> bytes:
    """The canonical text of a postproc XML file: UTF-8, declaration, two-space indent."""
    etree = lxml_etree()
    etree.indent(el, space="  ")
    return bytes(etree.tostring(el, pretty_print=True, xml_declaration=True, encoding="UTF-8"))


def where(el: etree._Element, file: str | None = None) -> Location:
    """Location of an element for diagnostics (the file is stamped on the tree by ``XFactory.load``)."""
    src = file or el.getroottree().docinfo.URL or "<xml>"
    return Location(str(src), el.sourceline or 1, 1)


@mypyc_attr(allow_interpreted_subclasses=True)
class XFactory:
    """Maps element names to constructors. ``reg`` on a node class is idempotent; ``register_lazy``
    registers a name whose class is imported when first needed."""

    def __init__(self) -> None:
        self._ctors: dict[str, Callable[[etree._Element], Any]] = {}
        self._classes: dict[str, type] = {}
        self._lazy: dict[str, str] = {}
        """Element name -> ``"module:Class"`` registered by ``register_lazy``, not imported yet."""

    def register(self, cls: type["XmlNode"]) -> None:
        known = self._classes.get(cls.XNAME)
        if known is cls:
            return
        if known is not None:
            raise ConfigError(f"element name {cls.XNAME!r} registered twice ({known.__name__}, {cls.__name__})")
        lazy = self._lazy.get(cls.XNAME)
        if lazy is not None and lazy != _target_of(cls) and _import_target(lazy) is not cls:
            raise ConfigError(f"element name {cls.XNAME!r} registered twice ({lazy}, {cls.__name__})")
        self._lazy.pop(cls.XNAME, None)
        self._classes[cls.XNAME] = cls
        self._ctors[cls.XNAME] = cls.from_xml

    def register_lazy(self, xname: str, target: str) -> None:
        """Register the element name ``xname`` for the node class ``target`` (``"package.module:Class"``),
        imported only when an element of that name is created or the classes are listed: a plugin
        registers every name it has, and a run that reads none of them imports none of its modules
        (lexers, expression parsers, ...: a few ms of a short run's start-up per dialect). Idempotent;
        the class must have ``xname`` as its ``XNAME`` (checked when it is imported)."""
        known = self._classes.get(xname)
        if known is not None:
            if _target_of(known) != target and _import_target(target) is not known:
                raise ConfigError(f"element name {xname!r} registered twice ({known.__name__}, {target})")
            return
        lazy = self._lazy.get(xname)
        if lazy is not None and lazy != target:
            raise ConfigError(f"element name {xname!r} registered twice ({lazy}, {target})")
        self._lazy[xname] = target

    def _resolve(self, xname: str) -> None:
        """Import the class registered lazily under ``xname`` and register it."""
        target = self._lazy[xname]
        try:
            cls = _import_target(target)
        except (ImportError, AttributeError) as exc:
            raise ConfigError(f"<{xname}>: cannot import its class {target}: {exc}") from None
        if not (isinstance(cls, type) and issubclass(cls, XmlNode) and cls.XNAME == xname):
            raise ConfigError(f"<{xname}>: {target} is not an XML node class named {xname!r}")
        del self._lazy[xname]
        self.register(cls)

    def create(self, el: etree._Element) -> Any:
        tag = el.tag if isinstance(el.tag, str) else ""
        ctor = self._ctors.get(tag)
        if ctor is None and tag in self._lazy:
            try:
                self._resolve(tag)
            except ConfigError as err:
                raise ConfigError(err.message, where(el)) from None
            ctor = self._ctors.get(tag)
        if ctor is None:
            raise ConfigError(f"unknown element <{tag}>", where(el))
        try:
            return ctor(el)
        except ConfigError:
            raise
        except (ValueError, KeyError, TypeError) as exc:
            raise ConfigError(f"invalid <{tag}>: {exc}", where(el)) from None

    def children(self, el: etree._Element) -> Iterator[Any]:
        for child in el:
            if isinstance(child.tag, str):
                yield self.create(child)

    def names(self) -> list[str]:
        """Every registered element name (lazily registered ones too, without importing them)."""
        return sorted(set(self._classes) | set(self._lazy))

    def classes(self) -> list[type]:
        """Every registered class, in the order of their names (lazily registered ones are imported)."""
        for xname in list(self._lazy):
            self._resolve(xname)
        return [self._classes[n] for n in self.names()]


def _target_of(cls: type) -> str:
    return f"{cls.__module__}:{cls.__qualname__}"


def _import_target(target: str) -> Any:
    """The object ``"package.module:Name"`` names (an entry point's spelling)."""
    module, _, name = target.partition(":")
    found: Any = importlib.import_module(module)
    for part in name.split(".") if name else ():
        found = getattr(found, part)
    return found


DEFAULT = XFactory()


@mypyc_attr(allow_interpreted_subclasses=True)
class XAttr:
    """Declares one XML attribute of a node: Python name, type, optional default and XML name."""

    __slots__ = ("name", "kind", "default", "xml")

    def __init__(self, name: str, kind: type = str, default: Any = ..., xml: str | None = None) -> None:
        self.name = name
        self.kind = kind
        self.default = default
        self.xml = xml or name

    def parse(self, el: etree._Element) -> Any:
        raw = el.get(self.xml)
        if raw is None:
            computed = computed_value(el, self.xml)
            if computed is not None:
                return computed
            if self.default is ...:
                raise ConfigError(f"<{el.tag}> needs attribute {self.xml!r}", where(el))
            return self.default
        try:
            return decode(self.kind, raw)
        except ValueError:
            raise ConfigError(f"<{el.tag}> attribute {self.xml}={raw!r} is not a valid "
                              f"{self.kind.__name__}", where(el)) from None

    def emit(self, el: etree._Element, value: Any) -> None:
        if isinstance(value, XmlNode):  # a computed value (an expression kept symbolically)
            etree = lxml_etree()
            etree.SubElement(el, "Value", of=self.xml).append(value.make_xml_source())
            return
        if value is None or (self.default is not ... and value == self.default):
            return
        el.set(self.xml, encode(value))


def computed_value(el: etree._Element, name: str) -> Any:
    """The expression in ``el``'s child ``<Value of="name">``, or None: how a field that holds a number
    holds an expression instead (``<Feed><Value of="value"><Var>..</Var></Value></Feed>``)."""
    for child in el:
        if child.tag == "Value" and child.get("of") == name:
            kids = [c for c in child if isinstance(c.tag, str)]
            if len(kids) != 1:
                raise ConfigError(f"<Value of=\"{name}\"> holds exactly one expression", where(child))
            if _computed_reader is None:
                raise ConfigError("no expression reader is registered for <Value>", where(child))
            return _computed_reader(kids[0])
    return None


_computed_reader: Callable[[etree._Element], Any] | None = None
"""Reads the expression inside ``<Value>``: registered by ``postproc.ir.expr`` (the expressions know this
module, not the other way round)."""


def register_computed_value_reader(reader: Callable[[etree._Element], Any]) -> None:
    """Set how ``computed_value`` reads an expression element; idempotent."""
    global _computed_reader
    _computed_reader = reader


def decode(kind: type, raw: str) -> Any:
    if kind is bool:
        if raw not in ("true", "false"):
            raise ValueError(raw)
        return raw == "true"
    if kind is float:
        return float(raw)
    if kind is int:
        return int(raw)
    return raw


def encode(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


_STATE_NAMES: dict[type, tuple[str, ...]] = {}


def _state_names(cls: type) -> tuple[str, ...]:
    """The instance attributes of ``cls`` and its ancestors: their ``__slots__``, or for a class compiled
    with mypyc (which keeps no ``__slots__``) its ``__mypyc_attrs__``."""
    names = _STATE_NAMES.get(cls)
    if names is None:
        found: list[str] = []
        for klass in cls.__mro__:
            declared = klass.__dict__.get("__slots__", ())
            for name in ((declared,) if isinstance(declared, str) else tuple(declared)) + tuple(
                    klass.__dict__.get("__mypyc_attrs__", ())):
                if not name.startswith("__") and name not in found:
                    found.append(name)
        names = _STATE_NAMES[cls] = tuple(found)
    return names


def slot_state(obj: object) -> dict[str, Any]:
    """``__getstate__`` for slotted classes: copy and pickle see the same attributes whether a class and
    its ancestors run compiled or not (mypyc's own would drop an interpreted subclass's slots)."""
    state: dict[str, Any] = dict(getattr(obj, "__dict__", {}))
    state.update((name, getattr(obj, name)) for name in _state_names(type(obj)) if hasattr(obj, name))
    return state


def restore_slots(obj: object, state: dict[str, Any]) -> None:
    """``__setstate__`` matching ``slot_state``."""
    for name, value in state.items():
        setattr(obj, name, value)


# Every class of a compiled module carries allow_interpreted_subclasses (docs/compiled.md): plugins
# subclass them, and only then does mypyc create an instance without __init__ (copy, pickle).
@mypyc_attr(allow_interpreted_subclasses=True)
class XmlNode:
    """Base of every XML-serialisable object. Subclasses list their attributes as ``XAttr``s.

    Nodes with children override ``from_xml`` and ``make_xml_source``; simple nodes need neither.
    """

    XNAME: ClassVar[str] = ""
    __slots__ = ()

    XATTRS: ClassVar[tuple[XAttr, ...]] = ()
    """The node's attributes, in XML order; each is also a slot of the same name."""

    @classmethod
    def xattrs(cls) -> tuple[XAttr, ...]:
        return cls.XATTRS

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """Assign the declared attributes by position or name; hot-path nodes write their own."""
        attrs = self.XATTRS
        if len(args) > len(attrs):
            raise TypeError(f"{type(self).__name__} takes at most {len(attrs)} arguments")
        for attr, value in zip(attrs, args):
            setattr(self, attr.name, value)
        for attr in attrs[len(args):]:
            if attr.name in kwargs:
                setattr(self, attr.name, kwargs.pop(attr.name))
            elif attr.default is ...:
                raise TypeError(f"{type(self).__name__} needs {attr.name!r}")
            else:
                setattr(self, attr.name, attr.default)
        if kwargs:
            raise TypeError(f"{type(self).__name__} has no attribute(s) {sorted(kwargs)}")

    @classmethod
    def from_xml(cls: type[T], el: etree._Element) -> T:
        return cls(**{a.name: a.parse(el) for a in cls.xattrs()})

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        """Serialise to an element. ``base_dir``/``rel_file`` let nodes that own files store them
        relative to the configuration folder; ``exhibition_only`` suppresses writing such files."""
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        for attr in self.xattrs():
            attr.emit(el, self._xvalue(attr.name))
        return el

    def _xvalue(self, name: str) -> Any:
        return getattr(self, name)

    def __getstate__(self) -> dict[str, Any]:
        return slot_state(self)

    def __setstate__(self, state: dict[str, Any]) -> None:
        restore_slots(self, state)

    @classmethod
    def reg(cls, factory: XFactory | None = None) -> None:
        """Register this class's constructor with ``factory`` (the default one if None). Idempotent."""
        (factory or DEFAULT).register(cls)

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash((type(self), repr(self._key())))

    def _key(self) -> tuple[Any, ...]:
        return tuple(getattr(self, a.name) for a in self.xattrs())

    def __repr__(self) -> str:
        inner = ", ".join(f"{a.name}={getattr(self, a.name)!r}" for a in self.xattrs())
        return f"{type(self).__name__}({inner})"


T = TypeVar("T", bound=XmlNode)
"""(After the class, bound to it as a class: a bound given by its name is a ``ForwardRef``, which compiles the name
with the interpreter's compiler at import, ~2M instructions of every start.)"""
