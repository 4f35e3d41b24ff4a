"""Do a block's sections hold what their annotations say? The compiled build (docs/compiled.md) checks a
compiled class's attribute types at run time: a section given an ``Expr`` where it declares ``int``
(``ToolLengthOffset.register`` from ``H#1``) is a ``TypeError`` there and passes silently in pure
Python. ``mistyped(block)`` makes the pure build see what the compiled one would refuse.

A field's type is its class annotation, or the ``__init__`` parameter of the same name (how mypyc
infers the type of a field assigned in ``__init__``). ``float`` accepts an ``int``, as mypyc does.
"""

from __future__ import annotations

import sys
import types
import typing
from functools import cache
from typing import Any, Iterable, Literal, Mapping, Union, get_args, get_origin

from postproc.ir import Block, Section


@cache
def field_types(cls: type) -> dict[str, Any]:
    """Field name -> its declared type, for every slot of ``cls`` and its bases that declares one."""
    found: dict[str, Any] = {}
    for klass in reversed(cls.__mro__):
        namespace = vars(sys.modules[klass.__module__]) if klass.__module__ in sys.modules else {}
        sources = [getattr(klass, "__annotations__", {}) if "__annotations__" in vars(klass) else {}]
        init = vars(klass).get("__init__")
        if init is not None and hasattr(init, "__annotations__"):
            sources.append({k: v for k, v in init.__annotations__.items() if k != "return"})
        slots = set(_slots(klass))
        for annotations in sources:
            for name, hint in annotations.items():
                if name not in slots and annotations is not sources[0]:
                    continue  # an __init__ parameter that is not a field of the same name
                if isinstance(hint, str):
                    try:
                        hint = eval(hint, dict(namespace), {})  # noqa: S307 (our own annotations)
                    except Exception:
                        continue  # a name only the type checker sees: not judged
                if get_origin(hint) is typing.ClassVar:
                    continue
                found[name] = hint
    return found


def _slots(cls: type) -> Iterable[str]:
    slots = vars(cls).get("__slots__", ())
    return (slots,) if isinstance(slots, str) else slots


def conforms(value: object, hint: Any) -> bool:
    """``value`` is of type ``hint`` as far as a run-time check can tell (unknown forms pass)."""
    if hint is Any or hint is object:
        return True
    if hint is None or hint is type(None):
        return value is None
    origin = get_origin(hint)
    if origin is Union or origin is types.UnionType:
        return any(conforms(value, arg) for arg in get_args(hint))
    if origin is Literal:
        return value in get_args(hint)
    if hint is float:
        return isinstance(value, (float, int))
    if origin in (dict, Mapping, typing.Mapping):
        key, item = get_args(hint) or (Any, Any)
        return isinstance(value, Mapping) and all(conforms(k, key) and conforms(v, item) for k, v in value.items())
    if origin in (list, frozenset, set):
        (item,) = get_args(hint) or (Any,)
        return isinstance(value, origin) and all(conforms(v, item) for v in value)  # type: ignore[arg-type]
    if origin is tuple:
        args = get_args(hint)
        if not isinstance(value, tuple):
            return False
        if len(args) == 2 and args[1] is Ellipsis:
            return all(conforms(v, args[0]) for v in value)
        return len(args) == len(value) and all(conforms(v, a) for v, a in zip(value, args))
    if isinstance(hint, type):
        return isinstance(value, hint)
    return True


def mistyped_section(section: Section) -> list[str]:
    """Each field of ``section`` whose value is not of its declared type, as 'Class.field = value'."""
    bad = []
    for name, hint in field_types(type(section)).items():
        if hasattr(section, name) and not conforms(getattr(section, name), hint):
            bad.append(f"{type(section).__name__}.{name} = {getattr(section, name)!r} (declared {hint})")
    return bad


def mistyped(block: Block) -> list[str]:
    """Every field of the block's sections (and of the sections a compound motion holds) that the compiled
    build would refuse."""
    bad = []
    for section in block.sections.values():
        bad += mistyped_section(section)
        for item in getattr(section, "items", None) or ():
            if isinstance(item, Section):
                bad += mistyped_section(item)
    return bad
