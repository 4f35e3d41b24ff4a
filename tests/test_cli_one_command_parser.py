"""A run builds its own command's parser alone (``build_parser(only=...)``, start-up): it parses every command
line as the whole parser does, and refuses what the whole parser refuses, with the same message."""

from __future__ import annotations

import contextlib
import io
import shlex

import pytest

from postproc.commands.command_line import COMMANDS, EXAMPLES, build_parser


def _example_lines() -> list[list[str]]:
    """Every example of every command's ``--help``, as argv (the examples are what users copy)."""
    lines = []
    for text in EXAMPLES.values():
        for line in text.splitlines():
            words = shlex.split(line.split("|")[-1].split(" > ")[0], comments=True)
            if words and words[0] == "postproc":
                lines.append(words[1:])
    return lines


EXTRA = [
    ["translate", "a.nc", "b.nc", "--from", "fanuc", "--to", "grbl", "--arcs", "ijk", "--units", "inch"],
    ["translate", "-", "--from", "fanuc", "--to", "linuxcnc", "--transform", "translate 1,2", "--define", "A=1"],
    ["verify", "a.nc", "b.ngc", "--from", "fanuc", "--to", "linuxcnc", "--tolerance", "0.01", "--arcs", "lines:0.01"],
    ["dialects", "--json"],
]


@pytest.mark.parametrize("argv", _example_lines() + EXTRA, ids=" ".join)
def test_a_commands_own_parser_reads_as_the_whole_parser(argv: list[str]) -> None:
    assert argv[0] in COMMANDS
    assert _values(build_parser(argv[0]).parse_args(argv)) == _values(build_parser().parse_args(argv))


def _values(args: object) -> dict[str, object]:
    """The parsed options; a transform by its text (its map has no equality of its own)."""
    return {name: getattr(value, "text", value) for name, value in vars(args).items()}


@pytest.mark.parametrize("argv", [
    ["translate", "a.nc", "--from", "fanuc"],
    ["translate", "a.nc", "--from", "fanuc", "--to", "grbl", "--units", "furlong"],
    ["verify", "a.nc", "--from", "fanuc", "--to", "grbl", "--tolerance", "-1"],
    ["config", "lint", "m.xml"],
    ["translate", "--help"],
])
def test_a_commands_own_parser_refuses_as_the_whole_parser(argv: list[str]) -> None:
    said = []
    for parser in (build_parser(argv[0]), build_parser()):
        out, err = io.StringIO(), io.StringIO()
        with pytest.raises(SystemExit) as done, contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            parser.parse_args(argv)
        said.append((done.value.code, out.getvalue(), err.getvalue()))
    assert said[0] == said[1]
    assert said[0][1] or said[0][2]  # it said something
