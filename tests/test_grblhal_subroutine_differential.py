"""Random Fanuc programs with subprograms (``M98 P L``, the packed P form, nested calls, ``M99`` in a block that
moves), written for a grblHAL build with expressions: rs274 runs the written o-word subs (grblHAL's
``ngc_flowctrl.c`` is its port, and calls without arguments in a program that computes nothing run alike), and
its moves must be those of our Fanuc simulation of the source. Each seed is one program: a failure names the
seed, and the program is in the assertion message.
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

SEEDS = range(25)
TOLERANCE_MM = 2e-4
EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))


def _program(seed: int) -> str:
    r = random.Random(seed)
    subs = sorted(r.sample(range(100, 9000), r.randint(1, 4)))

    def moves(count: int) -> list[str]:
        out = []
        for _ in range(count):
            if r.random() < 0.5:
                out.append(f"G91 G0 X{r.randint(-20, 20)}. Y{r.randint(-20, 20)}.")
                out.append(f"G1 Z-{r.randint(1, 5)}. F{r.choice((80, 120))}.")
                out.append("G0 Z" + out[-1].split("Z-")[1].split()[0])
                out.append("G90")
            else:
                out.append(f"G90 G1 X{r.randint(0, 60)}. Y{r.randint(0, 60)}. F100.")
        return out

    def call(callable_: list[int]) -> str:
        number = r.choice(callable_)
        times = r.randint(1, 3)
        if times > 1 and r.random() < 0.3:
            return f"M98 P{times:04d}{number:04d}"  # the packed form: 4 digits of repeats, 4 of the program
        return f"M98 P{number}" + (f" L{times}" if times > 1 or r.random() < 0.2 else "")

    lines = ["%", f"O{r.randint(1, 99):04d}", "G21 G17 G90", "G00 X0 Y0 Z5."]
    for _ in range(r.randint(2, 5)):
        lines += moves(r.randint(0, 2))
        lines.append(call(subs))
    lines += ["G90 G00 Z20.", "M30"]
    for at, number in enumerate(subs):
        lines.append(f"O{number}" + (" (SUB)" if r.random() < 0.5 else ""))
        lines += moves(r.randint(1, 2))
        later = subs[at + 1:]
        if later and r.random() < 0.6:
            lines.append(call(later))  # a call of a subprogram written after this one (acyclic)
        lines.append("G0 Z5. M99" if r.random() < 0.3 else "M99")
    lines.append("%")
    return "\n".join(lines) + "\n"


def _to_grblhal(text: str) -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text, newline=""), out, file="gen.nc", source="fanuc", target="grblhal", setup=EXPRESSIONS,
              diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", SEEDS)
def test_random_subprograms_written_as_subs_move_in_rs274_as_the_fanuc_program(seed: int) -> None:
    source = _program(seed)
    text, warnings = _to_grblhal(source)
    assert warnings == [] and " sub" in text and " call" in text, (seed, warnings, text)
    assert grblhal_problems(text) == [], (seed, text)
    ours = [e for e in toolpath_events(io.StringIO(source, newline=""), file="gen.nc", dialect="fanuc")
            if "move" in e]
    theirs = [e for e in canonical_moves(run_rs274(text.replace("(%)", "%")), start=(0.0, 0.0, 0.0)) if "move" in e]
    assert len(ours) == len(theirs), f"seed {seed}: {len(ours)} moves in the source, {len(theirs)} in rs274\n{source}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (seed, n, a, b, source, text)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (seed, n, a, b, source, text)


def test_the_generator_writes_every_form() -> None:
    """Not vacuous: across the seeds, repeats, the packed form, nested calls and an M99 that moves."""
    text = "".join(_program(seed) for seed in SEEDS)
    for form in (" L2", " L3", "M98 P0002", "M98 P0003", "G0 Z5. M99"):
        assert form in text, form
    assert any(_program(seed).split("M30")[1].count("M98") for seed in SEEDS)
