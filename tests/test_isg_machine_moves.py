"""Fanuc reference returns and G53 moves under G91, written for ISG and Fagor as their programmers write them
(issue 26; ``postproc.isg_family.machine_moves``): one ``G90`` before a run of them, ``G91`` again where the
program next reads the distance mode, and a zero-increment return (``G91 G28 Z0.``) written as the move to the
set-up's home alone. Was: ``G91`` / ``G90 G00`` / ``#SUPPRESS OFFSETS Z0.`` / ``G91`` / ``G90 G00`` / ... .

Expected texts are hand-written (home 0 on every axis: the set-up's); the property's oracle is the simulation
of the Fanuc source (``verify``, deviation 0), independent of both writers.
"""

from __future__ import annotations

from hypothesis import assume, given, settings

from postproc.errors import ErrorList

from tests.support.pair_checks import PairChecks
from tests.test_fagor_machine_moves import SETUP, programs

CHECK = PairChecks(SETUP)
_translate, _verify = CHECK.translate, CHECK.verify

RETURNS = "G21 G90\nG00 X10. Y5. Z5.\nG91 G28 Z0.\nG28 X0. Y0.\nG00 X1.\nG90\nG00 X1.\nM30\n"
"""Two returns under G91, then an incremental move (the G91 is owed there) and G90."""


def test_isg_writes_one_g90_and_g91_where_it_is_read() -> None:
    out = _translate(RETURNS, "fanuc", "isg")
    assert out.splitlines() == [
        "G71 G90", "G00 X10. Y5. Z5.",
        "G90 G00", "#SUPPRESS OFFSETS Z-12.5",
        "G00", "#SUPPRESS OFFSETS X-400. Y-250.",
        "G91 G00 X1.", "G90", "G00 X1.", "M30"]
    _verify(RETURNS, out, "fanuc", "isg")


def test_fagor_writes_one_g90_and_g91_where_it_is_read() -> None:
    out = _translate(RETURNS, "fanuc", "fagor")
    assert out.splitlines() == [
        "G71 G90", "G00 X10. Y5. Z5.",
        "G53 G90 G00 Z-12.5",
        "G53 G00 X-400. Y-250.",
        "G91 G00 X1.", "G90", "G00 X1.", "M30"]
    _verify(RETURNS, out, "fanuc", "fagor")


def test_a_return_with_an_increment_keeps_its_intermediate_move() -> None:
    text = "G21 G90\nG00 X10. Y5. Z5.\nG91 G28 Z2.\nM30\n"
    out = _translate(text, "fanuc", "isg")
    assert out.splitlines()[2:6] == ["G91", "G00 Z2.", "G90 G00", "#SUPPRESS OFFSETS Z-12.5"]
    _verify(text, out, "fanuc", "isg")


@settings(max_examples=40, deadline=None)
@given(programs())
def test_machine_moves_and_reference_returns_keep_the_toolpath_to_isg_and_back(program: str) -> None:
    try:
        out = _translate(program, "fanuc", "isg")
    except ErrorList as err:  # ISG applies a length at the next absolute Z: an incremental Z there is refused
        assume("tool length change applies at the next move" not in str(err))
        raise
    _verify(program, out, "fanuc", "isg")
    try:
        back = _translate(out, "isg", "fanuc")
    except ErrorList as err:  # ISG's G53 under G91 has no Fanuc spelling known [?]: refused by name
        assert "a move in machine coordinates in incremental distance mode" in str(err), err
        return
    _verify(program, back, "fanuc", "fanuc")


LENGTH_OFF = "G21 G90\nG00 X10. Y5. Z30.\nG43 H2 Z30.\nG91 G00 Z10.\nG53 G49 Z0.\nG00 X1.\nM30\n"
"""A Haas program's end under G91 (issue 26, haasfacts: cadekiely_o78239_3x3_face_smile.nc lines 56-57): the length
cancelled beside a move in machine coordinates."""


def test_a_length_cancelled_beside_a_machine_move_under_g91_is_refused_by_name() -> None:
    """What a Fanuc or Haas does with G53's words under G91 is not known [?] (``WordBlockSyntax.
    MACHINE_MOVE_INCREMENTAL``): the block is refused where it stands, not cut as a move to machine Z0."""
    try:
        _translate(LENGTH_OFF, "fanuc", "isg")
    except ErrorList as err:
        assert str(err.errors[0]).startswith("in.nc:5:1: error: G53 in incremental distance mode"), err
    else:
        raise AssertionError("translated")


def test_a_g90_in_the_machine_move_block_stays_in_force_after_it() -> None:
    """Fanuc's G90 beside G53 is modal: the next Z20. is absolute (work Z20). ISG once wrote G91 again after the
    #SUPPRESS OFFSETS line, so that Z20. moved 20 up from machine Z0 (verify found 25.5 mm with a tool length)."""
    text = "G21 G90 G94\nG00 X0. Y0. Z10.\nG91\nG00 X1.\nG90 G53 G00 Z0.\nG00 Z20.\nM30\n"
    out = _translate(text, "fanuc", "isg")
    assert out.splitlines()[4:7] == ["G90 G00", "#SUPPRESS OFFSETS Z0.", "G00 Z20."], out
    _verify(text, out, "fanuc", "isg")
