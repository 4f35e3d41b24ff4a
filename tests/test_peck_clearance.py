"""G73 retract and G83 clearance between controls: a peck cycle stays native only where the target pecks
with the clearance the program was read with (``Dialect.PECK_CLEARANCE_MM``, else the set-up's
``<Cycles peckRetract peckClearance>``); otherwise it is expanded, and either way the translation moves
the tool as the source at zero deviation.

The clearance of each side is derived by hand: Mach3 takes the machine's settings (the set-up, 0.5 mm by
default), LinuxCNC has 0.010 in = 0.254 mm built in (DIALECTS.md §2.1). A Mach3 G83 written natively for
LinuxCNC moved 0.246 mm off (0.5 - 0.254) before the lowering compared them. The LinuxCNC interpreter
(``rs274``) runs each LinuxCNC output as an independent check.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, motions, run_rs274

PECKS = """G21 G17 G90 G94
T1 M6
S1000 M3
G0 X0 Y0 Z5
G98 G83 X10 Y10 Z-10 R2 Q3 F100
X20
G80
G0 X0 Y20 Z5
G99 G73 X10 Y20 Z-6 R1 Q2 F100
X20
G80
G0 Z20
M30
"""
LINUXCNC_MM = 0.254
RS274_PLACES = 1.5e-4
"""mm: rs274 prints four decimals."""


def _translate(text: str, source: str, target: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="p.nc", source=source, target=target, setup=setup)
    return out.getvalue()


def _deviation(text: str, written: str, source: str, target: str, setup: MachineSetup) -> float:
    report = verify_lines(io.StringIO(text), io.StringIO(written), file_in="p.nc", file_out="o.nc",
                          source=source, target=target, setup=setup, tolerance=0.0)
    assert report.ok, report.summary()
    return report.max_deviation


def _cycles(text: str) -> set[str]:
    """The peck cycle codes written (an expansion's comment names its source, which is not a code)."""
    return {word for line in text.splitlines() if not line.startswith("(")
            for word in line.split() if word in ("G73", "G83")}


def test_mach3_pecks_are_expanded_for_linuxcnc_by_default() -> None:
    setup = MachineSetup()  # Mach3's clearances from the set-up: 0.5 mm, LinuxCNC pecks with 0.254
    written = _translate(PECKS, "mach3", "linuxcnc", setup)
    assert _cycles(written) == set()
    assert _deviation(PECKS, written, "mach3", "linuxcnc", setup) == 0.0


def test_mach3_pecks_stay_native_where_the_clearances_agree() -> None:
    setup = MachineSetup(cycles=CycleSettings(peck_retract=LINUXCNC_MM, peck_clearance=LINUXCNC_MM))
    written = _translate(PECKS, "mach3", "linuxcnc", setup)
    assert _cycles(written) == {"G73", "G83"}
    assert _deviation(PECKS, written, "mach3", "linuxcnc", setup) == 0.0


def test_only_the_cycle_whose_clearance_differs_is_expanded() -> None:
    setup = MachineSetup(cycles=CycleSettings(peck_retract=LINUXCNC_MM, peck_clearance=0.5))
    written = _translate(PECKS, "mach3", "linuxcnc", setup)
    assert _cycles(written) == {"G73"}
    assert _deviation(PECKS, written, "mach3", "linuxcnc", setup) == 0.0


def test_linuxcnc_pecks_are_expanded_for_mach3_unless_its_machine_matches() -> None:
    ngc = _translate(PECKS, "mach3", "linuxcnc",
                     MachineSetup(cycles=CycleSettings(peck_retract=LINUXCNC_MM, peck_clearance=LINUXCNC_MM)))
    default = MachineSetup()
    back = _translate(ngc, "linuxcnc", "mach3", default)
    assert _cycles(back) == set()  # LinuxCNC read with 0.254, the Mach3 machine pecks with 0.5
    assert _deviation(ngc, back, "linuxcnc", "mach3", default) == 0.0
    same = MachineSetup(cycles=CycleSettings(peck_retract=LINUXCNC_MM, peck_clearance=LINUXCNC_MM))
    assert _cycles(_translate(ngc, "linuxcnc", "mach3", same)) == {"G73", "G83"}


def test_the_clearance_a_peck_cycle_is_read_with_is_the_reading_dialects() -> None:
    """LinuxCNC's 0.254 whatever the set-up says; Mach3's from the set-up (the first re-approach of the
    G83 above stops d above the first peck's bottom, Z-1)."""
    setup = MachineSetup(cycles=CycleSettings(peck_clearance=0.4))
    def first_reapproach(dialect: str) -> float:
        events = list(toolpath_events(io.StringIO(PECKS), file="p.nc", dialect=dialect, setup=setup))
        rapids = [e for e in events if e.get("move") == "rapid" and e.get("x") == 10 and e.get("y") == 10]
        return float(rapids[3]["z"])  # above the hole, R, back to R after the first peck, then d above Z-1
    assert first_reapproach("mach3") == pytest.approx(-1 + 0.4, abs=1e-9)
    assert first_reapproach("linuxcnc") == pytest.approx(-1 + LINUXCNC_MM, abs=1e-9)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("clearance", [0.5, LINUXCNC_MM])
def test_rs274_runs_the_linuxcnc_output_as_mach3_moves(clearance: float) -> None:
    """The real interpreter runs the written program (expanded at 0.5, native at 0.254) along the Mach3
    source's toolpath."""
    setup = MachineSetup(cycles=CycleSettings(peck_retract=clearance, peck_clearance=clearance))
    written = _translate(PECKS, "mach3", "linuxcnc", setup)
    theirs = motions(canonical_moves(run_rs274(written), start=(0.0, 0.0, 0.0)))
    ours = motions(list(toolpath_events(io.StringIO(PECKS), file="p.nc", dialect="mach3", setup=setup))[1:])
    ours = [e for i, e in enumerate(ours) if i == 0 or _xyz(e) != _xyz(ours[i - 1])]
    assert len(theirs) == len(ours)
    for a, b in zip(theirs, ours):
        assert a["move"] == b["move"]
        assert max(abs(a[k] - b[k]) for k in "xyz") <= RS274_PLACES, (a, b)


def _xyz(event: dict[str, object]) -> tuple[object, ...]:
    return tuple(event[k] for k in "xyz")
