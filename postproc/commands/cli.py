"""The command line (a stable interface: see DESIGN.md): one command's process, from its arguments to its exit
status. Exit 0 ok, 1 program/config errors, 2 usage. The options are in ``command_line``, what each command
does in ``handlers``."""

from __future__ import annotations

import contextlib
import os
import sys
# ``signal``'s C core, built into the interpreter (typeshed has no stub for it: its names are Any here): ``signal``
# wraps the same functions to turn numbers into enums it builds from the core's names at its import, ~3.3M
# instructions of every start (callgrind) for handlers a command only sets and puts back.
import _signal
from typing import Iterator, Sequence

from .. import native
native.install()  # the compiled hot path, before any of its modules is imported

from ..errors import ErrorList, PostprocError, UsageError
from .command_line import COMMANDS, build_parser, handler

EXIT_INTERRUPTED = 128 + int(_signal.SIGINT)
EXIT_TERMINATED = 128 + int(_signal.SIGTERM)


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
        previous = {sig: _signal.signal(sig, handler) for sig, handler in
                    ((_signal.SIGINT, _signal.default_int_handler), (_signal.SIGTERM, terminate))}
    except ValueError:  # not the main thread (what threading would tell, without importing it)
        previous = None
    if previous is None:
        yield
        return
    try:
        yield
    finally:
        for sig, handler in previous.items():
            _signal.signal(sig, handler)


def _main(argv: Sequence[str] | None) -> int:
    given = sys.argv[1:] if argv is None else argv
    parser = build_parser(given[0] if given and given[0] in COMMANDS else None)  # a run: its command's parser
    args = parser.parse_args(argv)
    if not args.command:
        parser.print_help(sys.stderr)
        return 2
    try:
        return int(handler(args.command)(args))
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


if __name__ == "__main__":
    sys.exit(main())
