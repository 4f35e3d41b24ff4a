"""The translation rows of ``make bench`` (``run.py``) and of ``callgrind.sh`` (``callgrind_once.py``): one
place for each row's target dialect, options and issue 30's target, so the two measure the same command.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Translation:
    """One translation of the generated CAM program from Fanuc."""

    target: str
    times_gcode_lib: float
    """Issue 30's target: at least this many times gcode-lib's parse over the same file."""
    normalize: bool = False
    warn: bool = False
    """``--on-unsupported warn``: the target cannot express a construct of the program (said where)."""
    machine: bool = False
    """``--machine benchmarks/machine.xml``: the target needs the set-up's tools or home."""

    @property
    def label(self) -> str:
        extra = " --normalize" if self.normalize else " (copy)" if self.target == "fanuc" else ""
        return f"translate fanuc->{self.target}{extra}{' (warn)' if self.warn else ''}"

    def options(self, machine: Path) -> list[str]:
        return ((["--normalize"] if self.normalize else []) + (["--on-unsupported", "warn"] if self.warn else [])
                + (["--machine", str(machine)] if self.machine else []))


TRANSLATIONS: dict[str, Translation] = {
    "normalize": Translation("fanuc", 1.5, normalize=True),
    "copy": Translation("fanuc", 2.0),
    "linuxcnc": Translation("linuxcnc", 1.5),
    "grbl": Translation("grbl", 1.5, warn=True, machine=True),
    "grblhal": Translation("grblhal", 1.5, machine=True),
    "isg": Translation("isg", 1.5, machine=True),
    "fagor": Translation("fagor", 1.5, machine=True),
}
"""``--rows`` name -> translation. fanuc->fanuc without ``--normalize`` is the lossless copy (the program's
own text where nothing changes); ``--normalize`` rewrites every block. grbl writes the program's ``G43 H..``
(about one block in 10,000) as ``G43.1 Z<length>`` from the bench machine's tools, and warns at what else it
cannot express; ISG writes the closing ``G91 G28 Z0.`` as a move to the machine's Z home (the bench machine
gives it); Fagor writes it as ``G53 G00 Z<home>`` from the same set-up, and needs the tools' lengths for
``G43 H..``; grblHAL (the grblHAL plugin), like grbl, writes ``G43 H..`` as ``G43.1 Z<length>`` from the
machine's tools (without the set-up it refuses the program: no length for register 1). Every lowering target
(linuxcnc, grbl, grblhal, isg, fagor) has issue 30's
target of 1.5x gcode-lib's parse, the copy 2x, ``--normalize`` its former 1.5x (it keeps its lead)."""


def for_target(target: str, normalize: bool) -> Translation:
    """The row ``callgrind.sh SRC TGT NORMALIZE`` measures (a target without a row: the plain command)."""
    for t in TRANSLATIONS.values():
        if t.target == target and t.normalize == normalize:
            return t
    return Translation(target, 0.0, normalize=normalize)
