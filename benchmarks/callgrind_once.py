"""One translation for benchmarks/callgrind.sh, as ``make bench`` runs it: the ``postproc`` command's
process (``postproc.launch``: the command line, reading the file and writing one), in this interpreter
so that valgrind follows it. python callgrind_once.py SRC TGT NORMALIZE FILE."""
from __future__ import annotations

import os
import sys
import tempfile

from postproc.launch import run

source, target, normalize, path = sys.argv[1:5]
options = ["--normalize"] if normalize == "1" else []
# grbl writes the program's G43 H from the bench machine's tools (and warns at what it cannot express),
# as benchmarks/run.py runs it
if target == "grbl":
    options += ["--on-unsupported", "warn", "--machine", os.path.join(os.path.dirname(__file__), "machine.xml")]
with tempfile.TemporaryDirectory() as work:
    out = os.path.join(work, "out.nc")
    sys.argv = ["postproc", "translate", "--from", source, "--to", target, *options, path, "-o", out]
    run()
