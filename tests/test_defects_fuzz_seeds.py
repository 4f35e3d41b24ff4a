"""Seeds of ``make fuzz`` (defects3's run) kept as regression tests.

Memory B, Fanuc -> Fanuc: a G41 start-up move along +X followed by a move straight back turns the compensated path
back on itself. The simulation refuses it at its line (interference) and so does every translation that resolves or
re-spells the compensation; a copy within Fanuc, which keeps it native, was written unchanged with exit 0 and verify
then reported the source's own errors on both sides (a known defect until issue 26's comp26): it is refused at its
line too now, by the same geometry (``lowering.cutter_resolver.Resolver.check``).
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.plugins import default_registry
from postproc.simulate.toolpath import toolpath_events
from tests.support.fuzzing import known_defect
from tests.support.generators.offset_memories import memory_setup

REVERSAL = "G21 G17 G90 G94\nG0 X0. Y0. Z50.\nG41 D03 G1 X5. Y0. F200.\nX-5.\nG40 G0 X0. Y0.\nG40 G49 G0 Z50.\nM30\n"
INTERFERENCE = "in.nc:4:1: error: a move that turns back on itself under cutter compensation (interference)"


def _translate(target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(REVERSAL), out, file="in.nc", source="fanuc", target=target, setup=memory_setup("B"),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def test_the_reversal_is_refused_at_its_line_by_the_simulation() -> None:
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(REVERSAL), file="in.nc", dialect="fanuc", setup=memory_setup("B")))
    assert str(caught.value.errors[0]) == INTERFERENCE


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "isg", "siemens"])
def test_the_reversal_is_refused_at_its_line_by_other_targets(target: str) -> None:
    if target not in default_registry().dialects:
        pytest.skip(f"the {target} plugin is not installed")
    with pytest.raises(ErrorList) as caught:
        _translate(target)
    assert str(caught.value.errors[0]) == INTERFERENCE


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "isg", "siemens"])
def test_the_reversal_is_refused_at_its_line_by_every_target_the_copy_included(target: str) -> None:
    if target not in default_registry().dialects:
        pytest.skip(f"the {target} plugin is not installed")
    with pytest.raises(ErrorList) as caught:
        _translate(target)
    assert [str(e) for e in caught.value.errors] == [INTERFERENCE]


def test_the_fuzz_no_longer_lists_the_copy_as_known() -> None:
    message = ("translated, but verify fails: " + INTERFERENCE + "\nout.nc:4:1: error: a move that turns back on "
               "itself under cutter compensation (interference)")
    assert known_defect("fanuc", message) is None


CANCEL_AT_ONCE = "G21 G17 G90 G94\nG0 X0. Y0. Z50.\nG41 D03 G1 X5. Y0. F200.\nG40 X10.\nM30\n"
"""A cancel right after the start-up move: Fanuc's rules (type A) do not say where that start-up move ends."""


def test_a_copy_refuses_what_the_simulation_cannot_simulate_at_the_same_line() -> None:
    with pytest.raises(ErrorList) as simulated:
        list(toolpath_events(io.StringIO(CANCEL_AT_ONCE), file="in.nc", dialect="fanuc", setup=memory_setup("B")))
    with pytest.raises(ErrorList) as copied:
        translate(io.StringIO(CANCEL_AT_ONCE), io.StringIO(), file="in.nc", source="fanuc", target="fanuc",
                  setup=memory_setup("B"), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert [str(e) for e in copied.value.errors] == [str(simulated.value.errors[0])]
    assert str(simulated.value.errors[0]).startswith("in.nc:4:1: error: cutter compensation cancelled right after "
                                                     "its start-up move cannot be simulated")


def test_a_copy_the_check_cannot_follow_passes_unchanged() -> None:
    """A subprogram call under compensation: the check cannot follow the call (its moves are not in the
    stream), so it stops without a word and the copy is the program."""
    text = "G21 G17 G90 G94\nG0 X0. Y0. Z50.\nG41 D03 G1 X5. Y0. F200.\nM98 P100\nX-5.\nG40 G0 X0. Y0.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="fanuc", setup=memory_setup("B"),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert out.getvalue() == text
