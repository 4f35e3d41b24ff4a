"""Random LinuxCNC programs that compute and call numbered subs with arguments, written for a grblHAL build with
expressions. grblHAL hands a sub the caller's ``#k`` for an argument not given, rs274 reads 0
(``postproc_grblhal.variables``), so the writer gives every call its 30 arguments; then grblHAL runs the text as
rs274 does. Three runs must agree move by move: rs274 on the written program, our grblHAL simulation of it, and
our LinuxCNC simulation of the source (itself checked against rs274 by ``test_ngc_differential``). The sub
reads parameters its calls do not give, and the caller sets them first: where the arguments were not written
the runs would differ. Each seed is one program; a failure names it.
"""

from __future__ import annotations

import io
import math
import random

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.grblhal_rules import grblhal_problems
from tests.support.rs274 import available, canonical_moves, run_rs274

SEEDS = range(20)
TOLERANCE_MM = 2e-4
EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))


def _program(seed: int) -> str:
    r = random.Random(seed)

    def value() -> str:
        return r.choice(["#1", "#2", "#3", "#4", "#<k>", str(r.randint(0, 20)), f"[#1+{r.randint(1, 5)}]"])

    lines = ["G21 G17 G90", "G0 X0 Y0 Z5",
             f"#1={r.randint(1, 9)} #2={r.randint(1, 9)} #3={r.randint(1, 9)} #4={r.randint(1, 9)}",
             "o100 sub",
             "  #<k>=[#1+#2]",
             "  G1 X[#1 MOD 40] Y[#2 MOD 40] Z-[#3 MOD 5] F100",
             "  o101 if [#4 GT 4]",
             "    o100 return",
             "  o101 endif",
             "  G0 Z5 X[#<k> MOD 40]",
             "o100 endsub",
             "#<k>=1"]
    label = 200
    for _ in range(r.randint(3, 6)):
        kind = r.choice(["call", "call", "assign", "loop"])
        if kind == "assign":
            lines.append(f"#{r.randint(1, 4)}=[{value()} MOD 30]")
        elif kind == "call":
            args = " ".join(f"[{value()}]" for _ in range(r.randint(0, 3)))
            lines.append(f"o100 call {args}".rstrip())
        else:
            label += 1
            lines += [f"o{label} repeat [{r.randint(1, 3)}]", f"  #2=[#2+{r.randint(1, 4)}]",
                      f"  o100 call [{value()}]", f"o{label} endrepeat"]
    lines.append("M2")
    return "\n".join(lines) + "\n"


def _moves(events: object) -> list[tuple[str, float, float, float]]:
    return [(e["move"], float(e["x"]), float(e["y"]), float(e["z"])) for e in events if "move" in e]  # type: ignore[attr-defined]


def _agree(a: list[tuple[str, float, float, float]], b: list[tuple[str, float, float, float]], why: str) -> None:
    assert len(a) == len(b), f"{why}: {len(a)} moves against {len(b)}"
    for n, (x, y) in enumerate(zip(a, b)):
        dev = max(abs(x[i] - y[i]) for i in (1, 2, 3))
        assert x[0] == y[0] and dev <= TOLERANCE_MM and not math.isnan(dev), (why, n, x, y)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", SEEDS)
def test_random_subs_with_arguments_run_alike_on_grblhal_and_rs274(seed: int) -> None:
    source = _program(seed)
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(source, newline=""), out, file="gen.ngc", source="linuxcnc", target="grblhal",
              setup=EXPRESSIONS, diagnostics=diagnostics)
    text = out.getvalue()
    assert not diagnostics.warnings and "o100 call" in text and grblhal_problems(text) == [], (seed, text)
    theirs = _moves(canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)))
    hal = _moves(toolpath_events(io.StringIO(text, newline=""), file="gen.gcode", dialect="grblhal",
                                 setup=EXPRESSIONS))
    ours = _moves(toolpath_events(io.StringIO(source, newline=""), file="gen.ngc", dialect="linuxcnc"))
    _agree(hal, theirs, f"seed {seed}: grblHAL simulation against rs274\n{text}")
    _agree(ours, theirs, f"seed {seed}: the LinuxCNC source against rs274 on the output\n{source}\n{text}")


def test_the_calls_leave_arguments_out_where_inheriting_would_change_the_moves() -> None:
    """Not vacuous: calls with fewer than the four parameters the sub reads, after the caller set them, and
    for some seed the grblHAL simulation of the source text itself (no arguments written) moves otherwise."""
    differs = 0
    for seed in SEEDS:
        source = _program(seed)
        as_linuxcnc = _moves(toolpath_events(io.StringIO(source, newline=""), file="g", dialect="linuxcnc"))
        as_grblhal = _moves(toolpath_events(io.StringIO(source, newline=""), file="g", dialect="grblhal",
                                            setup=EXPRESSIONS))
        differs += as_linuxcnc != as_grblhal
    assert differs >= 5
