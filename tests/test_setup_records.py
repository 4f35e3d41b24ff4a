"""Set-up records are plain dataclasses validated by pydantic only at loading: the defaults a run without a
set-up builds are the ones a loaded file gets, and every bound declared with a field is enforced."""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest

from postproc.setup.machine_setup import GROUPS, MachineCode, SetupGroup
from postproc.setup.machine import CONTAINERS, ToolData
from postproc.setup.record import alias_of, values
from postproc.setup.validate import Invalid, validate

PARTNERS = {name: {"x": "0", "z": "0"} for name in ("x", "z", "x_wear", "z_wear")}
"""A lathe offset's fields need their partners (``ToolData``: x and z are given together)."""
BOUNDED = [(cls, f) for cls in [*GROUPS, *CONTAINERS.values()] for f in dataclasses.fields(cls)
           if {"ge", "gt", "le"} & set(f.metadata)]


@pytest.mark.parametrize("cls", list(GROUPS), ids=lambda c: c.TAG)
def test_a_group_left_empty_validates_to_its_code_defaults(cls: type[SetupGroup]) -> None:
    assert validate(cls, {}) == cls()


def test_there_are_bounded_fields() -> None:
    assert len(BOUNDED) > 30


@pytest.mark.parametrize(("cls", "field"), BOUNDED, ids=lambda x: getattr(x, "name", getattr(x, "__name__", "")))
def test_every_declared_bound_is_enforced_at_its_edge(cls: type[Any], field: dataclasses.Field[Any]) -> None:
    alias = alias_of(cls, field)
    named = getattr(cls, "KEY", "")  # an entry needs its key (the key's own bounds are tested as a field)
    key = {named: "1" if named == "number" else "X"} if named and named != field.name else {}
    key.update({k: v for k, v in PARTNERS.get(field.name, {}).items() if k != alias} if cls is ToolData else {})
    whole = "int" in str(field.type)
    step = 1 if whole else 1e-9
    edges = [("ge", -step, "greater than or equal to"), ("gt", 0, "greater than"), ("le", step, "less than or equal to")]
    for bound, beyond, words in edges:
        if bound not in field.metadata:
            continue
        edge = field.metadata[bound]
        assert getattr(validate(cls, {**key, alias: str(edge + step if bound == "gt" else edge)}), field.name) \
            == pytest.approx(edge, abs=2 * step)
        with pytest.raises(Invalid) as info:
            validate(cls, {**key, alias: str(edge + beyond)})
        assert info.value.problems == [(alias, f"Input should be {words} {edge:g}")] or \
            info.value.problems == [(alias, f"Input should be {words} {edge}")]


def test_a_machine_code_pattern_is_enforced() -> None:
    assert validate(MachineCode, {"letter": "G", "number": "5.1"}).number == "5.1"
    with pytest.raises(Invalid) as info:
        validate(MachineCode, {"letter": "M", "number": "x1"})
    assert info.value.problems == [("number", "String should match pattern '^[0-9]{1,4}(\\.[0-9]{1,2})?$'")]


def test_values_writes_xml_names_and_leaves_defaults_out() -> None:
    from postproc.setup.machine_setup import CycleSettings
    cycles = CycleSettings(peck_retract=0.2, shift_direction="-Y")
    assert values(cycles, by_alias=True, exclude_defaults=True) == {"peckRetract": 0.2, "shiftDirection": "-Y"}
    assert list(values(cycles))[:2] == ["peck_retract", "peck_clearance"]


@pytest.mark.parametrize("cls", list(CONTAINERS.values()), ids=lambda c: c.TAG)
def test_an_entry_class_gives_its_field_types_without_compiling(cls: type[Any], monkeypatch: pytest.MonkeyPatch) -> None:
    """The entries' annotations are evaluated where ``postproc.setup.machine`` loads (not text): the set-up lane's
    ``typing.get_type_hints`` of a class a set-up file fills compiles none of them (``typing.ForwardRef``), and so
    builds no syntax-tree types in a ``--machine`` run; the types are the ones the text would evaluate to."""
    import builtins
    import typing
    compiled: list[object] = []
    real = builtins.compile

    def counting(source: Any, *args: Any, **kwargs: Any) -> Any:
        compiled.append(source)
        return real(source, *args, **kwargs)

    hints = {f.name: f.type for f in dataclasses.fields(cls)}
    assert not any(isinstance(t, str) for t in hints.values())
    monkeypatch.setattr(builtins, "compile", counting)
    resolved = typing.get_type_hints(cls)
    monkeypatch.undo()
    assert compiled == []
    assert {name: resolved[name] for name in hints} == hints
