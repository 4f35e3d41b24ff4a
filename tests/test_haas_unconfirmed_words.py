"""Two words of CadeKiely's Haas mill programs whose meaning on a Haas is not in our sources (issue 26, held26;
tests/heldout/README.md, "Refusals left"), refused by name and located under the Haas variant as under plain
Fanuc, never read by a guess:

* a drilling cycle without R (``G82 Z-0.12 F10.``): the Haas manual marks R optional [V: Haas G82 page] without
  saying which level the control then takes [?];
* S with a decimal point (``S5000.``): a Fanuc alarm [K: B-64114EN/01 8.3]; a Haas [?].

The same blocks with R, and with S written whole, translate: the refusal is the word's, not the program's.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup

SETUPS = Path(__file__).resolve().parent / "heldout" / "setups"
HEAD = "%\nO1\nG00 G17 G40 G49 G54 G80 G90 G98\nT8 M06\nG43 H08 Z1.\n"


def _translate(text: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="linuxcnc", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, setup: MachineSetup) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, setup)
    return [str(e) for e in caught.value.errors]


@pytest.fixture(params=["haas", "fanuc"])
def setup(request: pytest.FixtureRequest) -> MachineSetup:
    haas = load_setup(SETUPS / "haas_mill.xml")
    if request.param == "fanuc":
        haas.controller.variant = "fanuc"
    return haas


def test_a_cycle_without_r_is_refused_by_name_at_its_block(setup: MachineSetup) -> None:
    text = HEAD + "S4000 M03\nX0.15 Y-.25\nG82 Z-0.12 F10.\nX3.85\nG80\nM30\n%\n"
    assert _errors(text, setup)[0] == "in.nc:8:1: error: G82 needs an R level R"
    assert "G82" in _translate(text.replace("G82 Z-0.12 F10.", "G82 Z-0.12 R0.1 F10."), setup)


def test_s_with_a_decimal_point_is_refused_by_name_where_it_is_written(setup: MachineSetup) -> None:
    text = HEAD + "S5000. M03\nX0.15 Y-.25\nG01 Z-0.1 F10.\nM30\n%\n"
    assert _errors(text, setup) == ["in.nc:6:1: error: address S takes no decimal point (S5000.)"]
    assert "S5000" in _translate(text.replace("S5000.", "S5000"), setup)
