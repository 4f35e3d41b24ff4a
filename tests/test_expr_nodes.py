"""Expression nodes: construction rules, equality, and the XML round trip through the factory."""

from __future__ import annotations

import pytest
from lxml import etree

from postproc.errors import ConfigError
from postproc.ir.expr import Binary, Func, Num, Unary, Var, expr_from_xml, register_expressions
from postproc.xmlio import XFactory, parse_xml_bytes

TREES = [
    Num(1.5),
    Var(Num(1.0)),
    Var(name="_global"),
    Var(Binary("add", Var(Num(2.0)), Num(1.0))),
    Unary("neg", Var(Num(3.0))),
    Binary("mul", Var(Num(1.0)), Func("cos", [Var(Num(5.0))])),
    Func("atan2_360", [Num(1.0), Unary("neg", Num(1.0))]),
    Binary("ne_tol", Func("exists", [Var(name="depth")]), Num(0.0)),
]


@pytest.mark.parametrize("tree", TREES, ids=repr)
def test_tree_round_trips_through_a_fresh_factory(tree: object) -> None:
    factory = XFactory()
    register_expressions(factory)
    register_expressions(factory)  # idempotent
    el = tree.make_xml_source()  # type: ignore[attr-defined]
    text = etree.tostring(el)
    back = factory.create(parse_xml_bytes(text, "t.xml"))
    assert back == tree
    assert hash(back) == hash(tree)
    assert etree.tostring(back.make_xml_source()) == text


def test_xml_spelling_is_pinned() -> None:
    el = Binary("add", Var(Num(1.0)), Var(name="depth")).make_xml_source()
    assert etree.tostring(el) == (b'<Binary op="add"><Var><Num value="1.0"/></Var>'
                                  b'<Var name="depth"/></Binary>')


def test_equality_tells_trees_apart() -> None:
    assert Var(Num(1.0)) != Var(Num(2.0))
    assert Binary("add", Num(1.0), Num(2.0)) != Binary("sub", Num(1.0), Num(2.0))
    assert Func("trunc", [Num(1.0)]) != Func("floor", [Num(1.0)])


@pytest.mark.parametrize("xml, message", [
    (b'<Binary op="add"><Num value="1"/></Binary>', "<Binary> needs exactly two operands"),
    (b'<Binary op="plus"><Num value="1"/><Num value="2"/></Binary>', "invalid <Binary>: unknown binary operator 'plus'"),
    (b'<Func name="sin"/>', "invalid <Func>: function 'sin' takes 1 argument(s), not 0"),
    (b'<Var name="a"><Num value="1"/></Var>', "<Var> has either a name or an index expression, not both"),
    (b'<Unary op="neg"><Feed/></Unary>', "<Feed> is not an expression"),
    (b'<Num/>', "<Num> needs attribute 'value'"),
])
def test_bad_xml_is_a_located_config_error(xml: bytes, message: str) -> None:
    with pytest.raises(ConfigError) as info:
        expr_from_xml(parse_xml_bytes(xml, "bad.xml"))
    assert info.value.message == message
    assert str(info.value.location) == "bad.xml:1:1"


def test_constructor_refuses_a_variable_with_both_number_and_name() -> None:
    with pytest.raises(ValueError):
        Var(Num(1.0), name="x")
    with pytest.raises(ValueError):
        Var()
