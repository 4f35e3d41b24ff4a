"""Random LinuxCNC G70/G71/G72 profiles written with o-word control flow and parameter assignments, for the
differential against rs274 (``tests/test_ngc_g7x.py``).

A profile drawn by ``tests.support.g7x_profiles`` is rewritten block by block in forms a programmer uses, so
that the controller must run the subprogram's statements to find its moves: a point read from a table of
global parameters (``#[100+i]``), a move relative to the current position (``#<_x>``, ``#<_z>``: the profile's
own point), a run of straight moves as a ``WHILE``, ``DO .. WHILE`` or ``REPEAT`` loop over the table, a move in
the taken branch of an ``IF``/``ELSEIF``/``ELSE`` (a decoy move in the others), a move through a local
parameter (``#1``) or through a call of another subprogram (``O.. CALL [x] [z]``). The moves the controller
makes are those of the drawn profile; which of them it cuts is rs274's to say.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

from tests.support.g7x_profiles import Case, Step, draw

X_TABLE = 100
Z_TABLE = 300
"""The global parameters holding the drawn points (#100.. X, #300.. Z; LinuxCNC's globals are #31-#5000)."""


@dataclass
class StatementCase:
    """A drawn ``case`` whose profile subprogram is ``body`` (statements and moves); ``helpers`` are the
    subprograms it calls, defined before it."""

    case: Case
    body: list[str]
    helpers: list[str]

    def subprograms(self, label: int) -> list[str]:
        return self.helpers + [f"O{label} SUB", *("  " + line for line in self.body), f"O{label} ENDSUB"]

    def cycle(self, label: int) -> list[str]:
        c = self.case
        return [f"G0 X{c.x:.4f} Z{c.z:.4f}",
                f"G{c.code} Q{label} X{c.x:.4f} Z{c.z:.4f}" + "".join(f" {k}{v:g}" for k, v in c.words.items())]

    def program(self) -> str:
        return "\n".join(["G18 G21 G8 G90 G40", "F400", *self.subprograms(100), *self.cycle(100), "M2"]) + "\n"


def batch(cases: list[StatementCase]) -> str:
    """One program running ``cases`` one after the other, each profile its own subprogram."""
    lines = ["G18 G21 G8 G90 G40", "F400"]
    for n, case in enumerate(cases):
        lines += case.subprograms(101 + n)
    for n, case in enumerate(cases):
        lines += case.cycle(101 + n)
    return "\n".join(lines + ["M2"]) + "\n"


def _plain_line(step: Step) -> bool:
    return step.g == 1 and not step.words


def _extra(step: Step) -> str:
    return "".join(f" {k}{v:.4f}" for k, v in step.words.items())


def rewrite(case: Case, rng: random.Random, labels: int) -> StatementCase:
    """``case``'s profile in statement forms (module docstring); o-word labels from ``labels`` on (a
    subprogram's labels are its own, but distinct ones keep the program readable)."""
    steps = case.steps
    body = [" ".join(f"#{X_TABLE + i}={s.x:.4f} #{Z_TABLE + i}={s.z:.4f}" for i, s in enumerate(steps[j:j + 3], j))
            for j in range(0, len(steps), 3)]
    helpers: list[str] = []
    label = labels
    i = 0
    while i < len(steps):
        step = steps[i]
        run = i
        while run < len(steps) and _plain_line(steps[run]):
            run += 1
        form = rng.choice(("plain", "table", "relative", "loop", "branch", "local", "call"))
        if form == "loop" and run - i >= 2:
            end = rng.randint(i + 2, run)
            kind = rng.choice(("while", "do", "repeat"))
            label += 1
            row = f"G1 X[#[{X_TABLE}+#<_k>]] Z[#[{Z_TABLE}+#<_k>]]"
            if kind == "while":
                body += [f"#<_k>={i}", f"O{label} WHILE [#<_k> LT {end}]", f"  {row}", "  #<_k>=[#<_k>+1]",
                         f"O{label} ENDWHILE"]
            elif kind == "do":
                body += [f"#<_k>={i}", f"O{label} DO", f"  {row}", "  #<_k>=[#<_k>+1]",
                         f"O{label} WHILE [#<_k> LT {end}]"]
            else:
                body += [f"#<_k>={i}", f"O{label} REPEAT [{end - i}]", f"  {row}", "  #<_k>=[#<_k>+1]",
                         f"O{label} ENDREPEAT"]
            i = end
            continue
        if form == "table":
            body.append(f"G{step.g} X[#{X_TABLE + i}] Z[#{Z_TABLE + i}]{_extra(step)}")
        elif form == "relative" and 0 < i < len(steps) - 2 and step.g in (0, 1):
            # (not the last two: a sum may miss the drawn number by a rounding, and the profile's last move must
            # end exactly at the cycle's X or Z for the reading to take it without a version)
            before = steps[i - 1]
            body.append(f"G{step.g} X[#<_x>+{step.x - before.x:.4f}] Z[#<_z>+{step.z - before.z:.4f}]"
                        f"{_extra(step)}")
        elif form == "branch":
            label += 1
            threshold = rng.randint(1, 3)
            taken = rng.randrange(3)  # the IF, the ELSEIF or the ELSE
            decoy = f"G1 X{step.x + 7.0:.4f} Z{step.z - 9.0:.4f}"
            arms = [decoy, decoy, decoy]
            arms[taken] = step.text()
            value = [threshold + 1, threshold, threshold - 1][taken]
            body += [f"#<_sel>={value}", f"O{label} IF [#<_sel> GT {threshold}]", f"  {arms[0]}",
                     f"O{label} ELSEIF [#<_sel> EQ {threshold}]", f"  {arms[1]}", f"O{label} ELSE",
                     f"  {arms[2]}", f"O{label} ENDIF"]
        elif form == "local":
            body += [f"#1={step.x:.4f}", f"#2=[{step.z:.4f}]", f"G{step.g} X#1 Z#2{_extra(step)}"]
        elif form == "call" and _plain_line(step):
            label += 1
            helpers += [f"O{label} SUB", "  G1 X#1 Z#2", f"O{label} ENDSUB"]
            body.append(f"O{label} CALL [{step.x:.4f}] [{step.z:.4f}]")
        else:
            body.append(step.text())
        i += 1
    return StatementCase(case, body, helpers)


def draw_with_statements(rng: random.Random, code: str, labels: int) -> StatementCase:
    """A random cycle whose profile the controller runs through statements (module docstring)."""
    return rewrite(draw(rng, code), rng, labels)
