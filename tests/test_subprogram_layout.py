"""Fanuc subprograms towards LinuxCNC: rs274 finds the ``O<n>`` of an ``M98 P<n>`` only after the call
("Failed to find sub 'O9001' before EOF" for one written before it), so each subprogram is written after
the subprograms that call it; subprograms that call each other are flattened, with the reason.

Expected moves are hand-derived from the Fanuc program (and agree with our Fanuc simulation); rs274 runs
the output.
"""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

CALLS_BACKWARD = ("%\nO0001\nG21 G90 G0 X0. Y0. Z10.\nM98 P9002\nM30\n"
                  "O9001\nG1 Y5. F100.\nM99\n"               # called by O9002, written before it
                  "O9002\nG1 X5. F100.\nM98 P9001\nM99\n%\n")
BACKWARD_MOVES = [("rapid", 0.0, 0.0, 10.0), ("feed", 5.0, 0.0, 10.0), ("feed", 5.0, 5.0, 10.0)]

EACH_OTHER = ("O0001\nG21 G90 G0 X0. Y0. Z10.\n#1=0\nM98 P9002\nM30\n"
              "O9001\n#1=#1+1\nWHILE [#1 LT 3] DO1\nM98 P9002\nEND1\nM99\n"
              "O9002\nG91 G1 X1. F100.\nG90\nM98 P9001\nM99\n")
EACH_OTHER_MOVES = [("rapid", 0.0, 0.0, 10.0)] + [("feed", float(x), 0.0, 10.0) for x in (1, 2, 3)]
"""O9002 moves X+1 and calls O9001, which counts #1 (shared by M98) and calls O9002 again while #1 < 3."""


def _translate(text: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = translate(io.StringIO(text), out, file="s.nc", source="fanuc", target="linuxcnc")
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def _moves(events: list[dict[str, object]]) -> list[tuple[object, float, float, float]]:
    return [(e["move"], round(float(e["x"]), 4), round(float(e["y"]), 4), round(float(e["z"]), 4))  # type: ignore[arg-type]
            for e in events if "move" in e]


@pytest.mark.parametrize("program, moves", [(CALLS_BACKWARD, BACKWARD_MOVES), (EACH_OTHER, EACH_OTHER_MOVES)],
                         ids=["backward", "each-other"])
def test_the_fanuc_simulation_makes_the_hand_derived_moves(program: str, moves: list[tuple[object, ...]]) -> None:
    assert _moves(list(toolpath_events(io.StringIO(program), file="s.nc", dialect="fanuc"))) == moves


def test_a_subprogram_called_from_a_later_one_is_written_after_it_and_rs274_finds_it() -> None:
    text, warnings = _translate(CALLS_BACKWARD)
    assert warnings == []
    lines = text.splitlines()
    assert lines.index("O9002") < lines.index("M98 P9001") < lines.index("O9001"), text
    assert _moves(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0))) == BACKWARD_MOVES


def test_a_linuxcnc_source_keeps_its_own_layout() -> None:
    ngc = "G21 G0 X0 Y0 Z10\nM98 P2\nM2\nO1\nG1 Y5 F100\nM99\nO2\nG1 X5 F100\nM98 P1\nM99\n"
    out = io.StringIO()
    translate(io.StringIO(ngc), out, file="s.ngc", source="linuxcnc", target="linuxcnc")
    assert out.getvalue() == ngc


def test_subprograms_that_call_each_other_are_flattened_with_the_reason() -> None:
    text, warnings = _translate(EACH_OTHER)
    assert any("line 9: subprograms O9001 and O9002 call each other" in w for w in warnings), warnings
    assert "M98" not in re.sub(r"\([^)]*\)", "", text), text
    assert _moves(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0))) == EACH_OTHER_MOVES
