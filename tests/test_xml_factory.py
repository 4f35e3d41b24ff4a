"""The XML layer: the one safe parser, the factory registry, XAttr descriptors and XmlNode."""

from __future__ import annotations

import importlib
import sys

import pytest
from lxml import etree

from postproc import xmlio
from postproc.errors import ConfigError
from postproc.ir import Feed, Motion, Sequence, register_sections
from postproc.xmlio import XAttr, XFactory, XmlNode, decode, encode, parse_xml_bytes, parse_xml_file, to_bytes


class Probe(XmlNode):
    """A node with one attribute of each kind."""

    XNAME = "Probe"
    XATTRS = (XAttr("name"), XAttr("count", int, 0), XAttr("scale", float, 1.0), XAttr("on", bool, False),
              XAttr("label", str, None, xml="display-label"))
    __slots__ = tuple(a.name for a in XATTRS)


class OtherProbe(XmlNode):
    XNAME = "Probe"
    __slots__ = ()


@pytest.fixture
def factory() -> XFactory:
    f = XFactory()
    Probe.reg(f)
    return f


def _el(text: str) -> etree._Element:
    return parse_xml_bytes(text.encode(), "probe.xml")


# -- the factory ---------------------------------------------------------------------------------------

def test_reg_is_idempotent(factory):
    Probe.reg(factory)
    Probe.reg(factory)
    assert factory.names() == ["Probe"]
    assert factory.classes() == [Probe]


def test_two_classes_cannot_share_an_element_name(factory):
    with pytest.raises(ConfigError, match="'Probe' registered twice"):
        OtherProbe.reg(factory)


def test_a_fresh_factory_knows_nothing():
    assert XFactory().names() == []
    with pytest.raises(ConfigError, match=r"unknown element <Sequence>"):
        XFactory().create(_el('<Sequence number="1"/>'))


def test_register_sections_fills_a_fresh_factory_without_touching_the_default():
    f = XFactory()
    register_sections(f)
    register_sections(f)
    assert f.create(_el('<Sequence number="5"/>')) == Sequence(5)
    assert "Sequence" in f.names() and "Probe" not in f.names()


def test_unknown_element_is_a_located_error(factory):
    root = _el('<Root>\n  <Probe name="a"/>\n  <Nope/>\n</Root>')
    with pytest.raises(ConfigError) as info:
        list(factory.children(root))
    assert info.value.message == "unknown element <Nope>"
    assert str(info.value.location) == "probe.xml:3:1"


def test_children_skip_comments_and_processing_instructions(factory):
    root = _el('<Root><!-- note --><?pi x?><Probe name="a"/></Root>')
    assert list(factory.children(root)) == [Probe("a")]


# -- XAttr --------------------------------------------------------------------------------------------

def test_xattr_parse_with_defaults(factory):
    assert factory.create(_el('<Probe name="a"/>')) == Probe("a", 0, 1.0, False, None)


def test_xattr_parse_every_kind(factory):
    probe = factory.create(_el('<Probe name="a" count="3" scale="0.25" on="true" display-label="L"/>'))
    assert (probe.name, probe.count, probe.scale, probe.on, probe.label) == ("a", 3, 0.25, True, "L")


def test_xattr_emit_skips_defaults_and_none():
    assert to_bytes(Probe("a").make_xml_source()) == b"<?xml version='1.0' encoding='UTF-8'?>\n<Probe name=\"a\"/>\n"
    el = Probe("a", 2, 0.5, True, "x").make_xml_source()
    assert dict(el.attrib) == {"name": "a", "count": "2", "scale": "0.5", "on": "true", "display-label": "x"}


@pytest.mark.parametrize("xml, message", [
    ("<Probe/>", "<Probe> needs attribute 'name'"),
    ('<Probe name="a" count="two"/>', "<Probe> attribute count='two' is not a valid int"),
    ('<Probe name="a" count="1.5"/>', "<Probe> attribute count='1.5' is not a valid int"),
    ('<Probe name="a" scale="wide"/>', "<Probe> attribute scale='wide' is not a valid float"),
    ('<Probe name="a" on="yes"/>', "<Probe> attribute on='yes' is not a valid bool"),
    ('<Probe name="a" on="True"/>', "<Probe> attribute on='True' is not a valid bool"),
])
def test_xattr_errors_are_located(factory, xml, message):
    with pytest.raises(ConfigError) as info:
        factory.create(_el(xml))
    assert info.value.message == message
    assert str(info.value.location) == "probe.xml:1:1"


@pytest.mark.parametrize("kind, raw, value", [
    (int, "42", 42), (int, "-7", -7), (float, "0.1", 0.1), (float, "-0.0", -0.0), (bool, "true", True),
    (bool, "false", False), (str, " x ", " x "),
])
def test_decode(kind, raw, value):
    assert decode(kind, raw) == value
    assert type(decode(kind, raw)) is kind


@pytest.mark.parametrize("value, text", [
    (True, "true"), (False, "false"), (3, "3"), (0.1 + 0.2, "0.30000000000000004"), (1e-7, "1e-07"), ("s", "s"),
])
def test_encode_keeps_every_digit(value, text):
    assert encode(value) == text
    assert decode(type(value), text) == value


# -- XmlNode ------------------------------------------------------------------------------------------

def test_node_init_by_position_and_name():
    assert Probe("a", count=2) == Probe("a", 2)
    assert Probe(name="a").count == 0


@pytest.mark.parametrize("args, kwargs, message", [
    ((), {}, "Probe needs 'name'"),
    (("a", 1, 2.0, True, "l", "extra"), {}, "Probe takes at most 5 arguments"),
    (("a",), {"colour": "red"}, "Probe has no attribute(s) ['colour']"),
])
def test_node_init_errors(args, kwargs, message):
    with pytest.raises(TypeError, match=message.replace("(", r"\(").replace(")", r"\)").replace("[", r"\[")):
        Probe(*args, **kwargs)


def test_node_equality_and_hash():
    assert Probe("a") == Probe("a") and hash(Probe("a")) == hash(Probe("a"))
    assert Probe("a") != Probe("b")
    assert Feed(1.0) != Sequence(1)
    assert len({Feed(1.0), Feed(1.0), Feed(2.0)}) == 2
    assert repr(Probe("a")) == "Probe(name='a', count=0, scale=1.0, on=False, label=None)"


def test_constructor_errors_become_located_config_errors():
    f = XFactory()
    Motion.reg(f)
    with pytest.raises(ConfigError) as info:
        f.create(_el('<Motion mode="rapid">\n  <Axes X="far"/>\n</Motion>'))
    assert info.value.message.startswith("invalid <Motion>: ")
    assert info.value.location.line == 1


# -- the parser ---------------------------------------------------------------------------------------

def test_canonical_text():
    root = etree.Element("Root")
    etree.SubElement(etree.SubElement(root, "A", x="1"), "B")
    assert to_bytes(root) == (b"<?xml version='1.0' encoding='UTF-8'?>\n"
                              b'<Root>\n  <A x="1">\n    <B/>\n  </A>\n</Root>\n')


def test_parse_keeps_the_file_name_for_locations():
    root = parse_xml_bytes(b"<Root>\n\n  <Child/>\n</Root>", "some/where.xml")
    assert str(xmlio.where(root[0])) == "some/where.xml:3:1"


@pytest.mark.parametrize("data, fragment, line, col", [
    # libxml2's own wording (a fragment of it); the column is libxml2's, 1-based: where it stopped reading
    (b"<Root>\n<Child x=1/></Root>", "AttValue", 2, 10),
    (b"<Root>\n  <A></B>\n</Root>", "Opening and ending tag mismatch: A line 2 and B", 2, 10),
    (b"<Root>", "Premature end of data in tag Root", 1, 7),
    (b"", "Document is empty", 1, 1),
    (b"not xml", "Start tag expected", 1, 1),
    (b"<Root>&undefined;</Root>", "Entity 'undefined' not defined", 1, 18),
])
def test_malformed_xml_is_located(data, fragment, line, col):
    with pytest.raises(ConfigError) as info:
        parse_xml_bytes(data, "bad.xml")
    assert info.value.message.startswith("malformed XML: ")
    assert fragment in info.value.message
    assert ", line " not in info.value.message  # the location says where, once
    assert (info.value.location.line, info.value.location.col) == (line, col)


BILLION_LAUGHS = b"""<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
]>
<Root name="&lol3;"/>
"""

EXTERNAL_ENTITY = b"""<?xml version="1.0"?>
<!DOCTYPE Root [ <!ENTITY secret SYSTEM "file:///etc/passwd"> ]>
<Root>&secret;</Root>
"""

EXTERNAL_DTD = b"""<?xml version="1.0"?>
<!DOCTYPE Root SYSTEM "http://example.invalid/evil.dtd">
<Root/>
"""


@pytest.mark.parametrize("data", [BILLION_LAUGHS, EXTERNAL_ENTITY, EXTERNAL_DTD], ids=["billion_laughs",
                                                                                     "external_entity",
                                                                                     "external_dtd"])
def test_doctype_is_refused_at_its_line(data):
    with pytest.raises(ConfigError) as info:
        parse_xml_bytes(data, "evil.xml")
    assert info.value.message == "a DOCTYPE is not allowed in postproc XML"
    assert (info.value.location.line, info.value.location.col) == (2, 1)
    assert "root:" not in str(info.value)


def test_entities_are_never_expanded():
    """Even below the DOCTYPE check, the parser itself resolves nothing."""
    root = etree.fromstring(EXTERNAL_ENTITY, xmlio.parser())
    assert "root:" not in etree.tostring(root).decode()


def test_size_limit(monkeypatch):
    monkeypatch.setattr(xmlio, "MAX_XML_BYTES", 10)
    with pytest.raises(ConfigError, match="larger than 10 bytes"):
        parse_xml_bytes(b"<Root>0123456789</Root>", "big.xml")


def test_missing_file_is_a_located_error(tmp_path):
    with pytest.raises(ConfigError) as info:
        parse_xml_file(tmp_path / "missing.xml")
    assert info.value.message.startswith("cannot read ")
    assert info.value.location.file == str(tmp_path / "missing.xml")


# -- names registered lazily (a plugin's syntax objects, imported when first used) ----------------------

LAZY_MODULE = '''
from postproc.xmlio import XAttr, XmlNode

class Chirp(XmlNode):
    XNAME = "Chirp"
    XATTRS = (XAttr("pitch", int),)
    __slots__ = ("pitch",)

class Misnamed(XmlNode):
    XNAME = "Other"
    __slots__ = ()
'''


@pytest.fixture
def lazy_module(tmp_path, monkeypatch) -> str:
    """A module of node classes that nothing has imported yet."""
    name = f"lazy_nodes_{tmp_path.name.replace('-', '_')}"
    (tmp_path / f"{name}.py").write_text(LAZY_MODULE)
    monkeypatch.syspath_prepend(str(tmp_path))
    yield name
    sys.modules.pop(name, None)


def test_a_lazy_name_is_known_before_its_module_is_imported(lazy_module):
    f = XFactory()
    f.register_lazy("Chirp", f"{lazy_module}:Chirp")
    f.register_lazy("Chirp", f"{lazy_module}:Chirp")  # idempotent
    assert f.names() == ["Chirp"] and lazy_module not in sys.modules
    with pytest.raises(ConfigError, match="unknown element <Nope>"):
        f.create(_el("<Nope/>"))
    assert lazy_module not in sys.modules
    chirp = f.create(_el('<Chirp pitch="440"/>'))
    assert type(chirp).__module__ == lazy_module and chirp.pitch == 440
    assert f.classes() == [sys.modules[lazy_module].Chirp]


def test_listing_the_classes_imports_the_lazy_ones(lazy_module):
    f = XFactory()
    Probe.reg(f)
    f.register_lazy("Chirp", f"{lazy_module}:Chirp")
    assert [c.XNAME for c in f.classes()] == ["Chirp", "Probe"] and lazy_module in sys.modules


def test_a_lazy_name_and_its_class_registered_again_is_harmless(lazy_module):
    f = XFactory()
    f.register_lazy("Chirp", f"{lazy_module}:Chirp")
    module = importlib.import_module(lazy_module)
    module.Chirp.reg(f)
    f.register_lazy("Chirp", f"{lazy_module}:Chirp")
    assert f.classes() == [module.Chirp]


def test_a_lazy_name_cannot_be_taken_twice(lazy_module):
    f = XFactory()
    f.register_lazy("Probe", f"{lazy_module}:Chirp")
    with pytest.raises(ConfigError, match="'Probe' registered twice"):
        f.register_lazy("Probe", "elsewhere:Probe")
    with pytest.raises(ConfigError, match="'Probe' registered twice"):
        Probe.reg(f)  # another class of that name
    g = XFactory()
    Probe.reg(g)
    with pytest.raises(ConfigError, match="'Probe' registered twice"):
        g.register_lazy("Probe", f"{lazy_module}:Chirp")


@pytest.mark.parametrize("target, says", [
    ("no_such_module_anywhere:Chirp", "<Chirp>: cannot import its class no_such_module_anywhere:Chirp"),
    ("{module}:Nothing", "<Chirp>: cannot import its class {module}:Nothing"),
    ("{module}:Misnamed", "<Chirp>: {module}:Misnamed is not an XML node class named 'Chirp'"),
])
def test_a_lazy_name_whose_class_cannot_be_had_is_a_located_error(lazy_module, target, says):
    f = XFactory()
    f.register_lazy("Chirp", target.format(module=lazy_module))
    with pytest.raises(ConfigError) as info:
        f.create(_el('<Root>\n  <Chirp pitch="1"/>\n</Root>')[0])
    assert info.value.message.startswith(says.format(module=lazy_module))
    assert str(info.value.location) == "probe.xml:2:1"
