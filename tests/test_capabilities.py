"""The capability table tells the truth: what a dialect says it lacks, its writer refuses."""

from __future__ import annotations

import io

import pytest

from postproc.errors import ErrorList
from postproc.plugins import default_registry
from postproc.api import translate

REGISTRY = default_registry()
WRITERS = sorted(name for name, cls in REGISTRY.dialects.items() if cls.WRITER is not None)

PROBES = {
    # capability: a Fanuc block that needs it (after a prologue that positions the tool)
    "CUTTER_COMPENSATION": "G41 D01 G01 X10. F100.",
    "TOOL_LENGTH_OFFSET": "G43 H01 Z10.",
    "SPINDLE_ORIENTATION": "M19",
}
PROLOGUE = "G21 G17 G90\nG00 X0. Y0. Z50.\n"


def _write(target: str, line: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(PROLOGUE + line + "\nM30\n"), out, file="probe.nc", source="fanuc", target=target)
    return out.getvalue()


@pytest.mark.parametrize("target", WRITERS)
@pytest.mark.parametrize("capability", sorted(PROBES))
def test_writer_agrees_with_capability(target: str, capability: str) -> None:
    has_it = REGISTRY.dialect(target).capabilities()[capability]
    if has_it:
        assert _write(target, PROBES[capability])
    else:
        with pytest.raises(ErrorList) as errs:
            _write(target, PROBES[capability])
        assert errs.value.errors[0].location.line == 3


@pytest.mark.parametrize("target", WRITERS)
def test_native_cycles_are_written_natively_or_expanded(target: str) -> None:
    """A cycle the target lists stays a cycle when its semantics match; any other is expanded."""
    dialect = REGISTRY.dialect(target)
    text = _write(target, "G98 G81 X10. Y10. Z-5. R2. F100.")
    native = "drill" in dialect.NATIVE_CYCLES and dialect.capabilities().get("CYCLE_SEMANTICS", "fanuc") == "fanuc"
    code = [line for line in text.splitlines() if not line.startswith("(")]
    assert any("G81" in line for line in code) == native
    assert ("drill from line 3" in text) == (not native)
