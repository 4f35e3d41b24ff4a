"""The line check every reader's lines pass (``postproc.lines``): non-ASCII outside comments, over-long
lines and numbers of more than 30 digits are located errors, for every readable dialect; comments keep
any character."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.plugins import default_registry
from postproc.setup import Limits, MachineSetup
from postproc.toolpath import toolpath_events

READABLE = sorted(n for n, c in default_registry().dialects.items() if c.READER is not None)


def _errors(program: str, dialect: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(program), io.StringIO(), file="p.nc", source=dialect, target=dialect,
                  setup=setup or MachineSetup())
    return [str(e) for e in info.value.errors]


def _metric(dialect: str, prologue: str) -> str:
    """Fagor's metric code is G71 (its G21 is no code of the 8070 reference)."""
    return prologue.replace("G21", "G71") if dialect == "fagor" else prologue


@pytest.mark.parametrize("dialect", READABLE)
@pytest.mark.parametrize("line, message", [
    ("G0 X\u0661\u0660.", "p.nc:2:5: error: character '\u0661' (U+0661) is not ASCII: outside comments a program "
                          "is ASCII"),
    ("G0 \uff3810.", "p.nc:2:4: error: character '\uff38' (U+FF38) is not ASCII: outside comments a program is "
                     "ASCII"),
    # a byte that is not UTF-8 is read as a surrogate (surrogateescape) and named as the byte the file holds
    ("G0 X\udcff2.", "p.nc:2:5: error: byte 0xFF (not UTF-8) is not ASCII: outside comments a program is ASCII"),
    ("G0 X" + "1" * 5000 + ".", "p.nc:2:5: error: a number with more than 30 digits cannot be read"),
    ("G0 X1" + "1" * 399, "p.nc:2:5: error: a number with more than 30 digits cannot be read"),
    ("G0 X" + "1" * 16 + "." + "1" * 16, "p.nc:2:5: error: a number with more than 30 digits cannot be read"),
])
def test_unreadable_line_is_a_located_error(dialect: str, line: str, message: str) -> None:
    # G90 is the absolute mode of a mill and the turning cycle of a lathe (GSK): a lathe gets G21 alone
    prologue = "G21" if "mill" not in default_registry().dialect(dialect).MACHINE_TYPES else "G21 G90"
    prologue = _metric(dialect, prologue)
    assert _errors(f"{prologue}\n{line}\nM30\n", dialect) == [message]


@pytest.mark.parametrize("dialect", READABLE)
def test_line_longer_than_the_limit_is_refused_before_reading(dialect: str) -> None:
    setup = MachineSetup(limits=Limits(line_length=40))
    line = "G0 X1. Y2. Z3." + " " * 40
    assert _errors(f"{_metric(dialect, 'G21')}\n{line}\nM30\n", dialect, setup) == [
        "p.nc:2:41: error: the line is 54 characters long, more than the limit of 40 (the set-up's "
        "<Limits lineLength>)"]


def test_default_line_limit_is_64k() -> None:
    assert Limits().line_length == 65_536
    line = "G0 X1." + " " * 70_000
    assert _errors(f"{line}\n", "fanuc")[0].startswith("p.nc:1:65537: error: the line is 70006 characters")


def test_every_bad_line_is_reported_and_line_numbers_stay() -> None:
    program = "G21\nG0 X\u0661.\nG0 X1.\nG1 X" + "9" * 40 + ". F100.\nM30\n"
    errors = _errors(program, "fanuc")
    assert [e.split(": error")[0] for e in errors] == ["p.nc:2:5", "p.nc:4:5"]


@pytest.mark.parametrize("comment", ["(caf\u00e9 \u0661\u0660 " + "1" * 50 + ")", "(caf\udce9)"])
def test_comments_keep_any_character(comment: str) -> None:
    program = f"G21 G90\nG0 X1. {comment}\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="fanuc")
    assert out.getvalue() == program


def test_thirty_digits_are_read() -> None:
    program = "G21 G90\nG0 X" + "1" * 15 + "." + "2" * 15 + "\nM30\n"
    moves = [e for e in toolpath_events(io.StringIO(program), file="p.nc", dialect="fanuc") if "move" in e]
    assert moves[0]["x"] == pytest.approx(111111111111111.2222)


def test_linuxcnc_semicolon_comment_keeps_any_character() -> None:
    program = "G21 G90\nG0 X1. ; caf\u00e9 \u0661\u0660\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.ngc", source="linuxcnc", target="linuxcnc")
    assert out.getvalue() == program


@pytest.mark.parametrize("dialect", ["fanuc", "linuxcnc"])
def test_signed_g_code_is_an_unknown_code_not_an_internal_error(dialect: str) -> None:
    """'G-.0' was an int('-') ValueError (found by the reader's fuzz test); never read as G0."""
    assert _errors("G-.0\nG-1 X1.\n", dialect) == ["p.nc:1:1: error: unknown G code G-.0",
                                                  "p.nc:2:1: error: unknown G code G-1"]
