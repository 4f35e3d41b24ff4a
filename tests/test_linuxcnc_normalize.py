"""``--normalize`` of LinuxCNC programs. With Fanuc-style subprograms (``O1`` .. ``M99``, called by ``M98 P1 L3``):
the ``O1`` line is read into the program start with no words, and the normalized line written from its words was
nothing: it became a comment ("nothing in this block has a meaning in linuxcnc"), so the output's ``M98 P1`` found no
subprogram (rs274 refuses it), exit 0 with a warning. It is written as read now; rs274 runs the normalized program
as it runs the source [V: rs274 below], so the expected moves are the interpreter's, not the tool's. With polar
coordinates in a loop (``spiral.ngc``): see the last test.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import MachineSetup
from tests.support.rs274 import available, canonical_moves, run_rs274

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "corpus" / "linuxcnc"


@pytest.mark.parametrize("name", ["m98m99_basics.ngc", "m98m99_loops.ngc"])
def test_normalize_keeps_a_fanuc_style_program_number(name: str) -> None:
    text = (CORPUS / name).read_text()
    setup = MachineSetup()
    setup.output.normalize = True
    out = io.StringIO()
    warnings = io.StringIO()
    translate(io.StringIO(text), out, file=name, source="linuxcnc", target="linuxcnc", setup=setup,
              diagnostics=Diagnostics(warn_stream=warnings))
    written = out.getvalue()
    assert "O1\n" in written and "nothing in this block" not in warnings.getvalue(), written
    if available():
        assert canonical_moves(run_rs274(written)) == canonical_moves(run_rs274(text))


def test_normalize_keeps_polar_words_that_a_loop_turns_further() -> None:
    """LinuxCNC's ``spiral.ngc`` turns ``G91 G1 @-.0025 ^4.5`` 800 times in an ``o100 repeat``: normalized, the
    line was its first pass's X and Y (one fixed step each pass: a straight line 3 m long instead of a spiral),
    exit 0. Kept as written; rs274 runs the normalized program as the source."""
    text = (CORPUS / "spiral.ngc").read_text()
    setup = MachineSetup()
    setup.output.normalize = True
    out = io.StringIO()
    translate(io.StringIO(text), out, file="spiral.ngc", source="linuxcnc", target="linuxcnc", setup=setup)
    written = out.getvalue()
    assert "@-.0025 ^4.5" in written, written
    if available():
        assert canonical_moves(run_rs274(written)) == canonical_moves(run_rs274(text))
