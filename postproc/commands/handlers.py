"""What each command does (``cmd_*``, run by ``cli`` with the options ``command_line`` parsed), and what the
single-file commands share: the set-up, the program read from a file or standard input, the output."""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import re
import sys
from typing import Iterable, Iterator, Sequence, TextIO

from ..errors import ConfigError, Diagnostics, Location, UsageError
from ..output.outfile import BUFFER, ENCODING, write_output
from ..plugins import default_registry  # (first of the compiled path's users: it installs it, native.install)
from ..reading import read_blocks
from ..setup.machine_setup import MachineSetup, check_named_file, load_setup
from ..xmlio import parse_xml_file, to_bytes
from . import command_line
from ..collector import gc_paused
from .progress import AboveProgress, progress_for


def _setup(path: str | None, lib: Sequence[str] = ()) -> MachineSetup:
    if path:
        check_named_file(path)
    if path:
        from ..fast.setup_values import plain_record  # the set-up lane: pydantic only for what it cannot read
        setup = load_setup(path, groups=default_registry().setup_groups, lane=plain_record)
    else:
        setup = MachineSetup()
    for folder in lib:
        if not os.path.isdir(folder):
            raise UsageError(f"--lib {folder}: no such directory")
        setup.library.append(os.path.abspath(folder))
    return setup


STDIN_NAME = "<stdin>"
"""How messages name standard input."""


@contextlib.contextmanager
def _open_program(path: str) -> Iterator[TextIO]:
    """The program ``path`` names, or standard input for ``-`` (read as files are, and left open)."""
    if path == "-":
        stdin = io.TextIOWrapper(sys.stdin.buffer, **ENCODING)  # type: ignore[arg-type]
        try:
            yield stdin
        finally:
            stdin.detach()
        return
    try:
        src = open(path, "r", buffering=BUFFER, **ENCODING)  # type: ignore[call-overload]
    except OSError as exc:
        raise UsageError(f"cannot read {path}: {exc.strerror}") from None
    with src:
        yield src


def _name(path: str) -> str:
    return STDIN_NAME if path == "-" else path


def _output(path: str | None) -> str | None:
    """``-o -`` is standard output, as no ``-o``."""
    return None if path == "-" else path


def _input_path(path: str) -> str | None:
    """The input, for the check that ``-o`` does not overwrite it (standard input cannot be)."""
    return None if path == "-" else path


def _watched(path: str, src: TextIO, setup: MachineSetup) -> tuple[Iterable[str], Diagnostics]:
    """The input's lines, with a progress bar where one is shown (``postproc.commands.progress``), and the
    diagnostics whose warnings print above the bar. The bar reads the lines as the check of their
    length does (``postproc.syntaxes.lines.pieces``): never a line longer than the limit at once."""
    progress = progress_for(path)
    if progress is None:
        return src, Diagnostics()
    from ..syntaxes.lines import pieces
    return (progress.lines(pieces(src, setup.limits.line_length)),
            Diagnostics(warn_stream=AboveProgress(progress, sys.stderr)))  # type: ignore[arg-type]


def cmd_translate(args: argparse.Namespace) -> int:
    renumber = _renumber(args.renumber)
    if (args.tolerance is not None or args.allow_ignored) and not args.verify:
        raise UsageError("--tolerance and --allow-ignored go with --verify")
    from .batch import is_batch
    if is_batch(args):
        if args.program_number is not None:
            raise UsageError("--program-number numbers one program: not with several inputs")
        from .batch.command import run_batch
        if args.tolerance is None:
            args.tolerance = 0.001
        return run_batch(args, renumber)
    with gc_paused(freeze=command_line.FREEZE_IMPORTS):  # one program: its run and the modules it loads
        return _translate_one(args, renumber)


def _translate_one(args: argparse.Namespace, renumber: tuple[int, int | None] | None) -> int:
    """``postproc translate`` of one program (``cmd_translate``)."""
    (path,) = args.input
    setup = _setup(args.machine, args.lib)
    if args.normalize:
        setup.output.normalize = True
    if args.program_number is not None:
        if not default_registry().dialect(args.target).PROGRAM_NUMBERS:
            raise UsageError(f"--program-number: the {args.target} dialect writes no program number")
        setup.output.program_number = args.program_number
    if renumber is not None:
        from .renumbering import apply_renumber
        apply_renumber(setup.output, renumber, args.source, args.target)
    from ..api import translate  # (here: toolpath, verify and ir have no use for the translation's own modules)
    from ..lowering.sequences import parse_defines
    defines = parse_defines(args.define)
    with _open_program(path) as src:
        lines, diagnostics = _watched(path, src, setup)
        write_output(_output(args.output), lambda out: translate(
            lines, out, file=_name(path), source=args.source, target=args.target, setup=setup,
            on_unsupported=args.on_unsupported, diagnostics=diagnostics, defines=defines, units=args.units,
            transform=args.transform, arcs=args.arcs),
            input_path=_input_path(path), in_place=args.in_place)
    return 0



_ARGUMENT = r"([A-Za-z])=([-+]?(?:\d+\.?\d*|\.\d+))"
"""Compiled where first used (``--arg``), not at every start."""


def _arguments(texts: Sequence[str]) -> dict[str, float]:
    """``--arg A=30`` (repeatable) as {"A": 30.0}; the dialect checks the addresses (wrong usage otherwise)."""
    found: dict[str, float] = {}
    for text in texts:
        m = re.fullmatch(_ARGUMENT, text.strip())
        if m is None:
            raise UsageError(f"--arg takes LETTER=NUMBER (A=30), got {text!r}")
        letter = m.group(1).upper()
        if letter in found:
            raise UsageError(f"--arg {letter} is given twice")
        found[letter] = float(m.group(2))
    return found


def _renumber(text: str | None) -> tuple[int, int | None] | None:
    """``--renumber START[,STEP]`` as numbers (a usage error otherwise; the set-up checks their range). START 0
    (or an empty value) is wrong usage: the option asks for numbering, and a set-up's ``renumberStart`` 0 means
    "keep the numbers as written", so it would be dropped without a word (docs/cli.md)."""
    if text is None:
        return None
    from ..setup.machine_setup import OutputSettings
    from ..setup.validate import Invalid, validate
    start, _, step = text.partition(",")
    try:
        numbers = int(start), int(step) if step else None
        given = {"renumber_start": numbers[0]} | ({} if numbers[1] is None else {"renumber_step": numbers[1]})
        validate(OutputSettings, given)  # the set-up's own bounds
    except (ValueError, Invalid):
        raise UsageError(f"--renumber takes START[,STEP], got {text!r}") from None
    if numbers[0] == 0:
        raise UsageError(f"--renumber numbers the blocks from START, at least 1, got {text!r} (0 is the set-up's "
                         "renumberStart for keeping the numbers as written: leave the option out for that)")
    return numbers


def cmd_toolpath(args: argparse.Namespace) -> int:
    from .export import export_toolpath
    setup = _setup(args.machine, args.lib)
    binary = args.format == "png"
    if binary and not args.output:
        raise UsageError("--format png needs -o OUT")
    if binary and args.output == "-":
        raise UsageError("--format png needs -o OUT, a file")
    with _open_program(args.input) as src:
        lines, diagnostics = _watched(args.input, src, setup)
        write_output(_output(args.output), lambda out: export_toolpath(
            lines, out, file=_name(args.input), dialect=args.dialect, setup=setup, fmt=args.format,
            diagnostics=diagnostics, on_unsupported=args.on_unsupported, arguments=_arguments(args.arg)),
            binary=binary, input_path=_input_path(args.input))
    return 0


def cmd_verify(args: argparse.Namespace) -> int:
    from ..drawing.overlay import Overlay, plot_format
    from ..simulate.verify import verify_lines
    fmt = plot_format(args.plot) if args.plot else None
    overlay = Overlay(_name(args.input), _name(args.output)) if fmt else None
    setup = _setup(args.machine, args.lib)
    target_setup = _setup(args.target_machine, args.lib) if args.target_machine else None  # the same machine
    if args.input == "-" and args.output == "-":
        raise UsageError("verify reads at most one of IN and OUT from standard input")
    try:
        with _open_program(args.input) as a, _open_program(args.output) as b:
            report = verify_lines(a, b, file_in=_name(args.input), file_out=_name(args.output),
                                  source=args.source, target=args.target, setup=setup,
                                  target_setup=target_setup, tolerance=args.tolerance,
                                  allow_ignored=args.allow_ignored, overlay=overlay,
                                  arguments=_arguments(args.arg), transform=args.transform,
                                  chord_tolerance=args.arcs.tolerance if args.arcs and args.arcs.form == "lines" else None)
        if overlay is not None:
            write_output(args.plot, lambda out: overlay.write(out, str(fmt), report), binary=fmt == "png",
                         input_path=_input_path(args.input))
    finally:
        if overlay is not None:
            overlay.close()
    print(report.summary())
    return 0 if report.ok else 1


def cmd_ir(args: argparse.Namespace) -> int:
    from .program_xml import dump_program
    setup = _setup(args.machine)
    registry = default_registry()
    dialect = registry.dialect(args.dialect)
    diagnostics = Diagnostics()

    def write(out: TextIO) -> None:
        with _open_program(args.input) as src:
            _, blocks = read_blocks(src, _name(args.input), dialect, setup, diagnostics)
            dump_program(blocks, out, dialect=dialect.NAME, file=_name(args.input))  # type: ignore[arg-type]
        diagnostics.check()

    write_output(_output(args.output), write, binary=True, input_path=_input_path(args.input))
    return 0


def cmd_info(args: argparse.Namespace) -> int:
    from .info import program_info, render_text
    setup = _setup(args.machine, args.lib) if args.machine or args.lib else None
    with _open_program(args.input) as src:
        report = program_info(src, file=_name(args.input), dialect=args.dialect, setup=setup,
                              machine=args.machine is not None)
    if args.format == "json":
        import json
        print(json.dumps(report, indent=2))
    else:
        render_text(report, sys.stdout)
    return 0


def cmd_config(args: argparse.Namespace) -> int:
    """Every problem of the set-up at once: its values, its dialect, its pipeline, its templates."""
    from ..setup.machine_setup import load_setup_collect
    from ..setup.load import raise_all
    from ..lowering.sequences import check_templates
    registry = default_registry()
    check_named_file(args.file)
    setup, problems = load_setup_collect(args.file, registry.setup_groups)
    if setup.dialect:
        try:
            registry.dialect(setup.dialect)
        except UsageError as err:  # a set-up naming a missing dialect is a configuration error
            root = parse_xml_file(args.file)
            problems.append(ConfigError(err.message, Location(args.file, root.sourceline or 1, 1)))
    from ..setup.foreign_codes import unknown_families
    problems.extend(unknown_families(setup.foreign_codes, {d.family() for d in registry.dialects.values()}, args.file))
    pipeline = setup.pipeline_path()
    if pipeline is not None:
        from ..syntaxes.syntax import load_pipeline
        try:
            load_pipeline(pipeline)
        except ConfigError as err:
            problems.append(err)
    from ..lowering.sequences import parse_defines
    target = registry.dialects.get(setup.dialect) if setup.dialect else None
    problems.extend(check_templates(setup, parse_defines(args.define), collect=True, target=target))
    raise_all(problems)
    if args.action == "check":
        print(f"{args.file}: ok")
        return 0
    from pathlib import Path
    base = str(Path(args.file).parent)
    sys.stdout.buffer.write(to_bytes(setup.make_xml_source(base, Path(args.file).name, True, flatten=args.flatten)))
    return 0

