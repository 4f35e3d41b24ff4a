"""``postproc.records.record`` against ``dataclasses.dataclass``: twin classes, one of each, built and used
on random arguments behave the same (what each call returns or which exception it raises)."""

from __future__ import annotations

import copy
import dataclasses
import math
import pickle
from dataclasses import dataclass, field
from typing import Any, Callable

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from postproc.records import record


def _twins(decorate: Callable[..., Any]) -> dict[str, type]:
    """The same three classes under `decorate` (record or dataclass), with the same qualified names."""

    @decorate
    class Plain:
        a: int
        b: str = "x"
        c: list[int] = field(default_factory=list)
        d: float = 0.0

        def __post_init__(self) -> None:
            if self.a < 0:
                raise ValueError("a < 0")
            self.c.append(self.a)

    @decorate(frozen=True)
    class Frozen:
        a: Any
        b: Any = None

    @decorate(frozen=True, slots=True)
    class Slotted:
        a: Any
        b: Any = 1

    return {"Plain": Plain, "Frozen": Frozen, "Slotted": Slotted}


RECORDS, DATACLASSES = _twins(record), _twins(dataclass)


@record(frozen=True, slots=True)
class PickledRecord:
    a: Any
    b: Any = 1


@dataclass(frozen=True, slots=True)
class PickledDataclass:
    a: Any
    b: Any = 1


values = st.one_of(st.integers(-3, 3), st.text("xy", max_size=2), st.floats(allow_nan=True), st.none())
names = st.sampled_from(["a", "b", "c", "d", "e"])
arguments = st.tuples(st.lists(values, max_size=5), st.dictionaries(names, values, max_size=3))


def outcome(call: Callable[[], Any]) -> tuple[str, Any]:
    """What a call gives, comparable across the twins: ('ok', its fields or value) or the exception's type."""
    try:
        result = call()
    except Exception as err:  # noqa: BLE001 - the exception's type is the outcome compared
        return ("raised", type(err).__name__)
    if dataclasses.is_dataclass(result) and not isinstance(result, type):
        return ("ok", repr(result))
    return ("ok", repr(result))


def build(classes: dict[str, type], name: str, args: tuple[list[Any], dict[str, Any]]) -> Any:
    positional, keywords = args
    if name == "Plain":  # c is a list of ints in the records' use
        keywords = {k: v for k, v in keywords.items() if k != "c"}
    return classes[name](*positional, **keywords)


@pytest.mark.parametrize("name", ["Plain", "Frozen", "Slotted"])
@given(first=arguments, second=arguments)
@example(first=([1], {}), second=([1], {}))
@example(first=([1, "y"], {}), second=([], {"a": 1, "b": "y"}))
@example(first=([], {"b": 2}), second=([1], {"a": 1}))
@example(first=([-1], {}), second=([1, 2, [3], 4.0, 5], {}))
@example(first=([math.nan], {}), second=([math.nan], {}))
@example(first=([1], {"e": 1}), second=([1, 2], {"b": 2}))
def test_record_behaves_as_its_dataclass(name: str, first: Any, second: Any) -> None:
    def both(use: Callable[[dict[str, type]], Any]) -> None:
        assert outcome(lambda: use(RECORDS)) == outcome(lambda: use(DATACLASSES))

    both(lambda c: build(c, name, first))
    both(lambda c: build(c, name, first) == build(c, name, second))
    both(lambda c: build(c, name, first) != build(c, name, second))
    both(lambda c: build(c, name, first) == (first, second))
    both(lambda c: hash(build(c, name, first)) == hash(build(c, name, second)))
    both(lambda c: setattr(build(c, name, first), "a", 2))
    both(lambda c: delattr(build(c, name, first), "b"))
    both(lambda c: dataclasses.replace(build(c, name, first), a=1))
    both(lambda c: dataclasses.asdict(build(c, name, first)))
    both(lambda c: [f.name for f in dataclasses.fields(c[name])])
    both(lambda c: copy.deepcopy(build(c, name, first)) == build(c, name, first))


def test_a_nan_field_is_equal_to_itself_as_in_a_tuple() -> None:
    nan = math.nan
    assert RECORDS["Frozen"](nan) == RECORDS["Frozen"](nan)
    assert DATACLASSES["Frozen"](nan) == DATACLASSES["Frozen"](nan)


def test_a_frozen_slotted_record_pickles_past_its_refusing_setattr() -> None:
    for cls in (PickledRecord, PickledDataclass):
        made = cls((1, 2), b="z")
        again = pickle.loads(pickle.dumps(made))
        assert again == made and again.b == "z" and again is not made


def test_what_a_record_cannot_be_is_refused_where_it_is_defined() -> None:
    with pytest.raises(TypeError, match="kw_only"):
        @record
        class KeywordOnly:
            a: int = field(default=1, kw_only=True)

    with pytest.raises(TypeError, match="__eq__"):
        @record
        class OwnEquality:
            a: int

            def __eq__(self, other: object) -> bool:
                return True
