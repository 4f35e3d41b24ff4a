"""GSK 980TDc: a first line ``%<title>`` (issue 29, defects). Fanuc's control skips what follows the first
``%`` (``TapeMark.title``, tests/test_fanuc_leader_title.py); whether the 980TDc does is not confirmed [?: its
manual was not reached, DIALECTS.md 1.2]. Before, the GSK reader refused the line ("'%' must stand alone on its
line"), so a GSK program carrying one could not even be copied. Now it is kept verbatim for GSK (a copy is byte
for byte, the simulation passes it as the control would skip it) and refused by name for every other target.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from pathlib import Path

SETUP = Path(__file__).resolve().parent.parent / "examples" / "setups" / "gsk_980tdc.xml"
PROGRAM = "%O1200(TOKARKA)\nG0 X10. Z5.\nG1 X20. Z-5. F0.2\nM30\n%\n"
WHAT = "a title after the first '%' (whether the GSK 980TDc skips it, as Fanuc does, is not confirmed)"


def _translate(text: str, target: str, normalize: bool = False) -> str:
    out = io.StringIO()
    setup = load_setup(str(SETUP))
    setup.output.normalize = normalize
    translate(io.StringIO(text), out, file="in.nc", source="gsk", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("normalize", [False, True])
def test_a_copy_to_gsk_keeps_the_title_verbatim(normalize: bool) -> None:
    assert _translate(PROGRAM, "gsk", normalize).splitlines()[0] == "%O1200(TOKARKA)"


def test_the_simulation_passes_the_title() -> None:
    events = list(toolpath_events(io.StringIO(PROGRAM), file="in.nc", dialect="gsk", setup=load_setup(str(SETUP))))
    assert [ev.get("line") for ev in events if "move" in ev] == [2, 3]


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
def test_another_target_refuses_the_title_by_name(target: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(PROGRAM, target)
    assert [str(e) for e in caught.value.errors] == [f"in.nc:1:1: error: {WHAT} from gsk has no equivalent in {target}"]


def test_a_bare_percent_and_a_later_titled_one_read_as_before() -> None:
    assert _translate(PROGRAM.replace("%O1200(TOKARKA)", "%"), "fanuc").splitlines()[0] == "%"
    with pytest.raises(ErrorList) as caught:
        read_program(io.StringIO("G0 X10. Z5.\n%END\n"), file="in.nc", dialect="gsk", setup=load_setup(str(SETUP)))
    assert "'%' must stand alone on its line" in str(caught.value.errors[0])
