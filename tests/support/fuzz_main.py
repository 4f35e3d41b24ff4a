"""The long-running fuzz target (``make fuzz``; not in CI): the suite's checks on random cases until a
time budget runs out, every case under a time limit. Prints the case count and each outcome; saves
every new failure (reduced to a small program) and one example of each known defect to a folder.
A round gives every pair and generator ``--per-round`` cases; the budget is checked before each case, so
a run ends on time (its last round then covers only the pairs it reached: the counts per pair say which).

    python -m tests.support.fuzz_main [--minutes 10] [--per-round 50] [--out fuzz-failures] [--case-seconds 5]
                                      [--only KIND ...]

``--only`` runs just the named generator kinds (``tests/support/generators``; 'pairs' and 'toolpath' name
the random fragments' translations and simulations), to give one generator the whole budget.
"""

from __future__ import annotations

import argparse
import contextlib
import math
import re
import signal
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Callable, Iterator

from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from postproc.setup.machine_setup import MachineSetup
from tests.support.fuzzing import PAIRS, READERS, check_toolpath, check_translation, known_defect, programs, setups
from tests.support.generators import Case, strategies

ROUND = 50
"""Cases per pair and round by default (a hypothesis run without shrinking; we reduce failures ourselves)."""


class CaseTimeout(Exception):
    pass


WALL_FACTOR = 20
"""The wall-clock backstop of a case, in multiples of its CPU limit (a case waiting on something, not working)."""


@contextlib.contextmanager
def time_limit(seconds: float) -> Iterator[None]:
    """At most ``seconds`` of this process's CPU time (``ITIMER_PROF``), and ``WALL_FACTOR`` times that on the
    clock. CPU, not wall time: on a shared machine (load 15 on 2 cores) a case of 0.5 s of CPU took 5.2 s on the
    clock and was saved as a hang; an endless run spends CPU, so it is caught all the same. (rs274, a child
    process, runs under its own timeout: ``tests/support/rs274.py``.)"""

    def expire(signum: int, frame: object) -> None:
        raise CaseTimeout("of CPU" if signum == signal.SIGPROF else "on the clock")

    previous = {sig: signal.signal(sig, expire) for sig in (signal.SIGPROF, signal.SIGALRM)}
    signal.setitimer(signal.ITIMER_PROF, seconds)
    signal.setitimer(signal.ITIMER_REAL, seconds * WALL_FACTOR)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.setitimer(signal.ITIMER_REAL, 0)
        for sig, handler in previous.items():
            signal.signal(sig, handler)


class Fuzzer:
    def __init__(self, out: Path, case_seconds: float, end: float = math.inf, per_round: int = ROUND,
                 only: frozenset[str] = frozenset()) -> None:
        self.out = out
        self.only = only
        """Kinds to run (empty: all)."""
        self.case_seconds = case_seconds
        self.end = end
        """``time.monotonic()`` at which the budget runs out: later cases are not run."""
        self.per_round = per_round
        self.cases = 0
        self.outcomes: Counter[str] = Counter()
        self.per_name: Counter[str] = Counter()
        """Cases run per pair or generator kind."""
        self.saved: set[str] = set()

    def over(self) -> bool:
        return time.monotonic() >= self.end

    def outcome(self, run: Callable[[str], object], program: str, target: str) -> tuple[str, str]:
        """(kind, message) of one case: 'ok', 'refused', 'known: ...' or 'NEW: ...'."""
        try:
            with time_limit(self.case_seconds):
                result = run(program)
            return (str(result) if result else "ok"), ""
        except CaseTimeout as exc:
            limit = self.case_seconds * (1 if str(exc) == "of CPU" else WALL_FACTOR)
            return f"NEW: ran longer than {limit:g} s {exc}", ""
        except AssertionError as exc:
            message = str(exc)
            known = known_defect(target, message)
            return (f"known: {known}" if known else "NEW: " + _signature(message)), message
        except Exception as exc:  # an internal error: exactly what fuzzing is for
            message = f"{type(exc).__name__}: {exc}"
            return "NEW: internal error " + _signature(message), message

    def record(self, name: str, run: Callable[[str], object], program: str, target: str, setup: object) -> None:
        if self.over():
            return  # the budget ran out: the rest of the round's draws are not run
        self.cases += 1
        self.per_name[name] += 1
        kind, message = self.outcome(run, program, target)
        self.outcomes[kind] += 1
        key = f"{name} {kind}"
        if not kind.startswith(("NEW", "known")) or key in self.saved:  # ok, refused, warned: ...
            return
        self.saved.add(key)
        small = reduce(program, lambda p: self.outcome(run, p, target)[0] == kind)
        self.out.mkdir(parents=True, exist_ok=True)
        path = self.out / f"{len(self.saved):03d}-{name}.txt"
        path.write_text(f"{name}\n{kind}\nset-up: {setup!r}\n\n--- reduced program ---\n{small}"
                        f"--- message (original program) ---\n{message}\n--- original program ---\n{program}")
        print(f"  {kind} [{name}] -> {path}", flush=True)

    def runs(self, kind: str) -> bool:
        return not self.only or kind in self.only

    def round(self) -> None:
        for source, target in PAIRS if self.runs("pairs") else ():
            name = f"{source}-{target}"

            if self.over():
                return

            @settings(max_examples=self.per_round, deadline=None, database=None, phases=[Phase.generate],
                      suppress_health_check=list(HealthCheck))
            @given(program=programs(), setup=setups(), warn=st.booleans())
            def case(program: str, setup: MachineSetup, warn: bool) -> None:
                self.record(name, lambda p: check_translation(source, target, p, setup, warn), program, target,
                            setup)

            case()
        for dialect in READERS if self.runs("toolpath") else ():
            if self.over():
                return

            @settings(max_examples=max(1, self.per_round // 4), deadline=None, database=None, phases=[Phase.generate],
                      suppress_health_check=list(HealthCheck))
            @given(program=programs(), setup=setups())
            def path_case(program: str, setup: MachineSetup) -> None:
                self.record(f"toolpath-{dialect}", lambda p: check_toolpath(dialect, p, setup), program, dialect,
                            setup)

            path_case()
        for kind, strategy in strategies().items():
            if not self.runs(kind):
                continue
            if self.over():
                return

            @settings(max_examples=self.per_round, deadline=None, database=None, phases=[Phase.generate],
                      suppress_health_check=list(HealthCheck))
            @given(case=strategy)
            def generated_case(case: Case) -> None:
                self.record(case.name, case.run, case.program, case.target, case.setup)

            generated_case()


def reduce(program: str, fails: Callable[[str], bool], budget: int = 300) -> str:
    """A smaller program that still fails the same way: drop lines, then words, while it does."""
    lines = program.splitlines()
    head, body = lines[:1], lines[1:]

    def text(b: list[str]) -> str:
        return "\n".join(head + b) + "\n"

    i = 0
    while i < len(body) and budget > 0:
        trial = body[:i] + body[i + 1:]
        budget -= 1
        if fails(text(trial)):
            body = trial
        else:
            i += 1
    for i in range(len(body)):
        words = body[i].split(" ")
        j = 0
        while j < len(words) and budget > 0:
            fewer = words[:j] + words[j + 1:]
            budget -= 1
            if fails(text(body[:i] + [" ".join(fewer)] + body[i + 1:])):
                words = fewer
            else:
                j += 1
        body[i] = " ".join(words)
    return text(body)


def _signature(message: str) -> str:
    first = message.splitlines()[0] if message else ""
    return re.sub(r"\d+", "N", first)[:160]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--out", type=Path, default=Path("fuzz-failures"))
    parser.add_argument("--case-seconds", type=float, default=5.0)
    parser.add_argument("--per-round", type=int, default=ROUND, help="cases per pair (and generator) per round")
    parser.add_argument("--only", action="append", default=[], metavar="KIND",
                        help="run only this generator kind ('pairs', 'toolpath' or a generator's KIND); repeatable")
    args = parser.parse_args(argv)
    unknown = set(args.only) - {"pairs", "toolpath", *strategies()}
    if unknown:
        parser.error(f"--only: unknown kind(s) {sorted(unknown)}; known: pairs, toolpath, {', '.join(strategies())}")
    start = time.monotonic()
    fuzzer = Fuzzer(args.out, args.case_seconds, start + args.minutes * 60, max(1, args.per_round),
                    frozenset(args.only))
    rounds = 0
    while not fuzzer.over():
        fuzzer.round()
        rounds += 1
        print(f"round {rounds}: {fuzzer.cases} cases", flush=True)
    print(f"\n{fuzzer.cases} cases in {rounds} rounds, {(time.monotonic() - start) / 60:.1f} minutes")
    print("cases per pair or generator:")
    for name, count in sorted(fuzzer.per_name.items()):
        print(f"{count:8d}  {name}")
    print("outcomes:")
    for kind, count in sorted(fuzzer.outcomes.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"{count:8d}  {kind}")
    new = sum(c for k, c in fuzzer.outcomes.items() if k.startswith("NEW"))
    print(f"\n{new} new failure(s); saved cases in {args.out}/" if fuzzer.saved else "\nno failures")
    return 1 if new else 0


if __name__ == "__main__":
    sys.exit(main())
