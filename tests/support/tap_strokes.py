"""What the tap stroke tests of ISG and SINUMERIK share (``tests/test_isg_tap_strokes_26.py``,
``tests/test_siemens_tap_strokes_26.py``): both controllers tap by the strokes G331/G332
(``postproc.isg_family.taps``), so their tests translate, simulate and verify alike."""

from __future__ import annotations

import io
from typing import Any

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

SUFFIX = {"isg": "nc", "siemens": "mpf"}
"""The file name a program of each dialect is read under (for messages)."""


def lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def to(source: str, target: str, text: str, mode: str = "error") -> str:
    """``text`` translated with the default set-up, every error raised."""
    out = io.StringIO(newline="")
    translate(lines(text), out, file="t.nc", source=source, target=target, setup=MachineSetup(),
              on_unsupported=mode, diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def events(text: str, dialect: str) -> list[dict[str, Any]]:
    """The toolpath's events without its header."""
    file = "t." + SUFFIX.get(dialect, "nc")
    return list(toolpath_events(lines(text), file=file, dialect=dialect, setup=MachineSetup()))[1:]


def moves(text: str, dialect: str) -> list[dict[str, Any]]:
    return [e for e in events(text, dialect) if "move" in e]


def verified(source: str, text: str, out: str, target: str) -> None:
    """``verify`` passes for ``text`` and its translation ``out``, to a micrometre."""
    report = verify_lines(lines(text), lines(out), file_in="t.nc", file_out="t." + SUFFIX.get(target, "nc"),
                          source=source, target=target, setup=MachineSetup())
    assert report.ok and report.max_deviation < 1e-6, report.summary()
