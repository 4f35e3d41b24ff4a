"""Defects: a Fanuc program that cancels its tool length (``G49``) before ``M30``, the common ending, was refused
for ISG, Fagor and SINUMERIK ("the new tool length is applied only at a move of Z ... program the length offset
beside a Z move"), though no axis moves after it: where the new length would apply never comes.

The change is now checked where it matters, at the next block that moves: there it must move Z absolutely
(where both controllers apply it), or the translation fails, located at the change, as before.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines

VMC = load_setup(Path(__file__).resolve().parent.parent / "examples" / "setups" / "fanuc_0i_mf_vmc.xml")
HEAD = ("%\nO1000\nG21 G90 G17 G94 G40 G49 G80\nG54\nT1 M06\nG43 H1 Z50.\nG00 X0. Y0.\nG01 Z-5. F200.\n"
        "G00 Z50.\n")


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target=target, setup=VMC,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("target", ["isg", "fagor", "siemens"])
@pytest.mark.parametrize("ending", ["G49\nM30\n%\n", "G49 M30\n%\n", "G91 G28 Z0.\nG49\nM30\n%\n",
                                    "G49\nG00 Z60.\nM30\n%\n"])
def test_a_length_cancelled_where_nothing_or_z_moves_next_translates_and_verifies(target: str, ending: str) -> None:
    source = HEAD + ending
    out = _translate(source, target)
    report = verify_lines(io.StringIO(source), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target=target, setup=VMC)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


def test_a_length_cancelled_before_a_move_without_z_gets_the_z_it_stands_at_towards_fagor() -> None:
    """Fanuc applies the cancel at the X move (the simulation's model), Fagor only when Z moves [V: Fagor 8055
    programming manual 8.2]: the X move gets the Z the program stands at (50, from ``G00 Z50.`` in HEAD), so the
    Fagor's Z moves there and applies it (``Fagor.LENGTH_AT_AXIS_MOVE``). Until issue 26 (held26) this was refused."""
    source = HEAD + "G49\nG00 X10.\nM30\n%\n"
    out = _translate(source, "fagor")
    assert "G44 G00 X10. Z50." in out.splitlines(), out
    report = verify_lines(io.StringIO(source), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target="fagor", setup=VMC)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


def test_a_length_cancelled_before_a_move_without_z_is_refused_where_z_is_not_known() -> None:
    """A length change before any Z was programmed: the programmed Z is not known, so no Z can be written beside
    the X move that applies it on Fanuc: a located error at the change."""
    with pytest.raises(ErrorList) as caught:
        _translate("%\nO1000\nG21 G90 G49\nG54\nT1 M06\nG43 H1\nG00 X0. Y0.\nM30\n%\n", "fagor")
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:6:5: error: this tool length change applies at the next move on the source's controller and only "
        "when Z next moves on the target's, and the programmed Z is not known where it applies: program Z beside "
        "the length change"]
