"""Seeds of ``make fuzz`` (defects3's run) kept as regression tests.

Memory B, Fanuc -> Fanuc: a G41 start-up move along +X followed by a move straight back turns the compensated path
back on itself. The simulation refuses it at its line (interference) and so does every translation that resolves or
re-spells the compensation; a copy within Fanuc keeps it native and writes the program unchanged, whose own errors
verify then reports on both sides (listed in ``tests/support/fuzzing.KNOWN_DEFECTS``: not fixed).
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


def test_a_fanuc_copy_keeps_the_program_and_the_fuzz_lists_it_as_known() -> None:
    assert _translate("fanuc") == REVERSAL
    message = ("translated, but verify fails: " + INTERFERENCE + "\nout.nc:4:1: error: a move that turns back on "
               "itself under cutter compensation (interference)")
    assert known_defect("fanuc", message) is not None
    assert known_defect("fanuc", "translated, but verify fails: " + INTERFERENCE) is None  # only both sides alike
