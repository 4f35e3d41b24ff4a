"""A Fanuc macro call (``G65 P.. A.. B..``) towards grblHAL: resolved as for grbl, the call's moves written with its
arguments evaluated, on every build (with expressions too). grblHAL's own G65 runs a built-in query (P1-P7) or a
file system plugin's ``P<n>.macro`` file, one level deep and only while the machine is idle [V: grblHAL/core
f80fc34 ``gcode.c`` ``case 65``, ``ngc_params.c`` ``onMacroExecute``; grblHAL/Plugin_SD_card 0000e2e3 ``macros.c``
``macro_execute``], so a translation
(one file, a call while the machine moves) has no native spelling (``plugins/grblhal/README.md``).

The expected moves are derived by hand: ``#1`` is A, ``#2`` is B (Fanuc argument specification I), the body a
square of side #1 at the depth -#2 from the call's point.
"""

from __future__ import annotations

import io
import re
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

ROOT = Path(__file__).resolve().parents[1]

FANUC = """O1000
G21 G90 G17 G94
G00 X10. Y20. Z5.
G65 P9010 A5. B2.
G00 X40.
G65 P9010 A3. B1.
M30
O9010
G01 Z-#2 F100.
G91 G01 X#1
Y#1
X-#1
Y-#1
G90 G00 Z5.
M99
"""
HAND = [(10, 20, 5), (10, 20, -2), (15, 20, -2), (15, 25, -2), (10, 25, -2), (10, 20, -2), (10, 20, 5),
        (40, 20, 5), (40, 20, -1), (43, 20, -1), (43, 23, -1), (40, 23, -1), (40, 20, -1), (40, 20, 5)]


def _setup(expressions: bool) -> MachineSetup:
    if expressions:
        return load_setup(str(ROOT / "tests" / "support" / "grblhal_expressions.xml"))
    return MachineSetup()


def _points(text: str, dialect: str, setup: MachineSetup) -> list[tuple[float, ...]]:
    events: list[dict[str, Any]] = list(toolpath_events(io.StringIO(text), file="prog", dialect=dialect,
                                                        setup=setup))
    return [(ev["x"], ev["y"], ev["z"]) for ev in events[1:] if "move" in ev]


@pytest.mark.parametrize("expressions", [False, True])
def test_a_fanuc_macro_call_reaches_grblhal_as_its_moves(expressions: bool) -> None:
    setup = _setup(expressions)
    assert _points(FANUC, "fanuc", setup) == HAND
    out = io.StringIO()
    diagnostics = Diagnostics()
    translate(io.StringIO(FANUC), out, file="prog", source="fanuc", target="grblhal", setup=setup,
              diagnostics=diagnostics)
    written = out.getvalue()
    assert not re.search(r"^\s*[^(]*\b(G65|M98|M99|o\d+ call)\b", written, re.M | re.I), written
    assert _points(written, "grblhal", setup) == HAND
    report = verify_lines(io.StringIO(FANUC), io.StringIO(written), file_in="prog", file_out="out",
                          source="fanuc", target="grblhal", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_grblhals_own_g65_is_refused_where_read() -> None:
    with pytest.raises(ErrorList) as err:
        list(toolpath_events(io.StringIO("G21\nG65 P100\nM2\n"), file="prog", dialect="grblhal",
                             setup=_setup(True)))
    assert "prog:2:1: error: grblHAL's G65 P1-P7 are its inbuilt macros" in str(err.value)
