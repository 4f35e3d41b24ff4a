"""``@record``: a dataclass whose methods are closures rather than generated source.

Python 3.11's ``dataclasses`` writes ``__init__``, ``__repr__`` and ``__eq__`` (a frozen class also
``__setattr__``, ``__delattr__`` and ``__hash__``) as source text and compiles each with ``exec``: 0.4 ms
for a frozen class, 1.5 ms for the set-up's seven groups, about 4 ms of a one-line translation's start
for the records its modules define. ``record`` lets ``dataclasses`` do the rest (the fields and their
defaults, ``__match_args__``, ``__slots__``; ``fields``, ``replace`` and ``asdict`` work as on any
dataclass, and pydantic validates it as one) and adds the same methods made once, here, for every class.

They behave as the generated ones for what the records use (``tests/test_records.py`` compares the two on
random values): positional or keyword arguments, defaults and ``default_factory``, ``__post_init__``,
equality with an instance of the same class only, ``repr``, and for a frozen record the hash of its
fields and ``FrozenInstanceError`` on assignment. A class that needs more (``InitVar``, keyword-only or
``init=False`` fields, ordering) is refused when it is defined. The price is a slower ``__init__`` (a loop
in Python): a record is made per set-up, per dialect or per diagnostic, never per block.
"""

from __future__ import annotations

import dataclasses
from typing import Any, Callable, TypeVar, dataclass_transform, overload

T = TypeVar("T", bound=type)

_MISSING: Any = dataclasses.MISSING


@overload
def record(cls: T, /) -> T: ...
@overload
def record(*, frozen: bool = False, slots: bool = False) -> Callable[[T], T]: ...


@dataclass_transform(field_specifiers=(dataclasses.field,))
def record(cls: T | None = None, /, *, frozen: bool = False, slots: bool = False) -> T | Callable[[T], T]:
    """``@dataclass``, ``@dataclass(frozen=True)`` or ``@dataclass(frozen=True, slots=True)`` as
    ``@record``, ``@record(frozen=True)``, ``@record(frozen=True, slots=True)``."""

    def wrap(cls: T) -> T:
        return make_record(cls, frozen, slots)

    return wrap if cls is None else wrap(cls)


def make_record(cls: T, frozen: bool, slots: bool) -> T:
    """The class as a dataclass with closure-made methods (see the module)."""
    own = cls.__dict__
    for name in ("__init__", "__repr__", "__eq__") + (("__setattr__", "__delattr__", "__hash__") if frozen else ()):
        if name in own:
            raise TypeError(f"@record {cls.__qualname__} defines {name}: use @dataclass")
    # A class without a docstring gets one from dataclasses: its name and ``inspect.signature(cls)``, which,
    # the class having no ``__init__`` yet, parses ``object.__init__``'s text signature with ``tokenize``,
    # compiling tokenize's regular expressions: ~12 ms of every start (pure build, measured with -X importtime
    # and cProfile; the set-up's groups, the first records made). The same text is written here instead, with
    # the fields' names (after the class is made: dataclasses only reads the docstring's presence).
    undocumented = not cls.__doc__
    if undocumented:
        cls.__doc__ = cls.__name__
    made: Any = dataclasses.dataclass(cls, init=False, repr=False, eq=False, slots=slots)
    fields = dataclasses.fields(made)
    if undocumented:
        made.__doc__ = f"{made.__name__}({', '.join(f.name for f in fields)})"
    for f in fields:
        if not f.init or f.kw_only:
            raise TypeError(f"@record {cls.__qualname__}.{f.name}: init=False and kw_only fields need @dataclass")
    if any(_is_init_var(f.type) for f in made.__dataclass_fields__.values()):
        raise TypeError(f"@record {cls.__qualname__}: InitVar needs @dataclass")
    names = tuple(f.name for f in fields)
    made.__init__ = _init(made, fields)
    made.__repr__ = _repr(names)
    made.__eq__ = _eq(names)
    if frozen:
        made.__setattr__ = _refuse_set
        made.__delattr__ = _refuse_delete
        made.__hash__ = _hash(names)
        if slots:  # pickle and copy restore the fields past the refusing __setattr__, as dataclasses does
            made.__getstate__ = _getstate(names)
            made.__setstate__ = _setstate(names)
    else:
        made.__hash__ = None  # as a dataclass with eq and not frozen: unhashable
    return made  # type: ignore[no-any-return]


def _init(cls: type, fields: tuple[dataclasses.Field[Any], ...]) -> Callable[..., None]:
    names = tuple(f.name for f in fields)
    count = len(names)
    defaults = {f.name: f.default for f in fields if f.default is not _MISSING}
    factories: dict[str, Callable[[], Any]] = {
        f.name: f.default_factory for f in fields if f.default_factory is not _MISSING}  # type: ignore[misc]
    post_init = hasattr(cls, "__post_init__")
    setter = object.__setattr__
    title = f"{cls.__qualname__}.__init__()"

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        given = len(args)
        if given > count:
            raise TypeError(f"{title} takes {count + 1} positional arguments but {given + 1} were given")
        for name, value in zip(names, args):
            setter(self, name, value)
        if kwargs:
            for name in names[:given]:
                if name in kwargs:
                    raise TypeError(f"{title} got multiple values for argument '{name}'")
        for name in names[given:]:
            if name in kwargs:
                value = kwargs.pop(name)
            elif name in defaults:
                value = defaults[name]
            elif name in factories:
                value = factories[name]()
            else:
                raise TypeError(f"{title} missing 1 required positional argument: '{name}'")
            setter(self, name, value)
        if kwargs:
            raise TypeError(f"{title} got an unexpected keyword argument '{next(iter(kwargs))}'")
        if post_init:
            self.__post_init__()

    return __init__


def _repr(names: tuple[str, ...]) -> Callable[[Any], str]:
    def __repr__(self: Any) -> str:
        inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in names)
        return f"{type(self).__qualname__}({inner})"

    return __repr__


def _eq(names: tuple[str, ...]) -> Callable[[Any, object], Any]:
    def __eq__(self: Any, other: object) -> Any:
        if other.__class__ is not self.__class__:
            return NotImplemented
        # as tuples, like the generated method: a field that is the same object is equal (a NaN too)
        return tuple(getattr(self, name) for name in names) == tuple(getattr(other, name) for name in names)

    return __eq__


def _hash(names: tuple[str, ...]) -> Callable[[Any], int]:
    def __hash__(self: Any) -> int:
        return hash(tuple(getattr(self, name) for name in names))

    return __hash__


def _getstate(names: tuple[str, ...]) -> Callable[[Any], list[Any]]:
    def __getstate__(self: Any) -> list[Any]:
        return [getattr(self, name) for name in names]

    return __getstate__


def _setstate(names: tuple[str, ...]) -> Callable[[Any, list[Any]], None]:
    def __setstate__(self: Any, state: list[Any]) -> None:
        for name, value in zip(names, state):
            object.__setattr__(self, name, value)

    return __setstate__


def _is_init_var(annotation: object) -> bool:
    """An ``InitVar`` field, given as a type or (``from __future__ import annotations``) as its text."""
    return isinstance(annotation, dataclasses.InitVar) or (isinstance(annotation, str) and "InitVar" in annotation)


def _refuse_set(self: Any, name: str, value: Any) -> None:
    raise dataclasses.FrozenInstanceError(f"cannot assign to field '{name}'")


def _refuse_delete(self: Any, name: str) -> None:
    raise dataclasses.FrozenInstanceError(f"cannot delete field '{name}'")
