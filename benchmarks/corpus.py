"""Third-party programs x targets (issue 26, "Done when"): every program of ``tests/corpus/`` translated
to every target whose machine type fits, then verified against its source, each pair in a process of
its own with a time limit, and the matrix printed.

A pair ends in one of four ways:

* ``ok``: translated (``--on-unsupported error``) and ``verify`` passes without ``--allow-ignored``, and
  a grbl or LinuxCNC output passes its controller's own rules (``tests/support/grbl_rules.py``; rs274
  where installed); ``ok*`` in the matrix when verify compared some setting that moves the tool as a
  setting rather than as the path it cuts (cutter compensation where only one side's rules are
  simulated, path control): the same on both sides, but not checked as a toolpath;
* ``refused``: a located error saying what the target cannot express (``UnsupportedError``): the
  capability is the error's message, grouped in the triage with its numbers taken out;
* ``excused``: the source itself cannot run (a subprogram the file lacks, a value only the machine
  knows, an editor's fixture): said in the manifest with its reason, and only while simulating the
  source really fails;
* ``FAILURE``: an internal error (a traceback), a timeout, a verify failure, an output its controller
  refuses, an error without a location, or a reader or simulator refusing a source the manifest does
  not excuse.

The share the issue asks for is ok / (pairs - excused).

    .venv/bin/python benchmarks/corpus.py                 # the whole corpus, 2 processes
    .venv/bin/python benchmarks/corpus.py --only fanuc/   # programs whose path matches 'fanuc/'
    .venv/bin/python benchmarks/corpus.py --json out.json # every outcome, for a script
    .venv/bin/python benchmarks/corpus.py --manifest DIR/corpus.toml   # another folder of programs
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import multiprocessing
import multiprocessing.connection
from multiprocessing.process import BaseProcess
import re
import sys
import time
import tomllib
import traceback
from collections import Counter
import dataclasses
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Callable, Iterable, cast

if TYPE_CHECKING:
    from postproc.setup.machine_setup import MachineSetup

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

CORPUS = ROOT / "tests" / "corpus"
MANIFEST = CORPUS / "corpus.toml"
TIMEOUT_S = 120.0
"""The issue's limit for one pair: no run past two minutes."""
TOOL_LENGTH_MM = 100.0
"""Every length register n holds TOOL_LENGTH_MM + n: a tool length lost or applied twice moves the
controlled point by more than the tolerance, so verify sees it."""
TOOL_RADIUS_MM = 0.5
"""Every radius register n holds TOOL_RADIUS_MM + n / 100: small enough that no corpus contour gouges,
large enough that a cutter compensation lost or applied on the wrong side is seen."""

CHIP_AUGER = (("fanuc", "31"), ("fanuc", "33"))
"""What every target machine of a Haas program is set up to do with Haas's chip auger (M31 forward, M33 stop
[K: Haas mill and lathe operator's manuals, M-code lists]): leave it out with a comment
(``<ForeignCodes><M family="fanuc" number="31" to="omit"/>``). The harness's target machines are generic: none
is known to have a programmable chip conveyor, and an integrator moving a Haas program to such a machine
omits the auger, which moves no axis and changes no spindle, coolant, feed or tool data (the operator runs
the conveyor); a machine with one would map the codes to its own (``to="M.."``). Only programs read under the
Haas variant get it: on another Fanuc-family machine M31 is the part counter, which the harness does not
presume about."""

OK, REFUSED, EXCUSED, FAILURE = "ok", "refused", "excused", "FAILURE"
FAILURE_KINDS = ("internal error", "timeout", "verify failed", "invalid output", "unlocated error",
                 "source refused", "translation refused the source")
"""What a FAILURE can be: the first five are defects of the translation (this script's exit status is 1
for them), the last two a reader or the simulator refusing a source the manifest says is valid.
``tests/test_corpus.py`` fails on any of them that it does not list as a known defect."""
BLOCKING = FAILURE_KINDS[:5]


@dataclass(frozen=True)
class Program:
    """One corpus program as the manifest describes it."""

    path: str
    """Relative to the manifest's folder (tests/corpus/)."""
    dialect: str
    machine: str
    """``mill`` or ``lathe``: the targets are the dialects that write programs for this machine type."""
    setup: str = ""
    """A set-up file relative to the manifest's folder, or to the repository when it starts with
    ``examples/`` (default: the default set-up, or ``examples/setups/fanuc_0i_tf.xml`` for a lathe)."""
    excused: str = ""
    """Why the source itself cannot run, or ''."""
    target_setups: tuple[tuple[str, str], ...] = ()
    """Target -> a set-up file (relative like ``setup``) of the machine under that target's controller: its
    ``<MachineCodes>`` (the target machine's own codes), ``<ForeignCodes>`` (what the source's machine codes
    become there) and the ``<Controller>`` settings of its build (``_TARGET_CONTROLLER``, its tool change) join
    the program's set-up for that pair (``_setup``). In the manifest an inline table,
    ``target_setups = { gsk = "setups/….xml" }``: one machine's codes differ by controller (a gear range is
    M41 on a GSK, a user M code on LinuxCNC), and one set-up names one code per source code."""
    folder: str = str(CORPUS)
    """The manifest's folder (set when it is read, not written in it)."""


@dataclass
class Outcome:
    """How one pair (or one source check, target '') ended."""

    program: str
    target: str
    kind: str
    category: str = ""
    """A refusal's capability or a FAILURE's kind."""
    detail: str = ""
    seconds: float = 0.0
    blockers: list[str] = field(default_factory=list)
    """A refusal's distinct capabilities (every error's, not only the first's)."""


def load_manifest(path: Path = MANIFEST) -> list[Program]:
    """The programs a manifest lists; their paths (and set-ups) are taken relative to its folder."""
    with open(path, "rb") as f:
        data = tomllib.load(f)
    fields = set(Program.__dataclass_fields__) - {"folder"}
    return [Program(**{k: tuple(sorted(v.items())) if k == "target_setups" else v for k, v in entry.items()
                       if k in fields}, folder=str(path.resolve().parent))
            for entry in data["program"]]


def targets(program: Program) -> list[str]:
    """The dialects that write programs for the program's machine type, the source's own left out."""
    from postproc.plugins import default_registry
    registry = default_registry()
    names = []
    for name, dialect in registry.dialects.items():
        if name != program.dialect and dialect.WRITER is not None and program.machine in dialect.MACHINE_TYPES:
            names.append(name)
    return sorted(names)


# -- one pair ---------------------------------------------------------------------------------------

def _load(program: Program, name: str) -> MachineSetup:
    """A set-up file the manifest names: relative to the manifest's folder, or to the repository for ``examples/``."""
    from postproc.setup.machine_setup import load_setup
    folder = ROOT if name.startswith("examples/") else Path(program.folder)
    return load_setup(folder / name)


def _setup(program: Program, target: str = "") -> MachineSetup:
    """The program's set-up with a tool table in which every length and radius register has a value, for
    a Haas program what the target machines do with its chip auger (``CHIP_AUGER``), and for ``target`` the
    codes of the machine under that controller (``Program.target_setups``). The one set-up serves the
    translation and both sides of verify, as ``postproc translate --machine`` does."""
    from postproc.setup.machine_setup import MachineSetup, load_setup
    from tests.support.tools import REGISTERS, with_tools
    if program.setup:
        base = _load(program, program.setup)
    elif program.machine == "lathe":
        base = load_setup(ROOT / "examples" / "setups" / "fanuc_0i_tf.xml")
    else:
        base = MachineSetup()
    setup = with_tools(base, lengths={n: TOOL_LENGTH_MM + n for n in REGISTERS},
                       radii={n: TOOL_RADIUS_MM + n / 100 for n in REGISTERS})
    if setup.controller.variant == "haas":  # the target machines' declaration (CHIP_AUGER)
        from postproc.setup.foreign_codes import ForeignCode
        declared = {c.key() for c in setup.foreign_codes}
        setup.foreign_codes = [*setup.foreign_codes, *(ForeignCode(family=f, number=n, to="omit")
                                                       for f, n in CHIP_AUGER if (f, "M" + n) not in declared)]
    own = dict(program.target_setups).get(target)
    if own is not None:  # the target machine's codes, over the source machine's (one code: the target's wins)
        codes = _load(program, own)
        mine = {c.key() for c in codes.machine_codes}
        setup.machine_codes = [*(c for c in setup.machine_codes if c.key() not in mine), *codes.machine_codes]
        foreign = {c.key() for c in codes.foreign_codes}
        setup.foreign_codes = [*(c for c in setup.foreign_codes if c.key() not in foreign), *codes.foreign_codes]
        said = {name: value for name in _TARGET_CONTROLLER if (value := getattr(codes.controller, name)) is not None}
        if codes.controller.tool_change_with_spindle_on:
            said["tool_change_with_spindle_on"] = True
        setup.controller = dataclasses.replace(setup.controller, **said)  # the target controller's build
    return setup


_TARGET_CONTROLLER = ("tool_table", "spindle_sync", "mist_coolant", "expressions")
"""``<Controller>`` settings of a target set-up that say what the target controller's build has (None: not
said), taken over for its pairs with ``toolChangeWithSpindleOn``; the source's variant and rules stay."""


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def _source(program: Program) -> str:
    return (Path(program.folder) / program.path).read_bytes().decode("utf-8", "surrogateescape")


def capability(message: str, target: str = "") -> str:
    """A refusal's message with its particulars taken out (the target's name, values, quoted words; the
    G and M codes stay), for grouping across targets and programs."""
    text = re.sub(r"\(in [^()]*, called from [^()]*\)", "", message)
    if target:
        text = re.sub(rf"\bthe {target} dialect\b", "the target", text)
        text = re.sub(rf"\b(in|to|for) {target}\b", r"\1 the target", text)
    text = re.sub(r"'[^']*'|\"[^\"]*\"|`[^`]*`", "'…'", text)
    text = re.sub(r"\b([A-FH-LN-Za-fh-ln-z])-?\d+(\.\d*)?", r"\1n", text)
    return re.sub(r"(?<![\w.])-?\d+(\.\d+)?(?!\w)", "n", text).strip()


def _errors_outcome(program: Program, target: str, errors: list[object]) -> Outcome:
    from postproc.errors import UnsupportedError
    first = errors[0]
    where = getattr(first, "location", None)
    # the errors that are no refusal first (they decide the outcome), each with its kind
    ordered = sorted(errors, key=lambda e: isinstance(e, UnsupportedError))
    detail = "\n".join(f"{e} [{type(e).__name__}]" for e in ordered[:5])
    if any(getattr(e, "location", None) is None for e in errors):
        return Outcome(program.path, target, FAILURE, "unlocated error", detail)
    if all(isinstance(e, UnsupportedError) for e in errors):
        return Outcome(program.path, target, REFUSED, capability(getattr(first, "message", str(first)), target),
                       detail, blockers=sorted({capability(getattr(e, "message", str(e)), target) for e in errors}))
    assert where is not None
    return Outcome(program.path, target, FAILURE, "translation refused the source", detail)


def check_source(program: Program) -> Outcome:
    """Simulate the source on its set-up: the pairs of a program that cannot run at all are excused."""
    from postproc.errors import Diagnostics, ErrorLevel, ErrorList, PostprocError
    from postproc.simulate.toolpath import toolpath_events
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    try:
        for _ in toolpath_events(_lines(_source(program)), file=program.path, dialect=program.dialect,
                                 setup=_setup(program), diagnostics=diagnostics):
            pass
        diagnostics.check()
    except (ErrorList, PostprocError) as err:
        errors = err.errors if isinstance(err, ErrorList) else [err]
        detail = "\n".join(str(e) for e in errors[:5])
        if program.excused:
            return Outcome(program.path, "", EXCUSED, program.excused, detail)
        return Outcome(program.path, "", FAILURE, "source refused", detail)
    if program.excused:
        return Outcome(program.path, "", OK, "", f"excused in the manifest ({program.excused}) but it runs")
    return Outcome(program.path, "", OK)


def run_pair(program: Program, target: str) -> Outcome:
    """Translate ``program`` to ``target`` and verify the translation (see the module docstring)."""
    from postproc.api import translate
    from postproc.errors import Diagnostics, ErrorLevel, ErrorList, PostprocError
    from postproc.simulate.verify import verify_lines
    setup = _setup(program, target)
    text = _source(program)
    out = io.StringIO(newline="")
    try:
        translate(_lines(text), out, file=program.path, source=program.dialect, target=target, setup=setup,
                  on_unsupported="error", diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    except ErrorList as err:
        return _errors_outcome(program, target, list(err.errors))
    except PostprocError as err:
        return _errors_outcome(program, target, [err])
    written = out.getvalue()
    problems = output_problems(target, written, setup)
    if problems:
        return Outcome(program.path, target, FAILURE, "invalid output", "\n".join(problems[:5]))
    try:
        report = verify_lines(_lines(text), _lines(written), file_in=program.path, file_out=f"out.{target}",
                              source=program.dialect, target=target, setup=setup)
    except ErrorList as err:
        return Outcome(program.path, target, FAILURE, "verify failed",
                       "the translation does not read back: " + "\n".join(str(e) for e in err.errors[:5]))
    if not report.ok:
        return Outcome(program.path, target, FAILURE, "verify failed", report.summary())
    # verified, but settings the simulation does not apply on either side (cutter compensation under rules
    # only one side has, path control) were compared as settings, not as the path they make: marked ok*
    category = "settings compared" if report.ignored else ""
    return Outcome(program.path, target, OK, category, "\n".join([f"{report.moves} moves", *report.ignored]))


def output_problems(target: str, text: str, setup: MachineSetup | None = None) -> list[str]:
    """What the target's own controller would refuse in ``text`` (grbl's and grblHAL's parser rules, grblHAL's
    for the build and mode ``setup`` describes, as the suite checks them: ``tests.support.output_rules``; rs274)."""
    if target == "grbl":
        from tests.support.grbl_rules import grbl_problems
        return grbl_problems(text)
    if target == "grblhal":
        from postproc.setup.machine_setup import MachineSetup as Setup
        from tests.support.output_rules import problems
        return problems(target, text, setup if setup is not None else Setup())
    if target == "linuxcnc":
        from tests.support.linuxcnc_rules import available, linuxcnc_problems
        return linuxcnc_problems(text) if available() else []
    return []


# -- running many, each in a process of its own -------------------------------------------------------

Task = tuple[Program, str]
"""A program and a target; target '' is the source check."""


def _do(task: Task) -> Outcome:
    program, target = task
    start = time.perf_counter()
    try:
        with contextlib.redirect_stderr(io.StringIO()):  # warnings: verify prints its readers' own
            outcome = check_source(program) if not target else run_pair(program, target)
    except Exception:  # an internal error: any traceback is a defect
        outcome = Outcome(program.path, target, FAILURE, "internal error", traceback.format_exc(limit=6))
    outcome.seconds = time.perf_counter() - start
    return outcome


def _child(task: Task, conn: multiprocessing.connection.Connection) -> None:
    conn.send(_do(task))
    conn.close()


def run_tasks(tasks: Iterable[Task], jobs: int = 2, timeout: float = TIMEOUT_S,
              fork: bool = True) -> list[Outcome]:
    """Run each task in a forked process (``jobs`` at once), killed after ``timeout`` seconds; with
    ``fork=False`` in this process, one after the other, without a time limit."""
    tasks = list(tasks)
    if not fork:
        return [_do(task) for task in tasks]
    context = multiprocessing.get_context("fork")
    pending, results = list(tasks), list[Outcome]()
    running: dict[multiprocessing.connection.Connection, tuple[BaseProcess, Task, float]] = {}
    while pending or running:
        while pending and len(running) < jobs:
            task = pending.pop(0)
            receive, send = context.Pipe(duplex=False)
            child = context.Process(target=_child, args=(task, send))
            child.start()
            send.close()
            running[receive] = (child, task, time.monotonic())
        first_deadline = min(started + timeout for _, _, started in running.values())
        wait = max(0.0, min(0.2, first_deadline - time.monotonic()))
        for ready in multiprocessing.connection.wait(list(running), timeout=wait):
            conn = cast(multiprocessing.connection.Connection, ready)
            process, task, started = running.pop(conn)
            try:
                results.append(cast(Outcome, conn.recv()))
            except EOFError:
                process.join()
                results.append(Outcome(task[0].path, task[1], FAILURE, "internal error",
                                       f"the process ended with status {process.exitcode} before answering",
                                       time.monotonic() - started))
            process.join()
        now = time.monotonic()
        for conn, (late, task, started) in list(running.items()):
            if now - started >= timeout:
                late.kill()
                late.join()
                del running[conn]
                results.append(Outcome(task[0].path, task[1], FAILURE, "timeout", f"over {timeout:g} s", now - started))
    return results


def run_corpus(programs: list[Program], jobs: int = 2, timeout: float = TIMEOUT_S,
               fork: bool = True) -> tuple[list[Outcome], list[Outcome]]:
    """The source checks, then every pair of every program whose source is not excused."""
    # imports before forking: every child starts with the dialects loaded
    import postproc.api  # noqa: F401
    import postproc.simulate.verify  # noqa: F401
    sources = run_tasks([(p, "") for p in programs], jobs, timeout, fork)
    excused = {o.program: o for o in sources if o.kind == EXCUSED}
    tasks = [(p, t) for p in programs if p.path not in excused for t in targets(p)]
    pairs = run_tasks(tasks, jobs, timeout, fork)
    for p in programs:
        if p.path in excused:
            pairs += [Outcome(p.path, t, EXCUSED, p.excused, excused[p.path].detail) for t in targets(p)]
    order = {p.path: n for n, p in enumerate(programs)}
    key: Callable[[Outcome], tuple[int, str]] = lambda o: (order[o.program], o.target)
    return sorted(sources, key=key), sorted(pairs, key=key)


# -- reports ------------------------------------------------------------------------------------------

def share(pairs: list[Outcome]) -> tuple[int, int, float]:
    """(ok pairs, pairs that can run, their ratio): the figure issue 26 asks to reach 90 %."""
    runnable = [o for o in pairs if o.kind != EXCUSED]
    ok = sum(o.kind == OK for o in runnable)
    return ok, len(runnable), (ok / len(runnable) if runnable else 1.0)


def matrix(programs: list[Program], pairs: list[Outcome]) -> str:
    names = sorted({o.target for o in pairs})
    cell = {(o.program, o.target): o for o in pairs}
    mark = {OK: "ok", REFUSED: "refused", EXCUSED: "excused", FAILURE: "FAIL"}
    width = max(len(p.path) for p in programs)
    rows = [" ".join([f"{'program':<{width}}"] + [f"{n:>8}" for n in names])]
    for p in programs:
        marks = [_mark(cell[(p.path, n)], mark) if (p.path, n) in cell else "-" for n in names]
        rows.append(" ".join([f"{p.path:<{width}}"] + [f"{m:>8}" for m in marks]))
    return "\n".join(rows)


def _mark(outcome: Outcome, mark: dict[str, str]) -> str:
    return "ok*" if outcome.kind == OK and outcome.category else mark[outcome.kind]


def triage(outcomes: list[Outcome]) -> str:
    """Failures by kind, then refusals by capability: the pairs each blocks and the pairs it alone
    blocks (those a fix would gain), most first, with the targets."""
    lines = []
    failures: dict[str, list[Outcome]] = {}
    for o in outcomes:
        if o.kind == FAILURE:
            failures.setdefault(o.category, []).append(o)
    for category, members in sorted(failures.items(), key=lambda kv: -len(kv[1])):
        lines.append(f"{len(members):4} FAILURE  {category}  [{_targets(members)}]")
        for o in members[:4]:
            text = o.detail.strip().splitlines() if o.detail else [""]
            first = text[-1] if o.category == "internal error" else text[0]
            lines.append(f"       {o.program} -> {o.target or '(source)'}: {first[:150]}")
    refusals: dict[str, list[Outcome]] = {}
    for o in outcomes:
        if o.kind == REFUSED:
            for blocker in o.blockers or [o.category]:
                refusals.setdefault(blocker, []).append(o)
    refused = [o for o in outcomes if o.kind == REFUSED]
    fixed: set[str] = set()
    gained = 0
    while len(fixed) < len(refusals):
        # the capability whose fix, with those above it, frees the most refused pairs
        def freed(blocker: str) -> int:
            return sum(set(o.blockers or [o.category]) <= fixed | {blocker} for o in refused)
        best = max((b for b in refusals if b not in fixed), key=lambda b: (freed(b), len(refusals[b]), b))
        now = freed(best)
        fixed.add(best)
        lines.append(f"{len(refusals[best]):4} refused  +{now - gained:<3} {best}  [{_targets(refusals[best])}]")
        gained = now
    return "\n".join(lines)


def _targets(members: list[Outcome]) -> str:
    counts = Counter(o.target or "(source)" for o in members)
    return ", ".join(f"{t} {n}" for t, n in sorted(counts.items()))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jobs", type=int, default=2, help="processes at once (default 2)")
    parser.add_argument("--timeout", type=float, default=TIMEOUT_S, help="seconds per pair (default 120)")
    parser.add_argument("--manifest", type=Path, default=MANIFEST,
                        help="another manifest (default tests/corpus/corpus.toml); paths are relative to its folder")
    parser.add_argument("--only", default="", help="only programs whose path matches this regular expression")
    parser.add_argument("--json", help="write every outcome to this file")
    parser.add_argument("--details", action="store_true", help="print every refusal's and failure's message")
    args = parser.parse_args(argv)
    programs = [p for p in load_manifest(args.manifest) if re.search(args.only, p.path)]
    started = time.monotonic()
    sources, pairs = run_corpus(programs, args.jobs, args.timeout)
    print(matrix(programs, pairs))
    print()
    ok, runnable, ratio = share(pairs)
    counts = Counter(o.kind for o in pairs)
    print(f"{len(programs)} programs, {len(pairs)} pairs: {counts[OK]} ok, {counts[REFUSED]} refused, "
          f"{counts[EXCUSED]} excused, {counts[FAILURE]} FAILURE; translated and verified: {ok}/{runnable} = "
          f"{100 * ratio:.1f} % of the pairs that can run ({time.monotonic() - started:.0f} s)")
    starred = sum(o.kind == OK and bool(o.category) for o in pairs)
    print(f"ok* ({starred} of the ok pairs): verified with settings the simulation applies on neither side (cutter "
          "compensation without both dialects' rules, path control) compared as settings, not as the path they cut")
    notes = [o for o in sources if o.detail and o.kind == OK]
    for o in notes:
        print(f"note: {o.program}: {o.detail}")
    print("\ntriage: failures by kind; then refusals by capability, ranked by the pairs each fix gains with the "
          "fixes above it (+n), with the pairs it blocks and [pairs per target]:")
    print(triage(sources + pairs))
    if args.details:
        for o in sources + pairs:
            if o.kind in (REFUSED, FAILURE):
                print(f"\n== {o.program} -> {o.target or '(source)'}: {o.kind} {o.category}\n{o.detail}")
    if args.json:
        Path(args.json).write_text(json.dumps([asdict(o) for o in sources + pairs], indent=1))
    return 1 if any(o.kind == FAILURE and o.category in BLOCKING for o in sources + pairs) else 0


if __name__ == "__main__":
    sys.exit(main())
