"""The command line (a stable interface: see DESIGN.md). Exit 0 ok, 1 program/config errors, 2 usage."""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import signal
import sys
import threading
from pathlib import Path
from typing import Iterator, Sequence, TextIO

from .api import read_blocks, translate
from .errors import ConfigError, Diagnostics, ErrorList, Location, PostprocError, UsageError
from .outfile import BUFFER, ENCODING, write_output
from .plugins import default_registry
from .setup import MachineSetup, load_setup
from .xmlio import parse_xml_file, to_bytes

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
    ``Terminated``, for the length of a command; the previous handlers come back afterwards."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def terminate(signum: int, frame: object) -> None:
        raise Terminated()

    previous = {sig: signal.signal(sig, handler) for sig, handler in
                ((signal.SIGINT, signal.default_int_handler), (signal.SIGTERM, terminate))}
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


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="postproc", description="Translate and post-process CNC part programs.")
    sub = p.add_subparsers(dest="command")

    t = sub.add_parser("translate", help="translate a program from one dialect to another")
    t.add_argument("input")
    t.add_argument("-o", "--output")
    t.add_argument("--from", dest="source", required=True)
    t.add_argument("--to", dest="target", required=True)
    t.add_argument("--machine")
    t.add_argument("--lib", action="append", default=[], metavar="DIR",
                   help="folder searched for subprograms (repeatable; after the set-up's <Library>)")
    t.add_argument("--on-unsupported", choices=("error", "warn"), default="error")
    t.add_argument("--normalize", action="store_true", help="write every decimal point explicitly")
    t.add_argument("--renumber", metavar="START[,STEP]", help="renumber blocks (implies --normalize)")
    t.add_argument("--in-place", action="store_true", help="allow -o to name the input (replace it)")
    t.set_defaults(run=cmd_translate)

    tp = sub.add_parser("toolpath", help="simulate a program and export its toolpath")
    tp.add_argument("input")
    tp.add_argument("--dialect", required=True)
    tp.add_argument("--machine")
    tp.add_argument("--lib", action="append", default=[], metavar="DIR",
                   help="folder searched for subprograms (repeatable; after the set-up's <Library>)")
    tp.add_argument("--format", choices=("jsonl", "svg", "png"), default="jsonl")
    tp.add_argument("-o", "--output")
    tp.set_defaults(run=cmd_toolpath)

    v = sub.add_parser("verify", help="compare the toolpaths of a program and its translation")
    v.add_argument("input")
    v.add_argument("output")
    v.add_argument("--from", dest="source", required=True)
    v.add_argument("--to", dest="target", required=True)
    v.add_argument("--machine")
    v.add_argument("--lib", action="append", default=[], metavar="DIR",
                   help="folder searched for subprograms (repeatable; after the set-up's <Library>)")
    v.add_argument("--target-machine", help="set-up of the target machine (default: --machine)")
    v.add_argument("--tolerance", type=_tolerance, default=0.001, help="mm (default 0.001)")
    v.set_defaults(run=cmd_verify)

    i = sub.add_parser("ir", help="print a program's IR as XML")
    i.add_argument("input")
    i.add_argument("--dialect", required=True)
    i.add_argument("--machine")
    i.add_argument("-o", "--output")
    i.set_defaults(run=cmd_ir)

    d = sub.add_parser("dialects", help="list installed dialects and their capabilities")
    d.add_argument("--json", action="store_true")
    d.set_defaults(run=cmd_dialects)

    c = sub.add_parser("config", help="check or dump a machine set-up")
    c.add_argument("action", choices=("check", "dump"))
    c.add_argument("file")
    c.set_defaults(run=cmd_config)
    return p


def _tolerance(text: str) -> float:
    """A finite, non-negative number of mm (argparse turns the error into usage, exit 2)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"must be a finite number of at least 0, got {text!r}")
    return value


def _setup(path: str | None, lib: Sequence[str] = ()) -> MachineSetup:
    setup = load_setup(path) if path else MachineSetup()
    for folder in lib:
        if not os.path.isdir(folder):
            raise UsageError(f"--lib {folder}: no such directory")
        setup.library.append(os.path.abspath(folder))
    return setup


def _open_program(path: str) -> TextIO:
    try:
        return open(path, "r", buffering=BUFFER, **ENCODING)  # type: ignore[call-overload,no-any-return]
    except OSError as exc:
        raise UsageError(f"cannot read {path}: {exc.strerror}") from None


def cmd_translate(args: argparse.Namespace) -> int:
    setup = _setup(args.machine, args.lib)
    if args.normalize:
        setup.output.normalize = True
    if args.renumber:
        start, _, step = args.renumber.partition(",")
        try:
            setup.output.renumber_start = int(start)
            if step:
                setup.output.renumber_step = int(step)
        except ValueError:
            raise UsageError(f"--renumber takes START[,STEP], got {args.renumber!r}") from None
    with _open_program(args.input) as src:
        write_output(args.output, lambda out: translate(
            src, out, file=args.input, source=args.source, target=args.target, setup=setup,
            on_unsupported=args.on_unsupported), input_path=args.input, in_place=args.in_place)
    return 0


def cmd_toolpath(args: argparse.Namespace) -> int:
    from .export import export_toolpath
    setup = _setup(args.machine, args.lib)
    binary = args.format == "png"
    if binary and not args.output:
        raise UsageError("--format png needs -o OUT")
    with _open_program(args.input) as src:
        write_output(args.output, lambda out: export_toolpath(
            src, out, file=args.input, dialect=args.dialect, setup=setup, fmt=args.format), binary=binary,
            input_path=args.input)
    return 0


def cmd_verify(args: argparse.Namespace) -> int:
    from .verify import verify_files
    setup = _setup(args.machine, args.lib)
    target_setup = _setup(args.target_machine, args.lib) if args.target_machine else None  # the same machine
    report = verify_files(args.input, args.output, source=args.source, target=args.target,
                          setup=setup, target_setup=target_setup, tolerance=args.tolerance)
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
            _, blocks = read_blocks(src, args.input, dialect, setup, diagnostics)
            dump_program(blocks, out, dialect=dialect.NAME, file=args.input)  # type: ignore[arg-type]
        diagnostics.check()

    write_output(args.output, write, binary=True, input_path=args.input)
    return 0


def cmd_dialects(args: argparse.Namespace) -> int:
    registry = default_registry()
    table = {name: {"description": cls.DESCRIPTION, "reads": cls.READER is not None,
                    "writes": cls.WRITER is not None, "capabilities": cls.capabilities()}
             for name, cls in sorted(registry.dialects.items())}
    if args.json:
        print(json.dumps(table, indent=2))
        return 0
    for name, info in table.items():
        rw = "/".join(x for x, ok in (("read", info["reads"]), ("write", info["writes"])) if ok)
        print(f"{name} ({rw}): {info['description']}")
        capabilities: dict[str, object] = info["capabilities"]  # type: ignore[assignment]
        for key, value in capabilities.items():
            shown = (", ".join(value) or "none") if isinstance(value, list) else value
            print(f"  {key}: {shown}")
    return 0


def cmd_config(args: argparse.Namespace) -> int:
    default_registry()
    setup = load_setup(args.file)
    if setup.dialect:
        try:
            default_registry().dialect(setup.dialect)
        except UsageError as err:  # a set-up naming a missing dialect is a configuration error
            root = parse_xml_file(args.file)
            raise ConfigError(err.message, Location(args.file, root.sourceline or 1, 1)) from None
    pipeline = setup.pipeline_path()
    if pipeline is not None:
        from .syntax import load_pipeline
        load_pipeline(pipeline)
    from .templates import check_templates
    check_templates(setup)
    if args.action == "check":
        print(f"{args.file}: ok")
        return 0
    base = str(Path(args.file).parent)
    sys.stdout.buffer.write(to_bytes(setup.make_xml_source(base, Path(args.file).name, True)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
