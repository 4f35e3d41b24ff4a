"""``--normalize`` within Fagor kept the program header (defects, a hand-made find).

A Fagor program starts with ``%<number>`` or ``%<name>`` (``dialects/fagor/reader.py``). Rewritten from its words
(``--normalize``), the header has none, and the writer took it for a block with no meaning in Fagor: a warning,
and ``;LINE 1: %1101`` instead of the header. ISG's writer keeps its header so; Fagor's now writes it from its
``ProgramStart``.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.groups import OutputSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples" / "fagor").glob("*.nc"))


def _normalized(text: str) -> tuple[str, str]:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fagor", target="fagor",
              setup=MachineSetup(output=OutputSettings(normalize=True)), diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


@pytest.mark.parametrize("header", ["%1101", "%DRILL", "%DRILL ;a note"])
def test_the_header_is_written_as_a_header(header: str) -> None:
    out, warnings = _normalized(f"{header}\nG71 G90\nG00 X0 Y0 Z50\nM30\n")
    assert out.splitlines()[0] == header, out
    assert warnings == ""


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_the_examples_keep_their_header_and_path(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    out, _ = _normalized(text)
    assert out.splitlines()[0] == text.splitlines()[0]
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a.nc", file_out="b.nc", source="fagor",
                          target="fagor", tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
