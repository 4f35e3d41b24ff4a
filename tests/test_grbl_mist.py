"""Mist coolant towards grbl: grbl 1.1 answers M7 with error 20 unless it was built with ENABLE_M7 (off by
default, config.h [K]), so a translation writes it only where the set-up says the build has it, and refuses
it otherwise at its line (a program that stops half-way at error 20 is the wrong output this prevents)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from tests.support.grbl_rules import grbl_problems

PROGRAM = "G21 G90\nM3 S1000\nM7\nG1 X10. F100.\nM9\nM30\n"


def _translate(setup: MachineSetup, warn: bool = False) -> tuple[str, str]:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="in.nc", source="fanuc", target="grbl", setup=setup,
              on_unsupported="warn" if warn else "error", diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def test_a_default_grbl_build_gets_no_mist_coolant() -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(MachineSetup())
    err = caught.value.errors[0]
    assert (err.location.line, err.location.col) == (3, 1) and "mistCoolant" in str(err)  # type: ignore[union-attr]


def test_warn_drops_only_the_mist_word_and_says_so() -> None:
    text, warnings = _translate(MachineSetup(), warn=True)
    assert "\nM7\n" not in text and "(UNSUPPORTED LINE 3: M7)" in text and "G1 X10. F100." in text
    assert "in.nc:3:1" in warnings and "mist coolant" in warnings
    assert grbl_problems(text) == []


def test_a_build_with_mist_coolant_says_so_in_the_set_up() -> None:
    text, _ = _translate(MachineSetup(controller=ControllerSettings(mist_coolant=True)))
    assert "\nM7\n" in text
    assert grbl_problems(text) != [] and grbl_problems(text, m7=True) == []  # error 20 only without ENABLE_M7


def test_other_targets_write_mist_coolant_as_before() -> None:
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="in.nc", source="fanuc", target="linuxcnc", setup=MachineSetup())
    assert "M7" in out.getvalue()
