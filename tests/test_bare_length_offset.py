"""G43/G44 without an offset register H in the Fanuc family (issue 26: Fusion 360's Haas Desktop Mill post
writes ``G0 G43 Z0.5906``). The register it takes is the one in force, the H last programmed [K: Fanuc];
with no H before it only the machine knows it, and a reader that does not carry the register over says
so: both are located errors naming the case, never a silent zero offset."""

from __future__ import annotations

import io

import pytest

from postproc.errors import ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from pathlib import Path

HAAS = Path(__file__).resolve().parent / "heldout" / "setups" / "haas_mill.xml"


def _errors(text: str, haas: bool) -> list[str]:
    setup = load_setup(HAAS) if haas else None
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(text), file="t.nc", dialect="fanuc", setup=setup))
    return [str(e) for e in info.value.errors]


@pytest.mark.parametrize("haas", [False, True])
def test_no_h_before_is_the_machines_register(haas: bool) -> None:
    text = "G20 G90 G17\nG0 X1. Y1.\nG0 G43 Z0.5906\nM30\n"
    assert _errors(text, haas) == [
        "t.nc:3:4: error: G43 without an offset register H, and no H programmed before it: the register in "
        "force is the machine's, known only to it (program G43 H..)"]


@pytest.mark.parametrize("code", ["G43", "G44"])
def test_an_earlier_h_is_named_and_not_guessed(code: str) -> None:
    """H0 was programmed: the bare code would take it, but a program that jumps may run another H last."""
    text = f"G21 G90 G17\nG0 G43 Z50. H0\nG49\nG0 {code} Z50.\nM30\n"
    assert _errors(text, False) == [
        f"t.nc:4:4: error: {code} without an offset register H: it takes the H last programmed, which this "
        f"reader does not carry over (write the H in this block)"]
