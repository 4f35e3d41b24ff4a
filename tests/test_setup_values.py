"""The set-up lane (``postproc.fast.setup_values``) held to pydantic: whatever record it builds, pydantic
builds the same (same field values, same types) from the same raw values, on random records of every
built-in class and on every set-up file the repository ships; and it builds the usual ones (it is not a
lane that always steps aside)."""

from __future__ import annotations

import dataclasses
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from postproc.fast.setup_values import plain_record
from postproc.setup.machine import CONTAINERS
from postproc.setup.machine_setup import GROUPS, MachineCode, load_setup
from postproc.setup.record import alias_of
from postproc.setup.validate import Invalid, validate

ROOT = Path(__file__).resolve().parent.parent
CLASSES: list[type[Any]] = [*GROUPS, *CONTAINERS.values(), MachineCode]
SETUPS = sorted(p for p in [*ROOT.glob("examples/setups/*.xml"), *ROOT.glob("tests/**/*.xml"),
                            ROOT / "benchmarks/machine.xml"]
                if b"<MachineSetup" in p.read_bytes()[:4096])

TEXTS = st.sampled_from([
    "0", "1", "-1", "-0", "5", "6", "7", "9999", "10000", "99999999", "100000000", "007", "+1", " 5", "5 ", "1_0",
    "1.", ".5", "0.5", "-0.5", "1e3", "1E-3", "nan", "inf", "-inf", "1.0", "2.50", "100000.0", "100000.00001",
    "-100000.0", "-100000.1", "1" * 25, "0." + "1" * 25, "1" * 400, "true", "false", "True", "yes", "no", "on", "1.5e2",
    "", " ", "X", "Z", "XYZ", "XYZA", "A", "mm", "inch", "keep", "none", "all", "upper", "lf", "table", "error",
    "stop", "m19", "seed", "+X", "fanuc", "haas", "A B", "IS-B", "least-increment", "calculator", "lathe", "mill",
    "XYZ3 F1", "Q9", "DRILL_8", 'a"b', "tab\there", "6.1", "06", "M", "G", "spindle-cw", "none ", "0x10",
    "\u0665", "\uff15", "٣.٥",
])
VALUES = st.one_of(
    TEXTS,
    st.text(max_size=8),
    st.from_regex(r"-?[0-9]{1,6}(\.[0-9]{1,6})?", fullmatch=True),
    st.booleans(),
    st.integers(-10**9, 10**9),
    st.floats(allow_nan=True, allow_infinity=True),
    st.none(),
)


def keys(cls: type[Any]) -> list[str]:
    fields = dataclasses.fields(cls)
    return [*(alias_of(cls, f) for f in fields), *(f.name for f in fields), "unknown"]


def plain_values(field: dataclasses.Field[Any]) -> st.SearchStrategy[Any]:
    """Values of a field's own type, spelt plainly, about its bounds (what a set-up file mostly holds)."""
    hint = str(field.type)
    words = re.findall(r"'([^']*)'", hint)
    near = [float(field.metadata[b]) for b in ("ge", "gt", "le") if b in field.metadata] or [0.0]
    numbers = st.sampled_from(near).flatmap(
        lambda edge: st.integers(-3, 3).map(lambda d: edge + d) | st.floats(edge - 2, edge + 2))
    out: st.SearchStrategy[Any] = st.sampled_from(words) if words else st.nothing()
    if "int" in hint:
        out |= numbers.map(lambda v: str(int(v)))
    if "float" in hint:
        out |= numbers.map(lambda v: f"{v:.{abs(hash(v)) % 7}f}") | numbers
    if "bool" in hint:
        out |= st.sampled_from(["true", "false", True, False])
    if field.name == "number" and hint.startswith("str"):  # a machine code's number
        out |= st.from_regex(r"[0-9]{1,5}(\.[0-9]{1,3})?", fullmatch=True)
    if hint.startswith("str"):
        out |= st.from_regex(r"[ -~]{0,12}", fullmatch=True)
    return out


@st.composite
def raw_records(draw: st.DrawFn) -> tuple[type[Any], dict[str, Any]]:
    cls = draw(st.sampled_from(CLASSES))
    fields = {alias_of(cls, f): f for f in dataclasses.fields(cls)}
    names = draw(st.lists(st.sampled_from(keys(cls)), max_size=6, unique=True))
    needed = ["letter", "number"] if cls is MachineCode else [getattr(cls, "KEY", "")]
    names = [n for n in needed if n and n not in names and draw(st.integers(0, 9))] + names  # mostly given
    raw: dict[str, Any] = {}
    for name in names:
        field = fields.get(name)
        wild = field is None or draw(st.integers(0, 9)) == 0
        raw[name] = draw(VALUES if wild else plain_values(field))  # type: ignore[arg-type]
    return cls, raw


def typed(record: Any) -> list[tuple[str, type, Any]]:
    """A record's fields with their values' types (``5 == 5.0``, but a float field must not hold an int)."""
    return [(f.name, type(getattr(record, f.name)), getattr(record, f.name)) for f in dataclasses.fields(record)]


def same_as_pydantic(cls: type[Any], raw: dict[str, Any]) -> Any:
    """The lane's record for ``raw`` (or None), after checking pydantic builds the very same one."""
    made = plain_record(cls, raw)
    if made is not None:
        try:
            checked = validate(cls, raw)
        except Invalid as exc:
            raise AssertionError(f"the lane built {made!r} from {raw!r}, pydantic refuses it: {exc}") from None
        assert type(made) is type(checked) and typed(made) == typed(checked), (raw, made, checked)
    return made


@settings(max_examples=3000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(raw_records())
def test_the_lane_builds_only_what_pydantic_builds(case: tuple[type[Any], dict[str, Any]]) -> None:
    same_as_pydantic(*case)


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_the_lane_reads_each_plain_field(cls: type[Any]) -> None:
    """Every field of every built-in record, at a plain value of its type, is the lane's (not pydantic's):
    the differential test above compares something."""
    key = getattr(cls, "KEY", "")
    base: dict[str, Any] = {key: "1" if key == "number" else "X"} if key else {}
    if cls is MachineCode:
        base = {"letter": "M", "number": "100"}
    assert same_as_pydantic(cls, base) is not None
    for field in dataclasses.fields(cls):
        text = str(field.type)
        number = field.default if type(field.default) in (int, float) else 1  # a value its rules take
        plain = ("true" if text.startswith("bool") else str(number) if "int" in text or "float" in text
                 else "XYZ" if field.name == "axes" else None)
        if plain is None or field.name in base or field.name in ("x", "z", "x_wear", "z_wear", "letter"):
            continue
        if field.name in ("offset", "offset_wear"):
            continue  # memory A's one value: valid alone, and ``base`` gives nothing else
        assert same_as_pydantic(cls, {**base, alias_of(cls, field): plain}) is not None, field.name


@pytest.mark.parametrize("path", SETUPS, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_shipped_set_up_loads_the_same_through_the_lane(path: Path) -> None:
    try:
        slow = load_setup(path)
    except Exception as exc:  # a set-up the tests keep for its error: the same error through the lane
        with pytest.raises(type(exc)) as fast_exc:
            load_setup(path, lane=plain_record)
        assert str(fast_exc.value) == str(exc)
        return
    fast = load_setup(path, lane=plain_record)
    assert repr(fast._key()) == repr(slow._key())


def test_a_plain_set_up_file_loads_without_pydantic(tmp_path: Path) -> None:
    """The point of the lane: the bench's set-up (and an invalid one, the other side) through the command line."""
    program = tmp_path / "one.nc"
    program.write_text("G0 X1\nM30\n")
    probe = ("import sys, runpy; sys.argv = ['postproc'] + sys.argv[1:]\n"
             "try:\n    runpy.run_module('postproc', run_name='__main__')\nexcept SystemExit:\n    pass\n"
             "print('PYDANTIC' if 'pydantic' in sys.modules else 'NONE', file=sys.stderr)\n")
    bad = tmp_path / "bad.xml"
    bad.write_text('<MachineSetup><Output decimals="+3"/></MachineSetup>')
    seen = []
    for setup in (ROOT / "benchmarks/machine.xml", bad):
        run = subprocess.run([sys.executable, "-c", probe, "translate", str(program), "--from", "fanuc", "--to",
                              "grbl", "--machine", str(setup), "-o", str(tmp_path / "out")],
                             capture_output=True, text=True, timeout=120)
        seen.append(run.stderr.strip().splitlines()[-1])
    assert seen == ["NONE", "PYDANTIC"]
