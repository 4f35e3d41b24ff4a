"""Defects: with travel limits in the set-up, a move in machine coordinates under a tool length offset (Fanuc
``G53 Z0.`` after ``G43 H1``, ISG ``#SUPPRESS OFFSETS Z0.`` under ``D1``) was refused ("the travel of Z cannot be
checked: ... controllers differ"), so Fanuc -> ISG of a valid program failed before anything was written.

The move's value is the machine position whatever the tool: Fanuc cancels the length offset vector of the axis
for a G53 move [K: Fanuc 0i-MB operator's manual B-63844EN/02 14.1.2], ISG's ``#SUPPRESS OFFSETS`` suppresses
every offset, and the simulation already moves the controlled point there. The travel check now takes it so.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

VMC = load_setup(Path(__file__).resolve().parent.parent / "examples" / "setups" / "fanuc_0i_mf_vmc.xml")
"""Travel X -800..0, Y -500..0, Z -500..0; G54 at X-400 Y-250 Z-350; H1 120 mm."""


def program(retract: str) -> str:
    return ("%\nO1000\nG21 G90 G17 G94 G40 G49 G80\nG54\nT1 M06\nG43 H1 Z50.\nG00 X0. Y0.\nG01 Z-5. F200.\n"
            f"G01 X20.\nG00 Z50.\n{retract}\nM30\n%\n")


def lines(text: str) -> list[str]:
    return text.splitlines(keepends=True)


def to_isg(text: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="isg", setup=VMC,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def test_g53_under_a_length_offset_translates_to_isg_and_verifies() -> None:
    source = program("G53 Z0.")
    out = to_isg(source)
    assert "#SUPPRESS OFFSETS Z0." in out.splitlines()
    report = verify_lines(lines(source), lines(out), file_in="in.nc", file_out="out.nc", source="fanuc",
                          target="isg", setup=VMC)
    assert report.ok and report.max_deviation == 0, report.summary()
    # the ISG program runs within the travel too: its spindle goes to machine Z0, the tip 120 mm below; the
    # toolpath gives both in the work frame (G54 Z-350, as rs274 gives a machine move): tip 230, spindle 350
    events = list(toolpath_events(lines(out), file="out.nc", dialect="isg", setup=VMC))
    last = [ev for ev in events if "move" in ev][-1]
    assert (last["z"], last["controlled"]["z"]) == (-120 + 350, 0 + 350)


def test_a_machine_move_beyond_the_travel_under_a_length_offset_is_still_refused() -> None:
    # machine Z 5 is 5 beyond the limit 0, whatever the 120 mm tool
    with pytest.raises(ErrorList) as caught:
        to_isg(program("G53 Z5."))
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:11:5: error: Z+5.000 mm beyond the limit 0.000 (machine Z 5.000)"]
