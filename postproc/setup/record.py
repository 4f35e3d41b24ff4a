"""The records a set-up is made of, as plain dataclasses: a run that loads no set-up file builds them from
their defaults without importing a validation library (pydantic costs more start-up than the rest of a
one-line translation).

Each field is declared once: its type, its default and, in ``setting(...)``, its bounds and XML alias.
``postproc.setup.validate`` hands the same classes to pydantic when a set-up file is loaded (pydantic
reads a dataclass field's ``metadata`` as the arguments of its ``Field``), so the bounds checked on
loading are the ones declared here, and ``config dump`` writes the fields back through ``values``.
Constructing a record in code checks nothing but the cross-field rules of its ``__post_init__``.
"""

from __future__ import annotations

import dataclasses
from typing import Any, Callable, ClassVar, dataclass_transform

from ..records import make_record


MAX_COORDINATE = 100_000.0
"""Largest magnitude of a travel limit, home, offset, tool length or start position (100 m or 100,000
degrees): no machine comes near it, and an absurd value (``1e308``) is refused at its line rather than
overflowing a sum."""

ROTARY_AXES = frozenset("ABC")
"""The axes whose positions are angles (degrees, never scaled by the machine's units): here, beside the records,
for the work offsets of every start (``work_offsets``) without the machine's geometry (``machine``)."""


def camel(name: str) -> str:
    """``peck_retract`` -> ``peckRetract``: the XML spelling of a set-up group's field."""
    head, *rest = name.split("_")
    return head + "".join(p.title() for p in rest)


def setting(default: Any = dataclasses.MISSING, *, ge: float | None = None, gt: float | None = None,
            le: float | None = None, alias: str | None = None, pattern: str | None = None) -> Any:
    """A field with its bounds (``ge``/``gt``/``le``), its XML name where it is not the generated one
    (``alias``) and the regular expression a string must match (``pattern``), checked when a set-up
    file is loaded."""
    given = {"ge": ge, "gt": gt, "le": le, "alias": alias, "pattern": pattern}
    metadata = {key: value for key, value in given.items() if value is not None}
    return dataclasses.field(default=default, metadata=metadata)


def pydantic_config(alias_generator: Callable[[str], str] | None) -> dict[str, Any]:
    """The validation rules of every record (pydantic's ``ConfigDict``, spelt as the plain dict it is):
    unknown attributes are errors, a field may be written by its name or its alias, and every float is
    finite (``nan``/``inf`` are errors)."""
    config: dict[str, Any] = {"populate_by_name": True, "extra": "forbid", "allow_inf_nan": False}
    if alias_generator is not None:
        config["alias_generator"] = alias_generator
    return config


def alias_of(cls: type, field: dataclasses.Field[Any]) -> str:
    """A field's XML name: its own alias, else the class's generated one, else its name."""
    alias = field.metadata.get("alias")
    if alias is not None:
        return str(alias)
    generate = getattr(cls, "__pydantic_config__", {}).get("alias_generator")
    return str(generate(field.name)) if generate is not None else field.name


def aliases(cls: type[Any]) -> dict[str, str]:
    """Field name -> XML name, in declaration order."""
    return {field.name: alias_of(cls, field) for field in dataclasses.fields(cls)}


def values(record: Any, *, by_alias: bool = False, exclude_defaults: bool = False, exclude_none: bool = False,
           include: set[str] | None = None, exclude: set[str] | None = None) -> dict[str, Any]:
    """The record's fields in declaration order (``include``/``exclude`` name fields, not aliases)."""
    out: dict[str, Any] = {}
    for field in dataclasses.fields(record):
        if (include is not None and field.name not in include) or (exclude and field.name in exclude):
            continue
        value = getattr(record, field.name)
        if (exclude_none and value is None) or (exclude_defaults and value == field.default):
            continue
        out[alias_of(type(record), field) if by_alias else field.name] = value
    return out


@dataclass_transform()
class SetupGroup:
    """A group of parameters stored as the attributes of one element (``<Cycles peckRetract="0.5"/>``,
    camelCase aliases of the fields). Every subclass is a dataclass without being decorated: plugins add
    their own groups (a subclass with its ``TAG``, fields with defaults, bounds through ``setting``) by the
    ``postproc_register_setup_groups`` hook. Every field has a default (a group may be left out)."""

    TAG: ClassVar[str] = ""
    __pydantic_config__: ClassVar[dict[str, Any]] = pydantic_config(camel)

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        make_record(cls, frozen=False, slots=False)  # a dataclass, its methods made without exec
