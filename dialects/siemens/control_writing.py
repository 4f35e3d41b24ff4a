"""Another dialect's variables and control flow in SINUMERIK's spelling (the writer's ``statement_words``).

What has an exact spelling is written; anything else is an ``UnsupportedError``, which makes the translation
flatten the program (the keep check's dry run, ``postproc.api``) with the warning every dialect gives:

* an assignment ``R1=<expr>`` to an R parameter (``R<n>`` is the neutral ``#500+n``, ``expressions``); a named
  variable needs its ``DEF`` at the program's start [K: 840D Job planning "Definition of user variables
  (DEF)": definitions come before the first statement], which a streamed translation cannot place: refused;
* ``IF cond`` / ``ELSE`` / ``ENDIF``, ``WHILE cond`` / ``ENDWHILE``, ``REPEAT`` / ``UNTIL cond`` (the
  neutral do-while as ``UNTIL NOT (cond)``), ``FOR R1=a TO b`` (step 1 only: SINUMERIK's FOR counts up by 1
  while the counter is at most the end value [K: Job planning "FOR counter loop"]) [K: 840D Job planning
  "Control structures"]. A condition is true when non-zero on SINUMERIK as in the neutral IR (the reader
  takes it as it is). There is no ``ELSEIF``, ``SWITCH``, ``BREAK`` or ``CONTINUE`` on the 840D: refused;
* jumps: ``GOTOF`` to a target not yet written, ``GOTOB`` to one written before, ``IF cond GOTOF ..`` for a
  conditional one [K: Fundamentals "Program jumps to jump markers"]; a numbered target is the block number
  ``N<n>`` (the source's sequence number, written on its block), a named one the label ``NAME:``. The neutral
  jump searches forward, then from the start; SINUMERIK's ``GOTOF``/``GOTOB`` search one way, so a target
  must be on one block only: the writer checks that when the program ends (``JumpTargets``);
* calls, subprogram definitions and returns are not written yet (a SINUMERIK subprogram is a file of its
  own, ``NAME.SPF``): refused, so such a program is flattened.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from postproc.interp.control import (
    Assign, Do, DoWhile, Else, EndFor, EndIf, EndWhile, For, Goto, GotoLabel, If, Until, While,
)
from postproc.errors import Location, UnsupportedError
from postproc.ir.expr import Expr, Num, Unary, Var
from postproc.ir import Section

from .expressions import spell_expr, spell_var

RESERVED = frozenset(("IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "TO", "ENDFOR", "REPEAT", "UNTIL",
                      "LOOP", "ENDLOOP", "GOTO", "GOTOF", "GOTOB", "GOTOC", "DEF", "PROC", "RET", "MCALL",
                      "TRANS", "NOT", "AND", "OR", "XOR", "MOD", "DIV"))
"""Words a label must not be (the reader takes them as statements)."""
LABEL_LENGTH = 32
"""[K: 840D Fundamentals "Labels": up to 32 characters, the first two letters or underscores]."""


def variable(var: Var) -> str:
    """An R parameter; a named variable would need a ``DEF`` at the program's start."""
    if var.name is not None:
        raise UnsupportedError(f"the named variable {var.name!r} (SINUMERIK needs its DEF at the program's start)")
    return spell_var(var)


def expression(expr: Expr) -> str:
    """``expr`` with its variables checked as ``variable`` does."""
    for var in _variables(expr):
        variable(var)
    return spell_expr(expr)


def _variables(expr: Expr) -> list[Var]:
    found: list[Var] = []
    stack = [expr]
    while stack:
        item = stack.pop()
        if isinstance(item, Var):
            found.append(item)
            if isinstance(item.index, Expr):
                stack.append(item.index)
            continue
        for name in ("operand", "left", "right"):
            child = getattr(item, name, None)
            if isinstance(child, Expr):
                stack.append(child)
        stack.extend(a for a in getattr(item, "args", ()) if isinstance(a, Expr))
    return found


def label_name(name: str) -> str:
    """A jump label in SINUMERIK's rules (upper case: SINUMERIK names are not case-sensitive [K])."""
    bare = name[1:-1] if name.startswith("<") and name.endswith(">") else name
    upper = bare.upper()
    if (not 2 <= len(upper) <= LABEL_LENGTH or not all(c.isalnum() or c == "_" for c in upper)
            or not all(c.isalpha() or c == "_" for c in upper[:2]) or upper in RESERVED):
        raise UnsupportedError(f"the label {name!r} (a SINUMERIK label has 2 to {LABEL_LENGTH} letters, digits "
                               "and _, the first two letters or _)")
    return upper


@dataclass
class JumpTargets:
    """The jump targets written so far (``N<n>`` or a label), to choose ``GOTOF``/``GOTOB`` and to check at
    the end that each target a jump names is on one block only."""

    written: dict[str, int] = field(default_factory=dict)
    """Target -> how many blocks carry it so far."""
    jumps: list[tuple[str, Location | None]] = field(default_factory=list)

    def mark(self, target: str) -> None:
        self.written[target] = self.written.get(target, 0) + 1

    def jump(self, target: str, at: Location | None) -> str:
        self.jumps.append((target, at))
        return "GOTOB" if self.written.get(target) else "GOTOF"

    def problems(self) -> list[UnsupportedError]:
        found = []
        for target, at in self.jumps:
            count = self.written.get(target, 0)
            if count != 1:
                found.append(UnsupportedError(
                    f"a jump to {target}, which is on {count or 'no'} block{'s' if count != 1 else ''} of the output "
                    "(SINUMERIK's GOTOF/GOTOB need exactly one)", at))
        return found


def statement(section: Section, targets: JumpTargets, at: Location | None) -> list[str]:
    """The words of one assignment or control statement."""
    if isinstance(section, Assign):
        return [f"{variable(var)}={expression(value)}" for var, value in section.items]
    if isinstance(section, If):
        return ["IF " + expression(section.cond)]
    if isinstance(section, Else):
        return ["ELSE"]
    if isinstance(section, EndIf):
        return ["ENDIF"]
    if isinstance(section, While):
        return ["WHILE " + expression(section.cond)]
    if isinstance(section, EndWhile):
        return ["ENDWHILE"]
    if isinstance(section, Do):
        return ["REPEAT"]
    if isinstance(section, Until):
        return ["UNTIL " + expression(section.cond)]
    if isinstance(section, DoWhile):
        return ["UNTIL " + expression(Unary("not", section.cond))]
    if isinstance(section, For):
        if not (isinstance(section.step, Num) and section.step.value == 1):
            raise UnsupportedError("a counted loop whose step is not 1 (SINUMERIK's FOR counts up by 1)")
        return [f"FOR {variable(section.counter)}={expression(section.start)} TO {expression(section.end)}"]
    if isinstance(section, EndFor):
        return ["ENDFOR"]
    if isinstance(section, (Goto, GotoLabel)):
        target = label_name(section.label) if isinstance(section, GotoLabel) else _block_number(section.target)
        jump = f"{targets.jump(target, at)} {target}"
        return [jump] if section.cond is None else [f"IF {expression(section.cond)} {jump}"]
    raise UnsupportedError(f"{_NAMES.get(type(section).__name__, type(section).__name__)} (no SINUMERIK "
                           "statement written for it)")


def _block_number(target: Expr) -> str:
    if isinstance(target, Num) and target.value.is_integer() and target.value >= 0:
        return f"N{int(target.value)}"
    raise UnsupportedError("a jump to a computed block number (SINUMERIK jumps to a label or a written N)")


_NAMES = {"ElseIf": "ELSEIF branches", "IfThen": "conditional assignments (IF .. THEN)", "Switch": "SWITCH",
          "Case": "SWITCH", "Default": "SWITCH", "EndSwitch": "SWITCH", "Break": "loop breaks",
          "Continue": "loop continues", "Repeat": "counted REPEAT loops", "EndRepeat": "counted REPEAT loops",
          "Call": "subprogram calls", "SubStart": "subprogram definitions", "SubEnd": "subprogram definitions",
          "Return": "subprogram returns", "ModalCall": "modal macro calls", "ModalCallCancel": "modal macro calls"}
