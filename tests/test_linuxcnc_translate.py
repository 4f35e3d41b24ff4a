"""Fanuc programs written for LinuxCNC, checked two ways: by ``postproc verify`` (our own linuxcnc
reader simulates the output) and by LinuxCNC's interpreter ``rs274`` itself (skipped when absent).

Fanuc hole cycles reach LinuxCNC expanded: its native cycles follow RS274/NGC rules (rise to R, G98 to
the old Z, G91 R from the block's Z) that move differently, so only the exact expansion is faithful.
"""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parents[1]
PROGRAMS = sorted((ROOT / "examples" / "fanuc").glob("*.nc")) + sorted(
    (ROOT / "tests" / "golden" / "fanuc" / "cycles").glob("*.nc"))
GOLDEN_SETUP = MachineSetup(cycles=CycleSettings(peck_retract=0.5, peck_clearance=0.3))
"""The cycle goldens' Fanuc parameters (their README); the examples have no G73/G83 depending on them
other than G83 with Q, for which these values serve as well."""
TOOL_TABLE = "".join(f"T{n} P{n} Z0 D0.25 ;\n" for n in range(1, 10))
TOLERANCE_MM = 3e-3
"""rs274 prints 4 decimals in program units: 1e-4 in = 0.00254 mm for the inch example."""


def _id(path: Path) -> str:
    return path.name


def _to_linuxcnc(path: Path) -> str:
    out = io.StringIO(newline="")
    with open(path, encoding="utf-8", newline="") as src:
        translate(src, out, file=str(path), source="fanuc", target="linuxcnc", setup=GOLDEN_SETUP)
    return out.getvalue()


@pytest.mark.parametrize("path", PROGRAMS, ids=_id)
def test_translation_verifies_with_our_linuxcnc_reader(cli: Any, tmp_path: Path, path: Path) -> None:
    out = tmp_path / (path.stem + ".ngc")
    out.write_text(_to_linuxcnc(path), encoding="utf-8")
    setup = tmp_path / "golden.xml"
    setup.write_text("<?xml version='1.0' encoding='UTF-8'?>\n<MachineSetup name=\"golden\">\n"
                     "  <Cycles peckRetract=\"0.5\" peckClearance=\"0.3\"/>\n"
                     + "  <Tools>\n" + "".join(f'    <Tool number="{n}" length="0.0"/>\n' for n in range(1, 10))
                     + "  </Tools>\n</MachineSetup>\n")
    result = cli("verify", path, out, "--from", "fanuc", "--to", "linuxcnc", "--machine", setup)
    assert result.status == 0, result.out.decode() + result.err
    assert result.out.decode().startswith("max deviation 0.0000 mm")


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", PROGRAMS, ids=_id)
def test_translation_runs_in_linuxcnc_as_the_fanuc_program_moves(path: Path) -> None:
    text = _to_linuxcnc(path)
    theirs = [e for e in canonical_moves(run_rs274(text, tool_table=TOOL_TABLE), start=(0.0, 0.0, 0.0))
              if "move" in e]
    with open(path, encoding="utf-8", newline="") as src:
        ours = [e for e in toolpath_events(src, file=str(path), dialect="fanuc", setup=with_tools(GOLDEN_SETUP))
                if "move" in e]
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in LinuxCNC\n{text}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        keys = ("x", "y", "z") + (("cx", "cy") if a["move"] in ("cw", "ccw") else ())
        dev = max(abs(float(a[k]) - float(b[k])) for k in keys)
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b)
