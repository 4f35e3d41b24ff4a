"""Returned values across dialect families: whether a program kept symbolically reads the values its calls
return as the target's controller sets them.

A family whose calls return a value keeps it in variables of its own (``Variables`` classes name them in
``RETURNED`` and say in ``RETURN_RULE`` when a call, a return and a definition the flow passes set them). Two
controllers of one spelling may set them at other moments: LinuxCNC's flow passing ``o100 sub`` .. ``o100 endsub
[6]`` sets the returned value, grblHAL's does not; grblHAL zeroes it at a call and keeps it at a return without a
value, LinuxCNC the other way round. And a return's value may be evaluated with the callee's parameters or,
once the call is unwound, with the caller's (``SubprogramRules.value_in_caller``). A program that reads such a
variable between two families that differ there is flattened instead: the source's run gives the values (one
that reads none may return what it likes: nothing reads it).
"""

from __future__ import annotations

from typing import Iterable, Iterator

from ..ir import Block
from ..ir.expr import Expr
from .rules import SubprogramRules
from .variables import VariablesFactory


def returned_names(family: VariablesFactory) -> frozenset[str]:
    """The named variables a return sets in ``family`` (none for a family without returned values)."""
    names: object = getattr(family, "RETURNED", None)
    return frozenset(name for name in names if isinstance(name, str)) if isinstance(names, frozenset) else frozenset()


def return_rule(family: VariablesFactory) -> str | None:
    """How ``family``'s calls, returns and passed definitions set its returned variables (None: it has none)."""
    rule = getattr(family, "RETURN_RULE", None)
    return rule if isinstance(rule, str) else None


def foreign_return(blocks: Iterable[Block], source: tuple[VariablesFactory, SubprogramRules],
                   target: tuple[VariablesFactory, SubprogramRules], names: tuple[str, str]) -> str | None:
    """Why ``blocks`` cannot read their returned values from ``source``'s family to ``target``'s (None: they
    can, or they read none): ``source`` and ``target`` are each family's variables and subprogram rules,
    ``names`` the source's and the target's dialect, for the message."""
    (ours, our_rules), (theirs, their_rules) = source, target
    returned = returned_names(ours)
    if not returned:
        return None
    rule, other = return_rule(ours), return_rule(theirs)
    why: list[str] = []
    if rule != other:
        why.append(f"{names[0]}: {rule}; {names[1]}: {other or 'no such variable'}")
    if our_rules.definition_runs_its_end != their_rules.definition_runs_its_end:
        runs, skips = (names[0], names[1]) if our_rules.definition_runs_its_end else (names[1], names[0])
        why.append(f"{runs} sets them where the flow passes a definition's end, {skips} does not")
    if our_rules.value_in_caller != their_rules.value_in_caller:
        late, early = (names[0], names[1]) if our_rules.value_in_caller else (names[1], names[0])
        why.append(f"{early} evaluates a return value with the callee's parameters, {late} with the caller's")
    if not why:
        return None
    for block in blocks:
        for name in _names(block):
            if name in returned:
                return f"line {block.line}: it reads #<{name}>, which {names[1]} sets otherwise ({'; '.join(why)})"
    return None


def _names(block: Block) -> Iterator[str]:
    """The variable names ``block`` reads: in its sections (statements) and in its words' values (a word's
    expression is in ``values`` until the block syntax reads it into a section)."""
    for item in (*block.sections.values(), *(v for v in block.values.values() if isinstance(v, Expr))):
        for var in item.make_xml_source().iter("Var"):
            name = var.get("name")
            if name is not None:
                yield name
