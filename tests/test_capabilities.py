"""The capability table tells the truth: what a dialect says it lacks, its writer refuses."""

from __future__ import annotations

import ast
import functools
import inspect
import io
import re
import textwrap
from pathlib import Path

import pytest

from postproc.errors import ErrorList
from postproc.plugins import default_registry
from postproc.api import translate
from postproc.dialect import Dialect
from postproc.setup.machine_setup import MachineSetup
from tests.support.tools import with_tools

REGISTRY = default_registry()
WRITERS = sorted(name for name, cls in REGISTRY.dialects.items()
                 if cls.WRITER is not None and "mill" in cls.MACHINE_TYPES)
"""Writers of milling programs: the probes below are milling blocks (a lathe-only control such as GSK
980TDc refuses a milling program from its first block; ``tests/test_lathe_*`` probe the lathes)."""

PROBES = {
    # capability: a Fanuc block that needs it (after a prologue that positions the tool)
    "CUTTER_COMPENSATION": "G41 D01 G01 X10. F100.",
    "TOOL_LENGTH_OFFSET": "G43 H01 Z10.",
    "SPINDLE_ORIENTATION": "M19",
}
PROLOGUE = "G21 G17 G90\nG00 X0. Y0. Z50.\n"


def _write(target: str, line: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO()
    translate(io.StringIO(PROLOGUE + line + "\nM30\n"), out, file="probe.nc", source="fanuc", target=target,
              setup=setup)
    return out.getvalue()


@pytest.mark.parametrize("target", WRITERS)
@pytest.mark.parametrize("capability", sorted(PROBES))
def test_writer_agrees_with_capability(target: str, capability: str) -> None:
    """A dialect with the capability writes the block (the registers' values given: ISG and Fagor choose
    their D from them); one without refuses it, at its line."""
    has_it = REGISTRY.dialect(target).capabilities()[capability]
    if has_it:
        assert _write(target, PROBES[capability], with_tools())
    else:
        with pytest.raises(ErrorList) as errs:
            _write(target, PROBES[capability])
        assert errs.value.errors[0].location.line == 3


def test_a_target_without_a_tool_table_gets_the_length_written() -> None:
    """grbl lacks the table (TOOL_LENGTH_OFFSET False): given the value, the offset is written as it."""
    assert not REGISTRY.dialect("grbl").TOOL_LENGTH_OFFSET
    text = _write("grbl", PROBES["TOOL_LENGTH_OFFSET"], with_tools(lengths={1: 12.5}))
    assert "G43.1 Z12.5" in text.splitlines() and "H" not in text


@pytest.mark.parametrize("target", WRITERS)
def test_native_cycles_are_written_natively_or_expanded(target: str) -> None:
    """A cycle the target lists stays a cycle when its semantics match; any other is expanded."""
    dialect = REGISTRY.dialect(target)
    text = _write(target, "G98 G81 X10. Y10. Z-5. R2. F100.")
    # grblHAL's G81 moves as Fanuc's from a block that starts at the initial level (postproc_grblhal.cycles,
    # from its motion_control.c): the one target that keeps another family's cycle native.
    native = "drill" in dialect.NATIVE_CYCLES and (dialect.capabilities().get("CYCLE_SEMANTICS") == "fanuc"
                                                   or target == "grblhal")
    code = [line for line in text.splitlines() if not line.startswith(("(", ";"))]  # (";": SINUMERIK's comments)
    assert any("G81" in line or "CYCLE81" in line for line in code) == native  # (SINUMERIK: MCALL CYCLE81)
    assert ("drill from line 3" in text) == (not native)


ROOT = Path(__file__).resolve().parents[1]
CODE_FILES = [*ROOT.glob("postproc/**/*.py"), *ROOT.glob("dialects/**/*.py"), *ROOT.glob("plugins/*/postproc_*/**/*.py")]


@functools.cache
def _attribute_docs(cls: type) -> dict[str, str]:
    """UPPER_CASE class attributes of ``cls``'s own source that have a docstring right beneath them (kept a
    class: ``inspect.getsource`` tokenizes its whole module, and the scan below asks for a class once a
    dialect and capability; ~7 s of CPU uncached)."""
    tree = ast.parse(textwrap.dedent(inspect.getsource(cls)))
    body = tree.body[0].body  # type: ignore[attr-defined]
    docs: dict[str, str] = {}
    for stmt, nxt in zip(body, body[1:]):
        target = stmt.targets[0] if isinstance(stmt, ast.Assign) else getattr(stmt, "target", None)
        if isinstance(target, ast.Name) and isinstance(nxt, ast.Expr) and isinstance(nxt.value, ast.Constant):
            docs[target.id] = str(nxt.value.value)
    return docs


def test_every_capability_is_declared_documented_and_read_by_code() -> None:
    """A flag no code reads promises what nothing keeps; one without a docstring says nothing."""
    code = "\n".join(p.read_text(encoding="utf-8") for p in CODE_FILES)
    seen: set[str] = set()
    for dialect in REGISTRY.dialects.values():
        for name in dialect.capabilities():
            owners = [k for k in dialect.__mro__ if name in vars(k)]
            assert Dialect in dialect.__mro__ and owners, name
            assert name in vars(Dialect) or name in _attribute_docs(owners[-1]), (
                f"{dialect.NAME}: capability {name} is not declared with a docstring")
            for owner in owners:
                if owner.__module__.split(".")[0] in ("postproc", "dialects") or owner.__module__.startswith("postproc_"):
                    assert _attribute_docs(owner).get(name), f"{owner.__name__}.{name} has no docstring"
            seen.add(name)
    for name in seen:
        assert re.search(rf"\.{name}\b|capable\(\"{name}\"\)", code), f"no code reads the capability {name}"
    assert {"NATIVE_CYCLES", "CUTTER_COMPENSATION", "TOOL_CHANGER", "DWELL_UNIT", "CYCLE_SEMANTICS"} <= seen


def test_the_dialects_command_lists_every_capability(capsys: pytest.CaptureFixture[str]) -> None:
    from postproc.commands.cli import main
    assert main(["dialects"]) == 0
    listed = capsys.readouterr().out
    for dialect in REGISTRY.dialects.values():
        for name in dialect.capabilities():
            assert re.search(rf"^{name} ", listed, re.M), name


@pytest.mark.parametrize("name", sorted(REGISTRY.dialects))
def test_each_dialect_names_its_own_cycle_rules(name: str) -> None:
    """The core has no family's default: a dialect with native cycles names the rules they follow (one
    of ``postproc.cycles.semantics``), one without names none (``postproc dialects`` shows '-')."""
    from postproc.cycles.semantics import semantics_named

    dialect = REGISTRY.dialect(name)
    if dialect.NATIVE_CYCLES:
        assert semantics_named(dialect.CYCLE_SEMANTICS) is not None
    else:
        assert dialect.CYCLE_SEMANTICS == ""
