"""Every reader, lowering and writer either succeeds or reports located errors: never anything else.

Random programs are built from fragments of real G-code, so they reach deep into the pipelines (cycles,
arcs, modal state) rather than failing at the first character.
"""

from __future__ import annotations

import io

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import ErrorList, PostprocError
from postproc.plugins import default_registry
from postproc.setup import MachineSetup
from postproc.toolpath import toolpath_events

REGISTRY = default_registry()
READERS = sorted(n for n, c in REGISTRY.dialects.items() if c.READER is not None)
WRITERS = sorted(n for n, c in REGISTRY.dialects.items() if c.WRITER is not None)

FRAGMENTS = [
    "G00", "G01", "G02", "G03", "G04", "G17", "G18", "G19", "G20", "G21", "G28", "G40", "G41", "G43", "G49",
    "G53", "G54", "G80", "G81", "G82", "G83", "G73", "G84", "G74", "G85", "G86", "G87", "G88", "G89", "G76",
    "G90", "G91", "G94", "G95", "G98", "G99", "M03", "M04", "M05", "M06", "M08", "M09", "M19", "M30",
    "X10.", "X-5", "Y2.5", "Y0", "Z-3.", "Z5", "R2.", "R-1", "Q1.", "Q0", "P500", "P0.5", "K2", "K0", "L2",
    "I5.", "J-5.", "K1.", "F100.", "S1000", "T1", "H01", "D02", "N10", "(C)", "/", "%", "X", "1.2.3",
]


def _programs() -> st.SearchStrategy[str]:
    line = st.lists(st.sampled_from(FRAGMENTS), min_size=0, max_size=6).map(" ".join)
    return st.lists(line, min_size=1, max_size=8).map(lambda lines: "G21 G90 G0 X0. Y0. Z10.\n" + "\n".join(lines) + "\n")


def _located(err: PostprocError) -> None:
    assert err.location is not None and err.location.line >= 1 and err.location.col >= 1, str(err)


@pytest.mark.parametrize("source", READERS)
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=_programs(), target=st.sampled_from(WRITERS), warn=st.booleans())
def test_translate_succeeds_or_reports_located_errors(source: str, program: str, target: str, warn: bool) -> None:
    setup = MachineSetup()
    try:
        translate(io.StringIO(program), io.StringIO(), file="fuzz.nc", source=source, target=target, setup=setup,
                  on_unsupported="warn" if warn else "error")
    except ErrorList as errs:
        for err in errs.errors:
            _located(err)


@pytest.mark.parametrize("dialect", READERS)
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=_programs())
def test_toolpath_succeeds_or_reports_located_errors(dialect: str, program: str) -> None:
    try:
        list(toolpath_events(io.StringIO(program), file="fuzz.nc", dialect=dialect, setup=MachineSetup()))
    except ErrorList as errs:
        for err in errs.errors:
            _located(err)
    except PostprocError as err:
        _located(err)
