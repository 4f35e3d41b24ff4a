"""Defects: a long chain of operators (``#1=1+1+...+1``, 20,000 terms) passed every reader's nesting bound
(brackets and signs are counted, a chain is built in a loop) and then exhausted Python's stack where the
expression is folded, evaluated or written: "internal error: RecursionError", no location, in every dialect
with expressions. Each operator of a chain is now one level, and a reader refuses an expression deeper than
the 200 levels the XML reader takes (``postproc.ir.expr.nests_deeper``), at the expression's first character.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events

PROGRAMS = {
    "fanuc": ("O1\n#1={chain}\nG1 X#1 F100.\nM30\n", "in.nc:2:4"),
    "linuxcnc": ("#1=[{chain}]\nG1 X#1 F100\nM30\n", "in.nc:1:4"),
    "isg": ("%1\nP1={chain}\nG1 X=P1 F100\nM30\n", "in.nc:2:4"),
    "fagor": ("P1={chain}\nG1 X=P1 F100\nM30\n", "in.nc:1:4"),
    "siemens": ("%_N_A_MPF\nR1={chain}\nG1 X=R1 F100\nM30\n", "in.nc:2:4"),
}
MESSAGE = "error: expression nested deeper than 200 levels (each operator of a chain counts one)"


def chain(terms: int) -> str:
    return "+".join(["1"] * terms)


def moves(text: str, dialect: str) -> list[dict[str, object]]:
    events = toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect)
    return [ev for ev in events if "move" in ev]


@pytest.mark.parametrize("dialect", sorted(PROGRAMS))
def test_a_chain_of_20000_terms_is_a_located_error(dialect: str) -> None:
    template, where = PROGRAMS[dialect]
    text = template.format(chain=chain(20000))
    with pytest.raises(ErrorList) as caught:
        moves(text, dialect)
    assert [str(e) for e in caught.value.errors] == [f"{where}: {MESSAGE}"]
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(text), io.StringIO(), file="in.nc", source=dialect, target="grbl",
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert [str(e) for e in caught.value.errors] == [f"{where}: {MESSAGE}"]


@pytest.mark.parametrize("dialect", sorted(PROGRAMS))
def test_a_chain_of_200_levels_still_runs(dialect: str) -> None:
    """199 additions of 1 to 1: X200 (mm), and one more term is refused."""
    template, where = PROGRAMS[dialect]
    assert [ev["x"] for ev in moves(template.format(chain=chain(200)), dialect)] == [200]
    with pytest.raises(ErrorList):
        moves(template.format(chain=chain(201)), dialect)
