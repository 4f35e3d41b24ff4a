"""Fuzz kind "offset memories": Fanuc mill programs that write and use tool compensation (``G10 L10``-``L13``
writes of geometry and wear, ``G43``/``G44 H``, ``G41``/``G42 D``, ``G49``/``G40``), on a machine whose
tool table is Fanuc memory A (one value per offset), B (with its wear) or C (separate H and D geometry and
wear), to every mill writer.

A case passes when it is refused with located errors, or when the output reads back in the target, meets
the target's rules, and verifies (the compensated paths: a register read as the wrong memory's column
moves the tool).
"""

from __future__ import annotations

from hypothesis import strategies as st

from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup

from ..fuzzing import check_translation
from . import Case

KIND = "offset memories"
TARGETS = ("fanuc", "linuxcnc", "grbl", "grblhal", "mach3", "isg", "fagor")
REGISTERS = (1, 2, 3)


def memory_setup(kind: str) -> MachineSetup:
    """Registers 1-3 of memory ``kind`` ('A', 'B' or 'C'), every other register zero (memory C)."""
    setup = MachineSetup()
    tools = {}
    for n in range(1, 100):
        if n in REGISTERS and kind == "A":
            tools[str(n)] = ToolData(number=n, offset=10.0 * n)
        elif n in REGISTERS and kind == "B":
            tools[str(n)] = ToolData(number=n, offset=10.0 * n, offset_wear=-0.1 * n)
        elif n in REGISTERS:
            tools[str(n)] = ToolData(number=n, length=10.0 * n, radius=0.5 * n, length_wear=-0.1 * n,
                                     radius_wear=0.02 * n)
        else:
            tools[str(n)] = ToolData(number=n, length=0.0, radius=0.0)
    setup.tools = tools
    return setup


@st.composite
def programs(draw: st.DrawFn) -> str:
    lines = ["G21 G17 G90 G94", "G0 X0. Y0. Z50."]
    for _ in range(draw(st.integers(1, 6))):
        kind = draw(st.sampled_from(["write", "write", "length", "radius", "move", "cancel", "inch"]))
        reg = draw(st.sampled_from(REGISTERS))
        if kind == "write":
            code = draw(st.sampled_from(["L10", "L11", "L12", "L13"]))
            value = draw(st.sampled_from(["5.", "-0.2", "0.", "12.5", "0.05"]))
            lines.append(f"G10 {code} P{reg} R{value}" + draw(st.sampled_from(["", " G91", " G90"])))
        elif kind == "length":
            lines.append(f"{draw(st.sampled_from(['G43', 'G43', 'G44']))} H{reg:02d} G0 Z{draw(st.sampled_from(['20.', '5.']))}")
        elif kind == "radius":
            side = draw(st.sampled_from(["G41", "G42"]))
            lines += [f"{side} D{reg:02d} G1 X{draw(st.integers(5, 30))}. Y{draw(st.integers(-10, 10))}. F200.",
                      f"X{draw(st.integers(-30, -5))}.", "G40 G0 X0. Y0."]
        elif kind == "move":
            lines.append(f"G1 X{draw(st.integers(-20, 20))}. Y{draw(st.integers(-20, 20))}. Z{draw(st.integers(-5, 5))}. F150.")
        elif kind == "cancel":
            lines.append(draw(st.sampled_from(["G49", "G40", "G49 G0 Z50."])))
        else:
            lines.append(draw(st.sampled_from(["G20", "G21"])))
    lines += ["G40 G49 G0 Z50.", "M30"]
    return "\n".join(lines) + "\n"


def _case(memory: str, target: str, program: str) -> Case:
    setup = memory_setup(memory)
    return Case(f"memory {memory} fanuc-{target}", target, program,
                lambda p: check_translation("fanuc", target, p, setup, False), f"Fanuc tool memory {memory}")


def cases() -> st.SearchStrategy[Case]:
    return st.builds(_case, st.sampled_from("ABC"), st.sampled_from(TARGETS), programs())
