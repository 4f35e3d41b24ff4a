"""A program without a units code, translated for another dialect (issue 26): the units the translation read it
in (millimetres) are written before the first block that reads a length, so a target machine that powers on
in inches runs the same path. rs274 is the oracle: the translation run after a ``G20`` (an inch power-on)
must give the millimetre moves the source means (hand-derived: X10 Y5 then Z-1)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from tests.support.rs274 import available, canonical_moves, motions, run_rs274

FANUC = "O0001\nG90 G54\nG0 X10. Y5.\nG1 Z-1. F100.\nM30\n"


def run(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target)
    return out.getvalue()


@pytest.mark.parametrize(("target", "code"), [("linuxcnc", "G21"), ("grbl", "G21"), ("mach3", "G21"),
                                               ("isg", "G71"), ("fagor", "G71")])
def test_units_join_the_first_block_that_reads_a_length(target: str, code: str) -> None:
    lines = run(FANUC, "fanuc", target).splitlines()
    first = next(i for i, line in enumerate(lines) if "G90" in line)
    assert code in lines[first].split()
    assert not any(code in line.split() for line in lines[:first])


@pytest.mark.skipif(not available(), reason="rs274 not installed")
def test_an_inch_power_on_runs_the_millimetres_the_source_means() -> None:
    out = run(FANUC, "fanuc", "linuxcnc")
    moves = motions(canonical_moves(run_rs274("G20\n" + out)))
    assert [(m["x"], m["y"], m["z"]) for m in moves] == [(10.0, 5.0, 0.0), (10.0, 5.0, -1.0)]


def test_a_program_that_says_its_units_gets_no_other() -> None:
    out = run("O0001\nG20 G90\nG0 X1.\nM30\n", "fanuc", "linuxcnc")
    assert "G21" not in out and out.count("G20") == 1


def test_units_after_the_first_move_are_written_before_it() -> None:
    out = run("O0001\nG0 X1.\nG21\nG1 X2. F100.\nM30\n", "fanuc", "linuxcnc").splitlines()
    assert out[1].split()[:1] == ["G21"] and "X1." in out[1]


def test_a_block_delete_block_does_not_carry_the_units() -> None:
    out = run("O0001\n/G0 X1.\nG0 X2.\nM30\n", "fanuc", "linuxcnc").splitlines()
    assert out[1] == "G21" and out[2].startswith("/")


def test_the_same_dialect_is_untouched() -> None:
    assert run(FANUC, "fanuc", "fanuc") == FANUC
