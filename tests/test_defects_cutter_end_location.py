"""Defects: cutter compensation that cannot be simulated at the program's end (a stop right after the start-up
move, under Haas rules, the stretch tried under the target's rules too) was an error without a location
(``error: a stop right after ...``), found by the fuzz generators' shop spellings. Every error names its line."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.setup.machine_setup import load_setup

SHOP = load_setup(Path(__file__).resolve().parent.parent / "examples" / "setups" / "haas_vf2_cell3.xml")
PROGRAM = "X0 Y0 Z1.\nG41 D1 X1.\nG00 X#10150\nM30\n"


@pytest.mark.parametrize("target", ["linuxcnc", "isg", "grbl"])
def test_an_error_at_the_end_of_a_compensated_stretch_names_its_line(target: str) -> None:
    with pytest.raises(PostprocError) as caught:
        translate(io.StringIO(PROGRAM), io.StringIO(), file="in.nc", source="fanuc", target=target, setup=SHOP,
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    errors = caught.value.errors if isinstance(caught.value, ErrorList) else [caught.value]
    assert errors
    for err in errors:
        assert err.location is not None, str(err)
        assert str(err).startswith("in.nc:"), str(err)
