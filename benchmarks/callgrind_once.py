"""One run for benchmarks/callgrind.sh, as ``make bench`` runs it, in this interpreter so that valgrind
follows it. python callgrind_once.py SRC TGT NORMALIZE FILE.

Our commands run as the ``postproc`` command's process (``postproc.commands.launch``: the command line,
reading the file and writing one); a peer or the plain loop runs as its ``make bench`` script
(``benchmarks/peers.py``, ``benchmarks/plainloop.py``) with the same argument list. TGT:

- ``toolpath``: ``postproc toolpath FILE --dialect SRC --format jsonl`` on the benchmark machine;
- ``verify:DIALECT``: ``postproc verify FILE FILE.DIALECT --from SRC --to DIALECT`` on it;
- ``peer:TOOL``: ``peers.py TOOL FILE`` (gcodeparser reads the ``Z0.0`` copy ``make bench`` gives it);
  ``peer:TOOL+DIALECT``: over FILE and FILE.DIALECT (verify's baseline: ``gcode-lib-state`` over both files);
- ``plainloop``: ``plainloop.py FILE OUT``; ``plainloop:DIALECT``: over FILE.DIALECT (the baseline of the
  cycles and macro rows: the plain loop rewriting the translation);
- anything else: ``postproc translate --from SRC --to TGT`` with the options of its ``make bench`` row
  (``benchmarks/translations.py``); with ``CALLGRIND_PROGRAM`` cycles or macro (``callgrind.sh --program``)
  without options, as ``make bench``'s cycles and macro rows run it (``workloads.translate``).

FILE.DIALECT is the translation ``callgrind.sh`` prepares first, unmeasured (``PREPARE=1``: write it, for
a TGT that reads one; nothing for the others)."""
from __future__ import annotations

import os
import runpy
import sys
import tempfile

from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)


def translated(target: str) -> str | None:
    """The dialect whose translation of FILE the row reads (None: it reads FILE only)."""
    if target.startswith("verify:") or target.startswith("plainloop:"):
        return target.split(":", 1)[1]
    if target.startswith("peer:") and "+" in target:
        return target.split("+", 1)[1]
    return None


def script(name: str, *args: str) -> None:
    """Run a benchmarks/ script as ``python benchmarks/NAME ARGS`` runs it."""
    sys.argv = [os.path.join(HERE, name), *args]
    sys.path[0] = HERE
    try:
        runpy.run_path(sys.argv[0], run_name="__main__")
    except SystemExit as done:
        if done.code not in (None, 0):
            raise


def postproc(*argv: str) -> None:
    """Run the ``postproc`` command line in this process; an exit status other than 0 ends the run."""
    from postproc.commands.launch import run
    # Off sys.path, benchmarks/ is not in the entry-point cache's key (postproc.entry_points): an edit there
    # between the two measured runs made one of them discover the entry points again (~65 M instructions).
    sys.path[:] = [entry for entry in sys.path if entry != HERE]
    sys.argv = list(argv)
    try:
        run()
    except SystemExit as done:
        if done.code not in (None, 0):
            raise


def prepare(source: str, target: str, path: str) -> None:
    """What the row reads besides FILE, made unmeasured: FILE's translation to DIALECT; gcodeparser's
    ``Z0.`` -> ``Z0.0`` copies (``make bench`` makes them before any timing)."""
    dialect = translated(target)
    if dialect is not None:
        postproc("postproc", "translate", "--from", source, "--to", dialect, path, "-o", f"{path}.{dialect}")
    if target.split("+", 1)[0] == "peer:gcodeparser":
        from peers import fanuc_decimals_copy
        for file in [path] + ([f"{path}.{dialect}"] if dialect else []):
            fanuc_decimals_copy(file, f"{file}.gcodeparser")


def main() -> None:
    source, target, normalize, path = sys.argv[1:5]
    machine = os.path.join(HERE, "machine.xml")
    dialect = translated(target)
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out")
        if os.environ.get("PREPARE") == "1":
            return prepare(source, target, path)
        if target == "toolpath":
            argv = ["postproc", "toolpath", path, "--dialect", source, "--machine", machine, "--format", "jsonl",
                    "-o", out]
        elif target.startswith("verify:"):
            argv = ["postproc", "verify", path, f"{path}.{dialect}", "--from", source, "--to", str(dialect),
                    "--machine", machine]
        elif target.startswith("peer:"):
            tool = target[5:].split("+", 1)[0]
            files = [path] + ([f"{path}.{dialect}"] if dialect else [])
            if tool == "gcodeparser":
                files = [f"{file}.gcodeparser" for file in files]
            return script("peers.py", tool, *files)
        elif target == "plainloop" or target.startswith("plainloop:"):
            return script("plainloop.py", f"{path}.{dialect}" if dialect else path, out)
        elif os.environ.get("CALLGRIND_PROGRAM", "cam") != "cam":
            # the cycles and macro rows of make bench: the plain command (workloads.translate, no options)
            argv = ["postproc", "translate", "--from", source, "--to", target, path, "-o", out]
        else:
            from translations import for_target
            options = for_target(target, normalize == "1").options(Path(machine))
            argv = ["postproc", "translate", "--from", source, "--to", target, *options, path, "-o", out]
        postproc(*argv)


if __name__ == "__main__":
    main()
