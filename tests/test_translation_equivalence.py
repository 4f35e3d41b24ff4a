"""Toolpath equivalence of translations: generated Fanuc hole-making programs, translated to every
writer (cycles kept native, forced to expand, or expanded because the target lacks them), must move
the tool exactly as the source does (``verify``: zero deviation, same structure)."""

from __future__ import annotations

import io

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.plugins import default_registry
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.verify import verify_lines

REGISTRY = default_registry()
READABLE_WRITERS = sorted(n for n, c in REGISTRY.dialects.items()
                          if c.WRITER is not None and c.READER is not None and "mill" in c.MACHINE_TYPES
                          and n not in ("mach3", "siemens"))
"""Targets of the milling programs below (a lathe-only control refuses them: tests/test_lathe_*). Not
mach3 and siemens: they write no oriented spindle stop even where the set-up says ``orientation="m19"``
(SINUMERIK's SPOS is not written yet), so their G76 case is refused (the conformance suite and
tests/test_siemens.py cover their translations)."""

# code, extra words it needs (a strategy each)
_Q = st.sampled_from(["Q1.", "Q2.5", "Q4."])
_P = st.sampled_from(["P200", "P500", "P1000"])
CYCLES: dict[str, list[st.SearchStrategy[str]]] = {
    "G81": [], "G82": [_P], "G83": [_Q], "G73": [_Q], "G84": [_P], "G85": [], "G86": [], "G89": [_P],
    "G76": [_Q, _P],
}


def _num(lo: int, hi: int) -> st.SearchStrategy[str]:
    return st.integers(lo * 2, hi * 2).map(lambda v: f"{v / 2:g}" + ("." if v % 2 == 0 else ""))


@st.composite
def programs(draw: st.DrawFn) -> str:
    initial = draw(st.integers(20, 40))
    lines = ["G21 G17 G90 G54", "S1200 M03", f"G00 X0. Y0. Z{initial}."]
    for _ in range(draw(st.integers(1, 3))):
        code = draw(st.sampled_from(sorted(CYCLES)))
        r = draw(st.integers(1, 5))
        bottom = -draw(st.integers(2, 12))
        words = [draw(st.sampled_from(["G98", "G99"])), code, f"X{draw(_num(-50, 50))}", f"Y{draw(_num(-50, 50))}",
                 f"Z{bottom}.", f"R{r}.", *[draw(s) for s in CYCLES[code]], f"F{draw(st.integers(50, 400))}."]
        lines.append(" ".join(words))
        for _ in range(draw(st.integers(0, 3))):  # modal repetition at new positions
            lines.append(f"X{draw(_num(-50, 50))} Y{draw(_num(-50, 50))}")
        lines.append("G80")
        lines.append(f"G00 Z{initial}.")
    lines.append("M05")
    lines.append("M30")
    return "\n".join(lines) + "\n"


def _setups(expand: bool) -> MachineSetup:
    # M19 for the orienting cycles (G76) on targets without it; forced expansion on request.
    return MachineSetup(cycles=CycleSettings(orientation="m19", expand="all" if expand else ""))


@pytest.mark.parametrize("target", READABLE_WRITERS)
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs(), expand=st.booleans())
def test_translation_moves_the_tool_exactly_as_the_source(target: str, program: str, expand: bool) -> None:
    setup = _setups(expand)
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="fanuc", target=target, setup=setup)
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target=target, setup=setup, target_setup=setup, tolerance=1e-6)
    assert report.ok, report.summary() + "\n--- in\n" + program + "--- out\n" + out.getvalue()
