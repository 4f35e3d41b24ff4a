"""Validation of set-up records at the boundary where a set-up file is read: pydantic over the plain
dataclasses of ``postproc.setup.record`` (imported only here, when a record is first validated, so a run
without a set-up file never pays for it, nor one whose values the set-up lane reads: ``postproc.fast.setup_values``).

Messages are pydantic's (``Input should be less than or equal to 6``), except that an unknown attribute is
an "unknown parameter" and the cross-field rules of a record's ``__post_init__`` stand alone.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, TypeVar

if TYPE_CHECKING:
    from pydantic import TypeAdapter

R = TypeVar("R")

UNKNOWN = frozenset(("extra_forbidden", "unexpected_keyword_argument"))
"""pydantic's error types for an attribute the record does not have."""


class Invalid(Exception):
    """The problems of one record, each as (field's XML name or "", message)."""

    def __init__(self, problems: list[tuple[str, str]]) -> None:
        super().__init__("; ".join(f"{name}: {msg}" if name else msg for name, msg in problems))
        self.problems = problems


_ADAPTERS: dict[type[Any], TypeAdapter[Any]] = {}
"""One pydantic ``TypeAdapter`` per record class (building one compiles its validator)."""


def _adapter(cls: type[Any]) -> TypeAdapter[Any]:
    found = _ADAPTERS.get(cls)
    if found is None:
        from pydantic import TypeAdapter
        found = _ADAPTERS[cls] = TypeAdapter(cls)
    return found


def validate(cls: type[R], raw: dict[str, Any]) -> R:
    """``cls`` built from ``raw`` (keys are XML names or field names; values as read), every value checked
    against the field's type and bounds. Raises ``Invalid`` with every problem found."""
    from pydantic import ValidationError
    try:
        made: R = _adapter(cls).validate_python(raw)
        return made
    except ValidationError as exc:
        raise Invalid([_problem(error) for error in exc.errors()]) from None


def _problem(error: Any) -> tuple[str, str]:
    msg = str(error["msg"])
    if error["type"] in UNKNOWN:
        msg = "unknown parameter"
    elif error["type"] == "value_error":  # our own rules' messages stand alone
        msg = str(error.get("ctx", {}).get("error", msg))
    return ".".join(str(p) for p in error["loc"]), msg
