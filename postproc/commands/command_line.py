"""The command line's grammar: every command with its options, their help and examples, and the checks of an
option's text that argparse reports as wrong usage (exit 2). What each command does is in ``handlers``
(``postproc dialects``: ``dialect_table``), imported by ``handler`` for the command that runs: building the
parser imports none of them, so ``postproc dialects`` and ``--version`` do not load the translation's modules
(``postproc.api``, the lowering steps, frames, cycles), which the handlers and the option checks of
``--arcs`` and ``--transform`` import."""

from __future__ import annotations

import argparse
import importlib
import math
import os
import sys
from typing import TYPE_CHECKING, Callable

from .. import native
from ..collector import gc_paused

if TYPE_CHECKING:  # imported by the checks that use them (see the module docstring)
    from ..lowering.arcs import ArcOption
    from ..transforms.spec import ProgramTransform

HANDLERS = {"translate": "handlers:cmd_translate", "toolpath": "handlers:cmd_toolpath",
            "verify": "handlers:cmd_verify", "ir": "handlers:cmd_ir", "info": "handlers:cmd_info",
            "dialects": "dialect_table:cmd_dialects", "config": "handlers:cmd_config"}
"""Each command's function, as ``module:name`` in ``postproc.commands``."""


FREEZE_IMPORTS = False
"""Set by the command's own process (``postproc.commands.launch``): what a command's modules and its one run make
while the collector is paused (``gc_paused(freeze=FREEZE_IMPORTS)``) is frozen (``gc.freeze``) as the process goes
on, as what the command line's imports made is there; a program that calls ``main`` keeps its collector as it is.

The collector is off while a command's modules load and its one run (a single translation, the dialect table)
goes: the imports only allocate (classes, functions, tables that live as long as the process), and its
collections while they did (37 in a one-line translation, each walking what had been made so far; one more as
the run ended, walking everything) cost it 3.4 % of its instructions (callgrind, compiled build). In the
command's process what was made is frozen at the end (the process exits next, or goes on with its own
collections walking only what it makes from then on)."""


def handler(command: str) -> Callable[[argparse.Namespace], int]:
    """The function that runs ``command`` (a key of ``HANDLERS``), its module imported now
    (``FREEZE_IMPORTS`` says why the collector is paused), with the plugin-hook lane installed
    (``postproc.fast.plugin_hooks``: a command's registry is made without pluggy where pluggy would call the hooks
    plainly)."""
    module, _, name = HANDLERS[command].partition(":")
    with gc_paused(freeze=FREEZE_IMPORTS):
        from ..fast import plugin_hooks
        plugin_hooks.install()  # the registry calls the plugins' hooks through the lane where it can
        found: Callable[[argparse.Namespace], int] = getattr(importlib.import_module(f"{__package__}.{module}"),
                                                             name)
    return found


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
    """The distribution's version (``postproc.version``: the constant the build reads, so the installed metadata
    says the same) and which build of the hot path runs."""
    from ..version import VERSION
    return f"postproc {VERSION}, hot path {native.describe()}"


class _Version(argparse.Action):
    """``--version``, made only when asked."""

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


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The command line's parser: every command's, or with ``only`` (a command's name) that command's alone, which
    parses that command's arguments as the whole parser does. A run names its command first (``cli``), so it builds
    one subparser instead of seven: argparse makes a formatter for every argument and looks up a translation for
    every parser's headings (gettext, with a ``stat`` per locale folder), ~16M instructions of every start for
    the whole parser (cachegrind)."""
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

    for name, build in COMMANDS.items():
        if only is None or name == only:
            build(command)
    return p


Command = Callable[[str, str, str], argparse.ArgumentParser]
"""``build_parser``'s ``command``: adds a command's subparser (name, help, description)."""


def _translate_command(command: Command) -> None:
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
    t.add_argument("--transform", type=_transform, metavar="OPS",
                   help="move the whole program: 'translate DX,DY[,DZ]', 'rotate DEG [about X,Y] [in xy|zx|yz]', "
                        "'mirror x|y|z.. [about V]', 'scale S[,SY,SZ] [about X,Y,Z]', joined by ';' (mm, degrees)")


def _toolpath_command(command: Command) -> None:
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


def _verify_command(command: Command) -> None:
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
    v.add_argument("--transform", type=_transform, metavar="OPS",
                   help="OUT was translated with this --transform: IN's path is moved by it before comparing")
    v.add_argument("--arcs", type=_arcs, metavar="lines:TOL|ijk|r",
                   help="OUT was translated with --arcs: with lines:TOL its chords may lie within TOL mm of IN's "
                        "arcs (each checked against its arc); ijk and r change nothing to compare")


def _ir_command(command: Command) -> None:
    i = command("ir", "print a program's IR as XML",
                "Read a program and write its dialect-neutral IR as XML (one element per block).")
    i.add_argument("input", metavar="IN", help=f"the program to read ({STDIO})")
    i.add_argument("--dialect", required=True, metavar="DIALECT", help="dialect of IN")
    i.add_argument("--machine", metavar="M.xml", help=MACHINE)
    i.add_argument("-o", "--output", metavar="OUT", help=OUTPUT)


def _info_command(command: Command) -> None:
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


def _dialects_command(command: Command) -> None:
    d = command("dialects", "list installed dialects and their capabilities",
                "List the installed dialects: what each reads and writes and its capability table.")
    d.add_argument("--format", choices=("table", "json"), default="table",
                   help="table (default, for people) or json (for tools)")
    d.add_argument("--json", dest="format", action="store_const", const="json", help="the same as --format json")


def _config_command(command: Command) -> None:
    c = command("config", "check or dump a machine set-up",
                "Check a machine set-up (every error with its line; templates rendered with sample values) "
                "or write it back in canonical form.")
    c.add_argument("action", choices=("check", "dump"), help="check: validate; dump: write the canonical form")
    c.add_argument("file", help="the set-up XML (M.xml)")
    c.add_argument("--define", action="append", default=[], metavar="NAME=VALUE",
                   help="a variable the templates are checked with (as translate --define)")
    c.add_argument("--flatten", action="store_true",
                   help="dump: write the set-up resolved, without extends (default: extends and the file's own values)")


COMMANDS: dict[str, Callable[[Command], None]] = {
    "translate": _translate_command,
    "toolpath": _toolpath_command,
    "verify": _verify_command,
    "ir": _ir_command,
    "info": _info_command,
    "dialects": _dialects_command,
    "config": _config_command,
}
"""Each command's subparser, in the order ``postproc --help`` lists them."""


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
    from ..errors import UsageError
    from ..lowering.arcs import parse_arc_option
    try:
        return parse_arc_option(text)
    except UsageError as err:
        raise argparse.ArgumentTypeError(err.message) from None


def _transform(text: str) -> ProgramTransform:
    """``--transform OPS`` (``postproc.transforms.spec.transform_argument``)."""
    from ..transforms.spec import transform_argument
    return transform_argument(text)



def _program_number(text: str) -> int:
    """``--program-number N``: a whole number 1-9999 (argparse reports anything else as a usage error)."""
    try:
        number = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if not 1 <= number <= 9999:
        raise argparse.ArgumentTypeError(f"{number} is not a program number (1-9999)")
    return number

