"""Subprogram identity across dialects: the target's name of each subprogram of one translation.

A subprogram is named by its definition (Fanuc ``O2000`` after the main program, LinuxCNC ``o100 sub``,
ISG ``%L SUB``) and by every call (``M98 P``, ``G65 P``, ``o100 call``, ``LL SUB``). The neutral name
(``postproc.interp.control``: ``"2000"``, ``"<probe>"``) is the source's; the target may not be able to write
it (Fanuc numbers its programs, ISG names them). A writer keeps one ``SubprogramNames`` and asks it for
the definition and for every call, so both always say the same name: the first time a name is met
decides its target name, whichever of the definition or a call comes first.

The rule is the target's data (``NameRule``): which numbers it writes as they are, where the others
get a number, whether it writes names. A name the target cannot write and cannot number is refused
(``UnsupportedError``, located by the writer), as is a call whose program number is computed once a
number has been changed (the value would call the source's number).
"""

from __future__ import annotations

from ..errors import UnsupportedError
from ..records import record


@record(frozen=True)
class NameRule:
    numbers: range
    """Program numbers the target writes as they are (Fanuc ``O1``-``O9999``)."""
    spare: range
    """Numbers given, in order, to the subprograms the target cannot name as the source does (empty:
    those are refused)."""
    names: bool
    """The target writes named subprograms (``"<probe>"``)."""
    lower_case: bool = False
    """The target reads names in any case as one (LinuxCNC): a name is written in lower case, and two
    names that differ only in case are refused."""
    one_kind: bool = False
    """How a subprogram is defined says how it is called (LinuxCNC: ``o<n> sub`` only by ``o<n> call``, a
    new level of locals; ``O<n>`` .. ``M99`` only by ``M98``, which shares the caller's): every call of
    one subprogram, and its definition, are of one kind (``postproc.interp.control.CALL_KINDS``)."""


class SubprogramNames:
    """The target name of every subprogram of one translation (one per writer)."""

    __slots__ = ("rule", "given", "kinds", "_folded", "_numbers", "_changed", "_computed")

    def __init__(self, rule: NameRule) -> None:
        self.rule = rule
        self.given: dict[str, str] = {}
        """Source name -> target name (decimal text of a program number, or ``<name>``)."""
        self.kinds: dict[str, tuple[str, str]] = {}
        """Source name -> the kind of its calls and definition (``one_kind`` rules), and what fixed it."""
        self._folded: dict[str, str] = {}
        """Lower-cased name -> the name as the source wrote it (``lower_case`` rules)."""
        self._numbers: set[int] = set()
        """Program numbers given so far (kept or spare)."""
        self._changed: str | None = None
        """A numbered subprogram whose number changed (a computed call could mean it)."""
        self._computed = False
        """A call with a computed program number was written."""

    def of(self, name: str) -> str:
        """The target name of source subprogram ``name`` (decided the first time it is asked)."""
        given = self.given.get(name)
        if given is not None:
            return given
        rule = self.rule
        if name.isdigit() and int(name) in rule.numbers:
            number = int(name)
            if number in self._numbers:
                other = next(k for k, v in self.given.items() if v == str(number))
                raise UnsupportedError(f"subprogram {name} (its number is already given to subprogram {other})")
            given = str(number)
        elif not name.isdigit() and rule.names:
            given = self._name(name)
        else:
            given = self._spare(name)
        if given.isdigit():
            self._numbers.add(int(given))
        self.given[name] = given
        return given

    def use(self, name: str, kind: str, what: str) -> str:
        """The target name of ``name`` for a call or a definition of ``kind`` (``what`` names it in a
        message): under ``one_kind`` rules, a kind other than the one fixed before is refused."""
        given = self.of(name)
        if self.rule.one_kind:
            fixed = self.kinds.setdefault(name, (kind, what))
            if fixed[0] != kind:
                raise UnsupportedError(f"{what} of subprogram {name} after {fixed[1]} (one is a subprogram call "
                                       f"sharing the caller's locals, the other a macro call with its own)")
        return given

    def kind(self, name: str) -> str | None:
        """The kind of the calls of ``name`` met so far (None: none yet)."""
        fixed = self.kinds.get(name)
        return None if fixed is None else fixed[0]

    def computed(self) -> None:
        """A call whose program number is known only when it runs: it reaches the source's numbers only
        while every number is written as it is."""
        if self._changed is not None:
            raise UnsupportedError(f"a call of a computed program number after subprogram {self._changed} was "
                                   f"numbered {self.given[self._changed]} (the call would reach the source's "
                                   f"number)")
        self._computed = True

    def _name(self, name: str) -> str:
        if not self.rule.lower_case or name == name.lower():
            return name
        lowered = name.lower()
        first = self._folded.setdefault(lowered, name)
        if first != name:
            raise UnsupportedError(f"subprograms {first} and {name}, whose names the target reads as one ({lowered})")
        return lowered

    def _spare(self, name: str) -> str:
        what = "named" if not name.isdigit() else "numbered"
        if not self.rule.spare:
            raise UnsupportedError(f"the {what} subprogram {name} (the target has no spelling for it)")
        number = next((n for n in self.rule.spare if n not in self._numbers), None)
        if number is None:
            raise UnsupportedError(f"the {what} subprogram {name} (no program number left)")
        if name.isdigit():
            if self._computed:
                raise UnsupportedError(f"subprogram {name} numbered {number} after a call of a computed program "
                                       f"number (it would reach the source's number)")
            self._changed = name
        return str(number)
