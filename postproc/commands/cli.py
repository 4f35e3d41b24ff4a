"""The command line (a stable interface: see DESIGN.md). Exit 0 ok, 1 program/config errors, 2 usage."""

from __future__ import annotations

import argparse
import contextlib
import io
import math
import os
import re
import signal
import sys
from pathlib import Path
from typing import Iterable, Iterator, Sequence, TextIO

from .. import native
native.install()  # the compiled hot path, before any of its modules is imported

from ..api import read_blocks, translate
from ..lowering.arcs import ArcOption, parse_arc_option
from ..errors import ConfigError, Diagnostics, ErrorList, Location, PostprocError, UsageError
from ..output.outfile import BUFFER, ENCODING, write_output
from ..plugins import default_registry
from .progress import AboveProgress, progress_for
from ..setup.machine_setup import MachineSetup, check_named_file, load_setup
from ..transforms.spec import transform_argument
from ..xmlio import parse_xml_file, to_bytes

EXIT_INTERRUPTED = 128 + signal.SIGINT
EXIT_TERMINATED = 128 + signal.SIGTERM


class Terminated(BaseException):
    """SIGTERM, raised like ``KeyboardInterrupt`` so that clean-up (the temporary output) runs."""


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command. Ctrl-C and SIGTERM end it quietly (exit 130, 143) with no output left behind."""
    with _signals_raise():
        try:
            return _main(argv)
        except KeyboardInterrupt:
            return EXIT_INTERRUPTED
        except Terminated:
            return EXIT_TERMINATED


@contextlib.contextmanager
def _signals_raise() -> Iterator[None]:
    """SIGINT raises ``KeyboardInterrupt`` (even where the shell started us ignoring it) and SIGTERM
    ``Terminated``, for the length of a command; the previous handlers come back afterwards. Outside
    the main thread (a caller's worker) the handlers stay as they are: only the main thread may set them."""

    def terminate(signum: int, frame: object) -> None:
        raise Terminated()

    try:
        previous = {sig: signal.signal(sig, handler) for sig, handler in
                    ((signal.SIGINT, signal.default_int_handler), (signal.SIGTERM, terminate))}
    except ValueError:  # not the main thread (what threading would tell, without importing it)
        previous = None
    if previous is None:
        yield
        return
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def _main(argv: Sequence[str] | None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "run", None):
        parser.print_help(sys.stderr)
        return 2
    try:
        return int(args.run(args))
    except UsageError as err:
        print(f"postproc: {err.message}", file=sys.stderr)
        return 2
    except ErrorList as errs:
        for each in errs.errors:
            print(each, file=sys.stderr)
        for note in errs.notes:
            print(f"postproc: {note}", file=sys.stderr)
        return 1
    except PostprocError as err:
        print(err, file=sys.stderr)
        return 1
    except BrokenPipeError:
        return 0
    except Exception as exc:  # a bug of ours: report it briefly, never a bare traceback
        if os.environ.get("POSTPROC_DEBUG"):
            raise
        print(f"postproc: internal error: {type(exc).__name__}: {exc} (set POSTPROC_DEBUG=1 for details)",
              file=sys.stderr)
        return 1


EXAMPLES = {
    "translate": """\
  postproc translate o1001.nc --from fanuc --to linuxcnc -o o1001.ngc
  postproc translate o1002.nc --from fanuc --to grbl --on-unsupported warn -o o1002.gcode
  postproc translate o1004.nc --from fanuc --to fanuc --normalize --renumber 10,10 -o o1004.nc --in-place
  cat o1001.nc | postproc translate - --from fanuc --to grbl > o1001.gcode
  postproc translate programs/ -o migrated/ --from fanuc --to linuxcnc --ext ngc --verify --report report.jsonl""",
    "toolpath": """\
  postproc toolpath o1003.nc --dialect fanuc                  # JSON lines on standard output
  postproc toolpath o1003.nc --dialect fanuc --format svg -o o1003.svg""",
    "verify": """\
  postproc translate o1001.nc --from fanuc --to grbl -o o1001.gcode
  postproc verify o1001.nc o1001.gcode --from fanuc --to grbl    # exit 1 above the tolerance
  postproc verify o1001.nc o1001.gcode --from fanuc --to grbl --plot diff.svg   # both toolpaths, overlaid""",
    "ir": """\
  postproc ir o1001.nc --dialect fanuc -o o1001.xml""",
    "info": """\
  postproc info o1001.nc --dialect fanuc                       # extent, tools, run time, targets
  postproc info o1001.nc --dialect fanuc --machine vmc.xml --format json""",
    "dialects": """\
  postproc dialects                  # one column per dialect, one row per capability
  postproc dialects --format json    # the same for tools""",
    "config": """\
  postproc config check examples/setups/fanuc_0i_mf_calculator.xml
  postproc config dump examples/setups/fanuc_0i_mf_calculator.xml > canonical.xml
  postproc config dump --flatten examples/setups/haas_vf2_cell3.xml > resolved.xml""",
}
"""One example (or a few) per command, shown by its ``--help`` (``examples``)."""


def examples(*commands: str) -> str:
    """The examples of ``commands`` under one heading: ``postproc --help`` shows several commands' examples
    together, each ``COMMAND --help`` its own."""
    lines = "\n".join(EXAMPLES[c] for c in commands)
    return ("example:\n" if lines.count("\n") == 0 else "examples:\n") + lines

STDIO = "'-' reads standard input"
MACHINE = "machine set-up XML (decimal-point mode, cycle parameters, output format, ...; see docs/setup-reference.md)"
LIB = "folder searched for subprograms (repeatable; after the set-up's <Library>)"
ARG = ("IN is a macro file run on its own, as if called with this argument (A=30: #1 = 30 on Fanuc; "
       "repeatable)")
OUTPUT = "write here instead of standard output ('-': standard output); written only on success, atomically"


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version
    try:
        number = version("postproc")
    except PackageNotFoundError:  # run from a checkout that is not installed
        number = "unknown"
    return f"postproc {number}, hot path {native.describe()}"


class _Version(argparse.Action):
    """``--version``, looked up only when asked (a run does not pay for importlib.metadata)."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace, values: object,
                 option_string: str | None = None) -> None:
        print(_version())
        parser.exit()


class _Formatter(argparse.RawDescriptionHelpFormatter):
    """argparse's formatter, sized to the terminal as argparse sizes it but without importing shutil:
    argparse makes a formatter for every argument it adds, each importing shutil (with bz2 and lzma) for
    ``shutil.get_terminal_size``, which a run that prints no help then pays for (~1.5 ms)."""

    def __init__(self, prog: str, indent_increment: int = 2, max_help_position: int = 24,
                 width: int | None = None) -> None:
        super().__init__(prog, indent_increment, max_help_position, _columns() - 2 if width is None else width)


def _columns() -> int:
    """``shutil.get_terminal_size().columns``: $COLUMNS, else the width of the terminal on standard
    output, else 80."""
    try:
        columns = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns  # type: ignore[union-attr]
        except (AttributeError, ValueError, OSError):
            columns = 0
    return columns or 80


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="postproc", formatter_class=_Formatter,
        description="Translate CNC part programs between controller dialects (fanuc, linuxcnc, grbl, ...) "
                    "and check that a translation moves the tool exactly as its source.",
        epilog=examples("translate", "verify", "toolpath") + "\n\n"
               "exit status: 0 ok, 1 the program or set-up has errors (FILE:LINE:COL: error: ...), 2 wrong usage; "
               "warnings go to standard error.\n'postproc COMMAND --help' describes each command.")
    p.add_argument("--version", action=_Version, nargs=0,
                   help="the version, and whether the hot path runs compiled or as pure Python")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")

    def command(name: str, help: str, description: str) -> argparse.ArgumentParser:
        return sub.add_parser(name, help=help, description=description, epilog=examples(name),
                              formatter_class=_Formatter)

    t = command("translate", "translate a program from one dialect to another",
                "Translate a program from one controller dialect to another. Read back in its own dialect a "
                "program is reproduced byte for byte; what the target cannot express is a located error "
                "(or, with --on-unsupported warn, a warning and the line written as a comment).")
    t.add_argument("input", metavar="IN", nargs="+",
                   help=f"the program to translate ({STDIO}); several files or folders make a batch")
    t.add_argument("-o", "--output", metavar="OUT", help=OUTPUT + "; for a batch, the folder to write into")
    t.add_argument("--from", dest="source", required=True, metavar="DIALECT",
                   help="dialect of IN ('postproc dialects' lists them)")
    t.add_argument("--to", dest="target", required=True, metavar="DIALECT", help="dialect to write")
    t.add_argument("--machine", metavar="M.xml", help=MACHINE)
    t.add_argument("--lib", action="append", default=[], metavar="DIR", help=LIB)
    t.add_argument("--on-unsupported", choices=("error", "warn"), default="error",
                   help="what the target cannot express: a located error (default), or a warning with the "
                        "line kept as a comment")
    t.add_argument("--normalize", action="store_true",
                   help="write every decimal point explicitly (Fanuc X10 under least-increment input becomes "
                        "X0.01); no digit the program wrote is rounded away")
    t.add_argument("--renumber", metavar="START[,STEP]", help="renumber blocks (implies --normalize)")
    t.add_argument("--in-place", action="store_true", help="allow -o to name the input (replace it)")
    t.add_argument("--program-number", type=_program_number, metavar="N",
                   help="the main program's number (1-9999) in a dialect that writes one (Fanuc O, ISG %%): "
                        "replaces the source's, and numbers a named ISG/Fagor program (whose name is kept as "
                        "a comment); as <Output programNumber>")
    t.add_argument("--define", action="append", default=[], metavar="NAME=VALUE",
                   help="a variable the set-up's templates see as NAME (repeatable)")
    t.add_argument("--arcs", type=_arcs, metavar="lines:TOL|ijk|r",
                   help="rewrite every arc: as lines within TOL mm of it, in centre form (I J K) or in radius "
                        "form (R); a program that computes is flattened (see docs/cli.md)")
    _batch_arguments(t)
    t.add_argument("--units", choices=("mm", "inch"), help="convert the whole program to these units")
    t.add_argument("--transform", type=transform_argument, metavar="OPS",
                   help="move the whole program: 'translate DX,DY[,DZ]', 'rotate DEG [about X,Y] [in xy|zx|yz]', "
                        "'mirror x|y|z.. [about V]', 'scale S[,SY,SZ] [about X,Y,Z]', joined by ';' (mm, degrees)")
    t.set_defaults(run=cmd_translate)

    tp = command("toolpath", "simulate a program and export its toolpath",
                 "Simulate a program and write its toolpath: JSON lines (end points in mm, arcs with centres, "
                 "spindle, coolant, tool, dwell and stop events, each with its source line) or a backplot.")
    tp.add_argument("input", metavar="IN", help=f"the program to simulate ({STDIO})")
    tp.add_argument("--dialect", required=True, metavar="DIALECT", help="dialect of IN")
    tp.add_argument("--machine", metavar="M.xml", help=MACHINE)
    tp.add_argument("--on-unsupported", choices=("error", "warn"), default="error",
                    help="warn: a move beyond the set-up's travel limits is a warning, not an error")
    tp.add_argument("--lib", action="append", default=[], metavar="DIR", help=LIB)
    tp.add_argument("--format", choices=("jsonl", "svg", "png"), default="jsonl",
                    help="jsonl (default), svg or png (png needs -o)")
    tp.add_argument("-o", "--output", metavar="OUT", help=OUTPUT)
    tp.add_argument("--arg", action="append", default=[], metavar="LETTER=VALUE", help=ARG)
    tp.set_defaults(run=cmd_toolpath)

    v = command("verify", "compare the toolpaths of a program and its translation",
                "Simulate a program and its translation and report the largest deviation between their "
                "toolpaths and where it happens. Exit 1 above the tolerance or when the moves differ.")
    v.add_argument("input", metavar="IN", help=f"the source program ({STDIO}, for one of IN and OUT)")
    v.add_argument("output", metavar="OUT", help="its translation")
    v.add_argument("--from", dest="source", required=True, metavar="DIALECT", help="dialect of IN")
    v.add_argument("--to", dest="target", required=True, metavar="DIALECT", help="dialect of OUT")
    v.add_argument("--machine", metavar="M.xml", help=MACHINE)
    v.add_argument("--lib", action="append", default=[], metavar="DIR", help=LIB)
    v.add_argument("--target-machine", metavar="TARGET.xml", help="set-up of the target machine (default: --machine)")
    v.add_argument("--tolerance", type=_tolerance, default=0.001, metavar="MM",
                   help="largest deviation accepted, in mm (default 0.001)")
    v.add_argument("--allow-ignored", action="store_true",
                   help="accept settings that move the tool (cutter compensation, tool length or work offset, "
                        "path control) differing between the programs; they are listed either way")
    v.add_argument("--plot", metavar="FILE.svg|FILE.png",
                   help="also draw both toolpaths over each other with the largest deviation marked (SVG, or "
                        "PNG with the render extra); written whatever the verdict")
    v.add_argument("--arg", action="append", default=[], metavar="LETTER=VALUE", help=ARG)
    v.add_argument("--units", choices=("mm", "inch"), help="OUT was translated with --units (both paths are in mm)")
    v.add_argument("--transform", type=transform_argument, metavar="OPS",
                   help="OUT was translated with this --transform: IN's path is moved by it before comparing")
    v.add_argument("--arcs", type=_arcs, metavar="lines:TOL|ijk|r",
                   help="OUT was translated with --arcs: with lines:TOL its chords may lie within TOL mm of IN's "
                        "arcs (each checked against its arc); ijk and r change nothing to compare")
    v.set_defaults(run=cmd_verify)

    i = command("ir", "print a program's IR as XML",
                "Read a program and write its dialect-neutral IR as XML (one element per block).")
    i.add_argument("input", metavar="IN", help=f"the program to read ({STDIO})")
    i.add_argument("--dialect", required=True, metavar="DIALECT", help="dialect of IN")
    i.add_argument("--machine", metavar="M.xml", help=MACHINE)
    i.add_argument("-o", "--output", metavar="OUT", help=OUTPUT)
    i.set_defaults(run=cmd_ir)

    n = command("info", "report a program's extent, tools, run time, holes, features and targets",
                "Simulate a program and report what a machinist asks before running it: its extent per axis (in "
                "machine coordinates too with --machine), the tools in order with their feed distance and time, the "
                "estimated run time, its holes and cycles, the features it uses, and which dialects can take it "
                "(each translation tried, nothing written).")
    n.add_argument("input", metavar="IN", help=f"the program ({STDIO})")
    n.add_argument("--dialect", required=True, metavar="DIALECT", help="dialect of IN")
    n.add_argument("--machine", metavar="M.xml", help=MACHINE + "; its <Axis rapid> rates time the rapids")
    n.add_argument("--lib", action="append", default=[], metavar="DIR", help=LIB)
    n.add_argument("--format", choices=("text", "json"), default="text",
                   help="text (default, for people) or json (for tools; the schema is in docs/cli.md)")
    n.set_defaults(run=cmd_info)

    d = command("dialects", "list installed dialects and their capabilities",
                "List the installed dialects: what each reads and writes and its capability table.")
    d.add_argument("--format", choices=("table", "json"), default="table",
                   help="table (default, for people) or json (for tools)")
    d.add_argument("--json", dest="format", action="store_const", const="json", help="the same as --format json")
    d.set_defaults(run=cmd_dialects)

    c = command("config", "check or dump a machine set-up",
                "Check a machine set-up (every error with its line; templates rendered with sample values) "
                "or write it back in canonical form.")
    c.add_argument("action", choices=("check", "dump"), help="check: validate; dump: write the canonical form")
    c.add_argument("file", help="the set-up XML (M.xml)")
    c.add_argument("--define", action="append", default=[], metavar="NAME=VALUE",
                   help="a variable the templates are checked with (as translate --define)")
    c.add_argument("--flatten", action="store_true",
                   help="dump: write the set-up resolved, without extends (default: extends and the file's own values)")
    c.set_defaults(run=cmd_config)
    return p


def _batch_arguments(t: argparse.ArgumentParser) -> None:
    """``translate`` over many files (postproc.commands.batch): any of these options makes the command a batch."""
    b = t.add_argument_group(
        "batch", "Several inputs, a folder, or any of these options translate every file into -o OUTDIR, keeping "
                 "paths relative to each folder given; a summary goes to standard output. See docs/cli.md.")
    b.add_argument("-j", "--jobs", type=_positive, metavar="N",
                   help="worker processes (default: every core); with --scheduler local, Dask workers")
    b.add_argument("--ext", metavar="EXT",
                   help="give each output this extension (ngc, .gcode; '' for none), replacing the input's "
                        "last one; default: the input's name unchanged")
    b.add_argument("--include", action="append", default=[], metavar="GLOB",
                   help="take only files whose name matches (repeatable; e.g. '*.nc'); default: every file "
                        "not hidden")
    b.add_argument("--report", metavar="REPORT.jsonl",
                   help="write one JSON line per file: status, warnings, errors, max deviation, time")
    b.add_argument("--verify", action="store_true",
                   help="verify each translation against its input; one that fails is not written")
    b.add_argument("--tolerance", type=_tolerance, metavar="MM", help="with --verify: largest deviation "
                   "accepted, in mm (default 0.001)")
    b.add_argument("--allow-ignored", action="store_true",
                   help="with --verify: accept settings that move the tool differing (see verify)")
    b.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on a Dask cluster: tcp://host:8786, or 'local' for a LocalCluster on this machine "
                        "(needs the dask extra; inputs and outputs on a path every worker sees)")
    b.add_argument("--files-per-task", type=_positive, metavar="N",
                   help="most files in one worker task (default 32, fewer for large files)")


def _positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text!r}")
    return value


def _tolerance(text: str) -> float:
    """A finite, non-negative number of mm (argparse turns the error into usage, exit 2)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"must be a finite number of at least 0, got {text!r}")
    return value


def _arcs(text: str) -> ArcOption:
    """``--arcs lines:TOL|ijk|r`` (argparse turns the error into usage, exit 2)."""
    try:
        return parse_arc_option(text)
    except UsageError as err:
        raise argparse.ArgumentTypeError(err.message) from None


def _setup(path: str | None, lib: Sequence[str] = ()) -> MachineSetup:
    if path:
        check_named_file(path)
    setup = load_setup(path, groups=default_registry().setup_groups) if path else MachineSetup()
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
    length does (``postproc.lines.pieces``): never a line longer than the limit at once."""
    progress = progress_for(path)
    if progress is None:
        return src, Diagnostics()
    from ..lines import pieces
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
    (path,) = args.input
    setup = _setup(args.machine, args.lib)
    if args.normalize:
        setup.output.normalize = True
    if args.program_number is not None:
        if not default_registry().dialect(args.target).PROGRAM_NUMBERS:
            raise UsageError(f"--program-number: the {args.target} dialect writes no program number")
        setup.output.program_number = args.program_number
    if renumber is not None:
        setup.output.renumber_start, step = renumber
        if step is not None:
            setup.output.renumber_step = step
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


def _program_number(text: str) -> int:
    """``--program-number N``: a whole number 1-9999 (argparse reports anything else as a usage error)."""
    try:
        number = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if not 1 <= number <= 9999:
        raise argparse.ArgumentTypeError(f"{number} is not a program number (1-9999)")
    return number


_ARGUMENT = re.compile(r"([A-Za-z])=([-+]?(?:\d+\.?\d*|\.\d+))")


def _arguments(texts: Sequence[str]) -> dict[str, float]:
    """``--arg A=30`` (repeatable) as {"A": 30.0}; the dialect checks the addresses (wrong usage otherwise)."""
    found: dict[str, float] = {}
    for text in texts:
        m = _ARGUMENT.fullmatch(text.strip())
        if m is None:
            raise UsageError(f"--arg takes LETTER=NUMBER (A=30), got {text!r}")
        letter = m.group(1).upper()
        if letter in found:
            raise UsageError(f"--arg {letter} is given twice")
        found[letter] = float(m.group(2))
    return found


def _renumber(text: str | None) -> tuple[int, int | None] | None:
    """``--renumber START[,STEP]`` as numbers (a usage error otherwise; the set-up checks their range)."""
    if not text:
        return None
    from ..setup.machine_setup import OutputSettings
    from ..setup.validate import Invalid, validate
    start, _, step = text.partition(",")
    try:
        numbers = int(start), int(step) if step else None
        given = {"renumber_start": numbers[0]} | ({} if numbers[1] is None else {"renumber_step": numbers[1]})
        validate(OutputSettings, given)  # the set-up's own bounds
        return numbers
    except (ValueError, Invalid):
        raise UsageError(f"--renumber takes START[,STEP], got {text!r}") from None


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


def cmd_dialects(args: argparse.Namespace) -> int:
    from .dialect_table import dialect_info, render_table
    info = dialect_info(default_registry().dialects)
    if args.format == "json":
        import json
        print(json.dumps(info, indent=2))
    else:
        sys.stdout.write(render_table(info))
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
        from ..syntax import load_pipeline
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
    base = str(Path(args.file).parent)
    sys.stdout.buffer.write(to_bytes(setup.make_xml_source(base, Path(args.file).name, True, flatten=args.flatten)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
