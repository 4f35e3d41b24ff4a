"""One translation for benchmarks/callgrind.sh: python callgrind_once.py SRC TGT NORMALIZE FILE."""
from __future__ import annotations

import io
import sys

from postproc.api import translate
from postproc.setup import MachineSetup

source, target, normalize, path = sys.argv[1:5]
setup = MachineSetup()
setup.output.normalize = normalize == "1"
with open(path, encoding="utf-8") as f:
    text = f.read()
# grbl warns at the program's G43 H (a table offset it cannot express), as benchmarks/run.py runs it
on_unsupported = "warn" if target == "grbl" else "error"
translate(io.StringIO(text), io.StringIO(), file="big.nc", source=source, target=target, setup=setup,
          on_unsupported=on_unsupported)
