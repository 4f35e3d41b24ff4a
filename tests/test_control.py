"""Control-flow sections: what their XML refuses (the round trips are in ``test_ir_xml.py``)."""

from __future__ import annotations

import pytest

from postproc.interp.control import ASSIGN, CONTROL, Assign, Call, Goto, While, register_control
from postproc.errors import ConfigError
from postproc.ir.expr import Num, Var, register_expressions
from postproc.ir import Block
from postproc.xmlio import XFactory, parse_xml_bytes


@pytest.fixture
def factory() -> XFactory:
    f = XFactory()
    register_expressions(f)
    register_control(f)
    register_control(f)  # idempotent
    return f


BAD = [
    ('<While label="1"/>', "<While> needs a <Cond> expression", 1),
    ('<While label="1">\n<Cond/>\n</While>', "<Cond> holds exactly one expression", 2),
    ('<While>\n<Cond><Num value="1.0"/></Cond>\n</While>', "<While> needs attribute 'label'", 1),
    ('<Goto>\n<Target><Num value="1.0"/></Target>\n<Target><Num value="2.0"/></Target>\n</Goto>',
     "<Goto> has more than one <Target>", 3),
    ('<Goto>\n<Where/>\n</Goto>', "unknown element <Where> in <Goto>", 2),
    ('<Goto>\n<Target><Motion/></Target>\n</Goto>', "<Motion> is not an expression", 2),
    ('<Assign/>', "<Assign> needs at least one <Set>", 1),
    ('<Assign>\n<Set><Num value="1.0"/><Num value="2.0"/></Set>\n</Assign>',
     "<Set> assigns to a variable, not <Num>", 2),
    ('<Assign>\n<Set><Var name="a"/></Set>\n</Assign>', "<Set> holds a variable and an expression", 2),
    ('<Call kind="sub"/>', "<Call> needs a name attribute or a <Name> expression (one of them)", 1),
    ('<Call name="1">\n<Arg n="0"><Num value="1.0"/></Arg>\n</Call>',
     "<Arg> needs a local variable number n (1 or more)", 2),
    ('<Call name="1">\n<Arg n="1"><Num value="1.0"/></Arg>\n<Arg n="1"><Num value="1.0"/></Arg>\n</Call>',
     '<Arg n="1"> appears twice', 3),
    ('<Call name="1" kind="jump"/>', "invalid <Call>: unknown call kind 'jump' (sub or macro)", 1),
    ('<IfThen>\n<Cond><Num value="1.0"/></Cond>\n</IfThen>', "<IfThen> needs exactly one <Assign>", 1),
]


@pytest.mark.parametrize("xml, message, line", BAD, ids=[m for _, m, _ in BAD])
def test_bad_control_xml_is_a_located_error(factory, xml, message, line):
    with pytest.raises(ConfigError) as info:
        factory.create(parse_xml_bytes(xml.encode(), "c.xml"))
    assert info.value.message == message
    assert (info.value.location.file, info.value.location.line) == ("c.xml", line)


def test_sections_sit_under_their_keys():
    block = Block(1, None)
    block.add(Assign([(Var(Num(1.0)), Num(2.0))]))
    block.add(While("1", Num(1.0)))
    assert list(block.sections) == [ASSIGN, CONTROL]
    block.add(Goto(Num(5.0)))  # one control statement per block: the last one stays
    assert isinstance(block.get(CONTROL), Goto)


def test_a_block_with_control_sections_round_trips(factory):
    block = Block(4, "#1=2 WHILE[#1LT10]DO1", words=[])
    block.add(Assign([(Var(Num(1.0)), Num(2.0))]))
    block.add(While("1", Num(1.0)))
    again = Block.from_xml(block.make_xml_source(), factory)
    assert again == block


def test_calls_compare_by_content():
    assert Call("1", {1: Num(1.0)}) == Call("1", {1: Num(1.0)})
    assert Call("1", {1: Num(1.0)}) != Call("1", {1: Num(1.0)}, kind="macro")
    assert Call("1") != Call(Num(1.0))
