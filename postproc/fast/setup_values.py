"""The set-up lane: a record of a set-up file built from values spelt the plain way, without pydantic.

Loading a set-up validates each group and entry with pydantic (``postproc.setup.validate``): importing it
and building one validator per record class cost about 0.3 s of CPU and 22 MB of peak memory, more than the
rest of a one-line translation and a fifth of a 100k-block one (``translate --machine``, the bench's grbl,
ISG and Fagor rows; ``python -X importtime``, ``/usr/bin/time``). Nearly every value a set-up file holds is
a plain number, word or ``true``/``false``: this lane reads those itself, with the rules pydantic applies to
them (the record's field types, ``ge``/``gt``/``le`` bounds, ``pattern``, no unknown attribute, finite
floats), and builds the record (its ``__post_init__`` rules run as they do under pydantic). Anything else -
a value of another spelling (``+1``, ``1e3``, `` 5``, ``yes``), a bound or rule broken, a type it does not
know (a plugin's group may use any) - gives None, and pydantic decides, with its messages. So the lane never
accepts what pydantic would refuse, nor builds another value: ``tests/test_setup_values.py`` holds it to
pydantic on random records of every built-in class.

Chosen per record by the lane itself (``plain_record``); the command line passes it to the set-up loader
(``load_setup(..., lane=plain_record)``).
"""

from __future__ import annotations

import dataclasses
import math
import re
import types
import typing
from typing import Any, Callable, Final, Literal, Union

Reader = Callable[[Any], Any]
"""A field's reader: the value a raw value stands for, or ``_NO`` (not a plain spelling: pydantic decides)."""

_NO: Final = object()
_INT: Final = re.compile(r"-?(?:0|[1-9][0-9]{0,17})")
"""A whole number as pydantic reads it from text (no sign '+', leading zero, blank, '_' or point)."""
_FLOAT: Final = re.compile(r"-?[0-9]{1,20}(?:\.[0-9]{1,20})?")
"""A decimal number as pydantic reads it from text (no exponent, sign '+', blank, '_', bare point)."""


class _Field:
    """One field of a record: its name, reader and bounds, and whether it must be given."""

    __slots__ = ("name", "read", "ge", "gt", "le", "pattern", "required")

    def __init__(self, field: dataclasses.Field[Any], read: Reader) -> None:
        meta = field.metadata
        self.name = field.name
        self.read = read
        self.ge: float | None = meta.get("ge")
        self.gt: float | None = meta.get("gt")
        self.le: float | None = meta.get("le")
        pattern = meta.get("pattern")
        self.pattern = re.compile(pattern) if isinstance(pattern, str) else None
        self.required = field.default is dataclasses.MISSING and field.default_factory is dataclasses.MISSING

    def value(self, raw: Any) -> Any:
        """The field's value for ``raw``, or ``_NO``."""
        made = self.read(raw)
        if made is _NO:
            return _NO
        if isinstance(made, (int, float)) and not isinstance(made, bool):
            if (self.ge is not None and not made >= self.ge) or (self.gt is not None and not made > self.gt) \
                    or (self.le is not None and not made <= self.le):
                return _NO
        elif isinstance(made, str) and self.pattern is not None and self.pattern.fullmatch(made) is None:
            return _NO  # (a full match is a match wherever pydantic's engine looks)
        return made


class _Plan:
    """How to build one record class: its fields by every name a raw key may have (alias or name)."""

    __slots__ = ("cls", "by_key", "fields")

    def __init__(self, cls: type[Any], fields: list[tuple[_Field, str]]) -> None:
        self.cls = cls
        self.fields = [f for f, _ in fields]
        self.by_key: dict[str, _Field] = {}
        for f, alias in fields:
            self.by_key[alias] = f
            self.by_key[f.name] = f  # ``populate_by_name``: the field's own name is read too


def _read_int(raw: Any) -> Any:
    if type(raw) is int:
        return raw
    return int(raw) if type(raw) is str and _INT.fullmatch(raw) else _NO


def _read_float(raw: Any) -> Any:
    if type(raw) is float or type(raw) is int:
        made = float(raw)
    elif type(raw) is str and _FLOAT.fullmatch(raw):
        made = float(raw)
    else:
        return _NO
    return made if math.isfinite(made) else _NO  # ``allow_inf_nan=False``


def _read_bool(raw: Any) -> Any:
    if type(raw) is bool:
        return raw
    return {"true": True, "false": False}.get(raw, _NO) if type(raw) is str else _NO


def _read_str(raw: Any) -> Any:
    return raw if type(raw) is str else _NO


def _literal(words: tuple[Any, ...]) -> Reader | None:
    if not all(type(w) is str for w in words):
        return None
    known = frozenset(words)
    return lambda raw: raw if type(raw) is str and raw in known else _NO


def _union(readers: list[Reader]) -> Reader:
    """A union's reader: the one member that reads the value (none, or more than one: pydantic decides which
    member wins, not this lane)."""
    def read(raw: Any) -> Any:
        found = [made for made in (r(raw) for r in readers) if made is not _NO]
        return found[0] if len(found) == 1 else _NO
    return read


_ATOMS: Final[dict[Any, Reader]] = {int: _read_int, float: _read_float, bool: _read_bool, str: _read_str}


def _reader(hint: Any) -> Reader | None:
    """The reader of a field of type ``hint``, or None (a type this lane leaves to pydantic)."""
    atom = _ATOMS.get(hint)
    if atom is not None:
        return atom
    origin = typing.get_origin(hint)
    if origin is Literal:
        return _literal(typing.get_args(hint))
    if origin is Union or origin is types.UnionType:
        readers = []
        for member in typing.get_args(hint):
            if member is type(None):
                continue  # a raw value is never None: the field's default stands for it
            read = _reader(member)
            if read is None:
                return None
            readers.append(read)
        return _union(readers)
    return None


def _plan(cls: type[Any]) -> _Plan | None:
    """How to build ``cls`` from plain values, or None when a field's type is not one the lane reads."""
    if not dataclasses.is_dataclass(cls):
        return None
    config = getattr(cls, "__pydantic_config__", None)
    if not isinstance(config, dict) or config.get("extra") != "forbid" or not config.get("populate_by_name") \
            or config.get("allow_inf_nan") is not False or set(config) - {"extra", "populate_by_name",
                                                                           "allow_inf_nan", "alias_generator"}:
        return None
    generate = config.get("alias_generator")
    try:
        hints = typing.get_type_hints(cls)
    except Exception:  # an annotation that does not resolve here: pydantic says what it makes of it
        return None
    fields: list[tuple[_Field, str]] = []
    for field in dataclasses.fields(cls):
        read = _reader(hints.get(field.name))
        if read is None or not field.init:
            return None
        alias = field.metadata.get("alias")
        if alias is None:
            alias = generate(field.name) if generate is not None else field.name
        fields.append((_Field(field, read), str(alias)))
    return _Plan(cls, fields)


_PLANS: dict[type[Any], _Plan | None] = {}


def plain_record(cls: type[Any], raw: dict[str, Any]) -> Any:
    """``cls`` built from ``raw`` (keys: XML names or field names) when every value is plain and valid (the
    module docstring), else None: pydantic validates it (``postproc.setup.validate.validate``)."""
    plan = _PLANS.get(cls, _NO)
    if plan is _NO:
        plan = _PLANS[cls] = _plan(cls)
    if plan is None:
        return None
    assert isinstance(plan, _Plan)
    kwargs: dict[str, Any] = {}
    for key, value in raw.items():
        field = plan.by_key.get(key)
        if field is None or field.name in kwargs:  # unknown, or given twice (by alias and by name)
            return None
        made = field.value(value)
        if made is _NO:
            return None
        kwargs[field.name] = made
    if any(f.required and f.name not in kwargs for f in plan.fields):
        return None
    try:
        return cls(**kwargs)
    except (ValueError, TypeError):  # a cross-field rule (``__post_init__``): pydantic words the message
        return None
