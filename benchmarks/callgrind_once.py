"""One run for benchmarks/callgrind.sh, as ``make bench`` runs it: the ``postproc`` command's process
(``postproc.commands.launch``: the command line, reading the file and writing one), in this interpreter so that
valgrind follows it. python callgrind_once.py SRC TGT NORMALIZE FILE.

TGT ``toolpath``: ``postproc toolpath FILE --dialect SRC --format jsonl`` on the benchmark machine;
``verify:DIALECT``: ``postproc verify FILE FILE.DIALECT --from SRC --to DIALECT`` on it, against the
translation ``callgrind.sh`` prepared (with ``PREPARE=1``: write that translation); anything else
``postproc translate --from SRC --to TGT`` with the options of its ``make bench`` row
(``benchmarks/translations.py``)."""
from __future__ import annotations

import os
import sys
import tempfile

from pathlib import Path

from postproc.commands.launch import run

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from translations import for_target  # noqa: E402

source, target, normalize, path = sys.argv[1:5]
machine = os.path.join(os.path.dirname(os.path.abspath(__file__)), "machine.xml")
with tempfile.TemporaryDirectory() as work:
    out = os.path.join(work, "out")
    if target == "toolpath":
        sys.argv = ["postproc", "toolpath", path, "--dialect", source, "--machine", machine, "--format", "jsonl",
                    "-o", out]
    elif target.startswith("verify:"):
        dialect = target.split(":", 1)[1]
        translated = f"{path}.{dialect}"
        if os.environ.get("PREPARE") == "1":
            sys.argv = ["postproc", "translate", "--from", source, "--to", dialect, path, "-o", translated]
        else:
            sys.argv = ["postproc", "verify", path, translated, "--from", source, "--to", dialect,
                        "--machine", machine]
    else:
        options = for_target(target, normalize == "1").options(Path(machine))
        sys.argv = ["postproc", "translate", "--from", source, "--to", target, *options, path, "-o", out]
    run()
