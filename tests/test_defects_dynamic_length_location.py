"""A LinuxCNC ``G43.1`` towards a target that cannot write a length given in the program is refused at the
``G43.1`` (issue 26, defects).

Towards a controller that applies a length change at its next move (Fanuc's rule), ``length_timing`` moves a
LinuxCNC change to the next block that programs Z absolutely, where both apply it. A dynamic length the target
cannot write was moved there too, and its writer refused it at that Z move's line (line 5 here): the error did not
point at its cause. Now such a change stays at its block (``Dialect.DYNAMIC_TOOL_LENGTH``).
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.plugins import default_registry
from postproc.rs274.writer import WordWriter

PROGRAM = "G21 G90 G17\nG0 X0 Y0 Z40\nG43.1 Z2.5\nG1 X10 F100\nG1 Z-1\nG49\nG0 X5\nM2\n"
"""The change on line 3 applies at the absolute Z of line 5."""


def _translate(target: str, mode: str = "error") -> tuple[str, str]:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="in.ngc", source="linuxcnc", target=target, on_unsupported=mode,
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


@pytest.mark.parametrize("target", ["fanuc", "mach3"])
def test_the_refusal_names_the_g43_1_line(target: str) -> None:
    if target not in default_registry().dialects:
        pytest.skip(f"the {target} plugin is not installed")
    with pytest.raises(ErrorList) as caught:
        _translate(target)
    assert [str(e) for e in caught.value.errors] == [
        f"in.ngc:3:1: error: the {target} dialect cannot express a dynamic tool length offset (a length given in "
        "the program, not a register of the tool table)"]


def test_warn_mode_names_the_g43_1_line_too() -> None:
    out, warnings = _translate("fanuc", "warn")
    assert warnings.startswith("in.ngc:3:1: warning: "), warnings
    assert "in.ngc:5:" not in warnings, warnings
    assert [line for line in out.splitlines() if "G43" in line] == ["(UNSUPPORTED LINE 3: G43.1 Z2.5)"], out


def test_the_capability_is_what_each_writer_spells() -> None:
    """``DYNAMIC_TOOL_LENGTH`` says what each word writer's code table writes (the lowering decides by the
    first, the writer by the second: they must agree)."""
    checked = 0
    for name, dialect in default_registry().dialects.items():
        writer = dialect.WRITER
        if writer is None or not issubclass(writer, WordWriter) or not hasattr(writer, "CODES"):
            continue
        checked += 1
        assert dialect.DYNAMIC_TOOL_LENGTH == (writer.CODES.spell("length", "dynamic") is not None), name
    assert checked >= 5
