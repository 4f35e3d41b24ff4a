"""Translation, its located errors and its verification, for tests that check one set-up's pairs of dialects:
the helpers tests/test_fagor_cycle_end.py and tests/test_fagor_machine_moves.py each wrote out."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines


class PairChecks:
    """``translate``, ``errors`` and ``verify`` under one set-up, strict (``--on-unsupported error``)."""

    def __init__(self, setup: MachineSetup, tolerance: float = 0.001) -> None:
        self.setup = setup
        self.tolerance = tolerance

    def translate(self, text: str, source: str, target: str) -> str:
        """The translation's text (warnings swallowed); raises ``ErrorList`` on its errors."""
        out = io.StringIO(newline="")
        translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target, setup=self.setup,
                  on_unsupported="error", diagnostics=Diagnostics(warn_stream=io.StringIO()))
        return out.getvalue()

    def errors(self, text: str, source: str, target: str) -> list[str]:
        """The translation's located errors (it must have some)."""
        with pytest.raises(ErrorList) as caught:
            self.translate(text, source, target)
        return [str(e) for e in caught.value.errors]

    def verify(self, a: str, b: str, source: str, target: str) -> None:
        """``b`` (in ``target``) moves as ``a`` (in ``source``) does, at no deviation."""
        report = verify_lines(io.StringIO(a), io.StringIO(b), file_in="a.nc", file_out="b.nc", source=source,
                              target=target, tolerance=self.tolerance, setup=self.setup)
        assert report.ok and report.max_deviation < 1e-9, report.summary() + "\n" + b
