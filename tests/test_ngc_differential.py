"""Random LinuxCNC programs that compute, run by rs274 and by our reader and interpreter, move by move.

A small generator writes programs with numbered and named parameters, ``if``/``else``, ``while``,
``repeat`` and ``do`` loops and calls of a subprogram with arguments; values stay bounded (``MOD``) so
rs274's 4 printed decimals are enough. Each seed is one program: a failure names the seed, and the
program is in the assertion message. A few dozen programs per run.
"""

from __future__ import annotations

import io
import math
import random

import pytest

from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

SEEDS = range(30)
TOLERANCE_MM = 2e-4


class _Gen:
    def __init__(self, seed: int) -> None:
        self.r = random.Random(seed)
        self.lines: list[str] = []
        self.label = 0

    def expr(self, depth: int = 0) -> str:
        r = self.r
        if depth > 2 or r.random() < 0.35:
            return r.choice(["#1", "#2", "#3", "#<n>", "#<_g>", str(r.randint(0, 20)), f"{r.randint(0, 99) / 4}"])
        op = r.choice(["+", "-", "*", "+", "MOD", "func"])
        if op == "func":
            return f"{r.choice(['SIN', 'COS', 'ABS', 'FIX', 'FUP', 'ROUND'])}[{self.expr(depth + 1)}]"
        if op == "MOD":
            return f"[{self.expr(depth + 1)} MOD {r.randint(2, 9)}]"
        return f"[{self.expr(depth + 1)}{op}{self.expr(depth + 1)}]"

    def bounded(self) -> str:
        return f"[{self.expr()} MOD 50]"

    def cond(self) -> str:
        return f"[{self.expr()} {self.r.choice(['LT', 'GT', 'LE', 'GE', 'EQ', 'NE'])} {self.r.randint(0, 10)}]"

    def statements(self, depth: int, count: int) -> None:
        for _ in range(count):
            self.statement(depth)

    def statement(self, depth: int) -> None:
        r = self.r
        kinds = ["move", "move", "assign", "call"] + (["if", "while", "repeat", "do"] if depth < 2 else [])
        kind = r.choice(kinds)
        emit = self.lines.append
        if kind == "move":
            if r.random() < 0.5:
                emit(f"G0 X{self.bounded()} Y{self.bounded()}")
            else:
                emit(f"G1 X{self.bounded()} Z-{self.bounded()} F100")
        elif kind == "assign":
            emit(f"#{r.randint(1, 3)}={self.bounded()} #<n>={self.bounded()}")
        elif kind == "call":
            emit(f"o<s1> call [{self.bounded()}] [{self.bounded()}]")
        else:
            self.label += 1
            label = self.label
            if kind == "if":
                emit(f"o{label} if {self.cond()}")
                self.statements(depth + 1, r.randint(1, 2))
                if r.random() < 0.5:
                    emit(f"o{label} elseif {self.cond()}")
                    self.statements(depth + 1, 1)
                if r.random() < 0.5:
                    emit(f"o{label} else")
                    self.statements(depth + 1, 1)
                emit(f"o{label} endif")
            elif kind == "repeat":
                emit(f"o{label} repeat [{r.randint(0, 3)}]")
                self.statements(depth + 1, r.randint(1, 2))
                emit(f"o{label} endrepeat")
            else:
                counter = f"#<i{label}>"
                emit(f"{counter}=0")
                if kind == "while":
                    emit(f"o{label} while [{counter} LT {r.randint(0, 3)}]")
                else:
                    emit(f"o{label} do")
                emit(f"{counter}=[{counter}+1]")
                self.statements(depth + 1, r.randint(1, 2))
                if r.random() < 0.3:
                    emit(f"o{label} if [{counter} GT 1]")
                    # rs274 never ends a repeat around a do loop left by continue (seed 15 of this
                    # generator hung it): continue only in while loops
                    emit(f"o{label} {r.choice(['break', 'continue']) if kind == 'while' else 'break'}")
                    emit(f"o{label} endif")
                    self.label += 1  # the if borrowed the loop's label in its own scope: not allowed, renumber
                    self.lines[-3] = f"o{self.label} if [{counter} GT 1]"
                    self.lines[-1] = f"o{self.label} endif"
                emit(f"o{label} endwhile" if kind == "while" else f"o{label} while [{counter} LT {r.randint(1, 3)}]")

    def program(self) -> str:
        head = ["G21 G17 G90", "G0 X0 Y0 Z5", f"#1={self.r.randint(0, 9)}", f"#2={self.r.randint(0, 9)}",
                "#3=1.5", "#<n>=2", "#<_g>=3",
                "o<s1> sub", "G1 X[#1 MOD 50] Y[#2 MOD 50] F120", "#<_g>=[[#<_g>+#1] MOD 17]", "o<s1> endsub"]
        self.lines = head
        self.statements(0, self.r.randint(4, 9))
        self.lines.append("M30")
        return "\n".join(self.lines) + "\n"


def _ours(text: str) -> list[dict[str, object]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="gen.ngc", dialect="linuxcnc")
    return [e for e in events if "move" in e]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", SEEDS)
def test_random_program_moves_as_rs274_runs_it(seed: int) -> None:
    text = _Gen(seed).program()
    theirs = [e for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = _ours(text)
    assert len(ours) == len(theirs), f"seed {seed}: {len(ours)} moves here, {len(theirs)} in rs274\n{text}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (seed, n, a, b, text)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))  # type: ignore[arg-type]
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (seed, n, a, b, text)


def test_the_generator_makes_programs_that_compute() -> None:
    """The generator is not vacuous: across the seeds it writes every construct."""
    text = "".join(_Gen(seed).program() for seed in SEEDS)
    for construct in (" if [", " elseif [", " else\n", " while [", " repeat [", " do\n", " call [", "break",
                      "continue", "#<n>=", "MOD"):
        assert construct in text, construct
