"""The conformance checks, as plain functions that return what is wrong (an empty list: nothing).

Each message names the dialect, the file and line, and what differs, so a plugin author reads the
failure and knows where to look. ``postproc.testing`` runs them as pytest tests; they run as well from
any other harness.
"""

from __future__ import annotations

import contextlib
import dataclasses
import io
import re
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

from .. import api
from ..dialect import Dialect
from ..errors import Diagnostics, ErrorList, PostprocError
from ..ir import Block
from ..plugins import default_registry
from ..commands.program_xml import dump_program, load_program
from ..setup.machine_setup import InputSettings, MachineSetup, load_setup
from ..simulate.toolpath import start_position, toolpath_events
from ..simulate.verify import compare, verify_lines
from ..xmlio import to_bytes
from .neutral import NeutralProgram, simulate_neutral, write_neutral

LOCATED = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<col>\d+): error: \S")
"""An error line as every postproc command prints it: ``FILE:LINE:COL: error: message``."""

PROGRAM_SUFFIXES = frozenset({".nc", ".ngc", ".tap", ".gcode", ".cnc", ".txt", ".mpf", ".min", ".iso", ".ptp"})
"""File name endings taken for programs in an examples folder (others, such as README.md, are skipped)."""


@dataclass
class DialectUnderTest:
    """What the suite checks: a dialect, its example programs and the known-bad ones it gives.

    ``examples`` holds programs in the dialect that must read back byte for byte; ``invalid`` programs that
    must fail (a ``NAME.err`` beside ``NAME.nc`` lists lines the error output must contain); ``setup`` an
    optional machine set-up XML the examples are read under (a lathe, a decimal-point mode)."""

    dialect: str
    examples: Path
    invalid: Path | None = None
    setup: Path | None = None
    name: str = ""
    """How the case is named in messages (default: the dialect)."""
    skip_targets: frozenset[str] = field(default_factory=frozenset)
    """Dialects the cross-translation check leaves out (say why where you set it)."""

    def __post_init__(self) -> None:
        self.name = self.name or self.dialect

    def cls(self) -> type[Dialect]:
        return default_registry().dialect(self.dialect)

    def machine(self) -> MachineSetup:
        return load_setup(self.setup, groups=default_registry().setup_groups) if self.setup is not None \
            else MachineSetup()

    def programs(self) -> list[Path]:
        return _programs(self.examples)

    def bad_programs(self) -> list[Path]:
        return _programs(self.invalid) if self.invalid is not None else []


def _programs(folder: Path) -> list[Path]:
    if not folder.is_dir():
        return []
    return sorted(p for p in folder.iterdir() if p.is_file() and p.suffix.lower() in PROGRAM_SUFFIXES)


def read_text(path: Path) -> str:
    """A program as the command line reads it (bytes kept: no newline translation)."""
    with open(path, encoding="utf-8", errors="surrogateescape", newline="") as f:
        return f.read()


def quiet() -> Diagnostics:
    """Diagnostics whose warnings are kept, not printed (the checks judge errors only)."""
    return Diagnostics(warn_stream=io.StringIO())


def _first_difference(expected: str, got: str) -> str:
    a, b = expected.splitlines(keepends=True), got.splitlines(keepends=True)
    for n, (x, y) in enumerate(zip(a, b), 1):
        if x != y:
            return f"line {n}:\n    read:  {x!r}\n    wrote: {y!r}"
    if len(a) != len(b):
        n = min(len(a), len(b)) + 1
        extra = (a if len(a) > len(b) else b)[n - 1]
        which = "dropped" if len(a) > len(b) else "added"
        return f"line {n}: the writer {which} {extra!r} ({len(a)} lines read, {len(b)} written)"
    return "the texts differ only in bytes splitlines hides"


# -- 1. same-dialect round trip -----------------------------------------------------------------------

def round_trip_problems(case: DialectUnderTest, path: Path) -> list[str]:
    """Read in the dialect and write back in it: byte for byte the same text."""
    text = read_text(path)
    out = io.StringIO()
    try:
        api.translate(io.StringIO(text), out, file=str(path), source=case.dialect, target=case.dialect,
                      setup=case.machine(), diagnostics=quiet())
    except ErrorList as errs:
        return [f"{path}: reading and writing back in {case.dialect} fails:\n" + "\n".join(f"  {e}" for e in errs.errors)]
    if out.getvalue() != text:
        return [f"{path}: written back in {case.dialect}, the program changed at {_first_difference(text, out.getvalue())}"]
    return []


# -- 2. IR -> XML -> IR ---------------------------------------------------------------------------------

def ir_xml_problems(case: DialectUnderTest, path: Path) -> list[str]:
    """The program's IR dumped as XML and loaded again equals the IR, block for block."""
    try:
        blocks = api.read_program(io.StringIO(read_text(path)), file=str(path), dialect=case.dialect,
                              setup=case.machine())
    except ErrorList as errs:
        return [f"{path}: the {case.dialect} reader refuses its own example:\n" + "\n".join(f"  {e}" for e in errs.errors)]
    return blocks_xml_problems(blocks, case.dialect, str(path))


def blocks_xml_problems(blocks: list[Block], dialect: str, file: str) -> list[str]:
    buf = io.BytesIO()
    try:
        dump_program(blocks, buf, dialect=dialect, file=file)
    except PostprocError as err:
        return [f"{file}: the IR cannot be written as XML: {err}"]
    with tempfile.TemporaryDirectory() as tmp:
        xml = Path(tmp) / "ir.xml"
        xml.write_bytes(buf.getvalue())
        try:
            _, back = load_program(xml)
        except PostprocError as err:
            return [f"{file}: the IR XML does not load back (a section's XNAME, from_xml or reg is missing?): {err}"]
    for before, after in zip(blocks, back):
        if before != after:
            return [f"{file}:{before.line}: the block's IR changes through XML:\n    before: {before!r}\n"
                    f"    after:  {after!r}\n  (check the section's make_xml_source/from_xml pair)"]
    if len(back) != len(blocks):
        return [f"{file}: {len(blocks)} blocks went into the IR XML, {len(back)} came back"]
    return []


# -- 3. errors are located, exit status 1 -----------------------------------------------------------------

@dataclass
class CliRun:
    status: int
    err: str


def run_cli(*args: str) -> CliRun:
    """``postproc ARGS`` in this process (stdout discarded)."""
    from ..commands.cli import main  # late: the cli binds postproc.api.translate when imported, which a test may wrap

    err = io.StringIO()
    out = io.TextIOWrapper(io.BytesIO(), encoding="utf-8")  # ``-o -`` writes bytes to ``stdout.buffer``
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        try:
            status = main(list(args))
        except SystemExit as exc:
            status = exc.code if isinstance(exc.code, int) else 2
    return CliRun(status, err.getvalue())


def located_problems(run: CliRun, file: str, what: str, *, must_fail: bool) -> list[str]:
    """Exit 0 (when allowed) or 1 with every error line ``FILE:LINE:COL: error: ...`` naming ``file``."""
    if run.status == 0:
        return [f"{what}: accepted (exit 0), but it is invalid"] if must_fail else []
    if run.status != 1:
        return [f"{what}: exit status {run.status}, expected 1 (2 is for wrong usage)\n{run.err}"]
    problems = []
    lines = run.err.splitlines()
    crashed = [line for line in lines if line.startswith(("Traceback", "postproc: internal error"))]
    if crashed:
        return [f"{what}: postproc crashed (a bug in the dialect's code, not a located error): {crashed[0]}\n{run.err}"]
    errors = [line for line in lines if "error:" in line and ": warning: " not in line]
    if not any(LOCATED.match(line) for line in errors):
        problems.append(f"{what}: exit 1 but no FILE:LINE:COL: error: line on stderr:\n{run.err}")
    for line in errors:
        m = LOCATED.match(line)
        if m is None:
            problems.append(f"{what}: an error without FILE:LINE:COL: {line!r}")
        elif m.group("file") != file or int(m.group("line")) < 1 or int(m.group("col")) < 1:
            problems.append(f"{what}: an error located outside the program ({file}): {line!r}")
    return problems


def invalid_problems(case: DialectUnderTest, path: Path) -> list[str]:
    """A known-bad program: exit 1, located errors, and the lines of ``NAME.err`` in the output."""
    args = ["translate", str(path), "--from", case.dialect, "--to", case.dialect, "-o", "-"]
    if case.setup is not None:
        args += ["--machine", str(case.setup)]
    run = run_cli(*args)
    problems = located_problems(run, str(path), f"{path} (translate --from {case.dialect} --to {case.dialect})",
                                must_fail=True)
    expected = path.with_suffix(".err")
    if expected.is_file():
        for want in filter(None, (w.strip() for w in expected.read_text(encoding="utf-8").splitlines())):
            if want not in run.err:
                problems.append(f"{path}: the error output lacks {want!r} (from {expected.name}); it was:\n{run.err}")
    return problems


def garbage_problems(case: DialectUnderTest, text: str, folder: Path) -> list[str]:
    """A generated malformed program: read and written back (exit 0), or refused with located errors."""
    path = folder / ("garbage" + (case.programs()[0].suffix if case.programs() else ".nc"))
    path.write_text(text, encoding="utf-8", errors="surrogateescape", newline="")
    args = ["translate", str(path), "--from", case.dialect, "--to", case.dialect, "-o", str(folder / "out")]
    if case.setup is not None:
        args += ["--machine", str(case.setup)]
    return located_problems(run_cli(*args), str(path), f"generated program {text!r}", must_fail=False)


# -- 4b. the pipeline declared in Python is the pipeline file ---------------------------------------------

def pipeline_setups(dialect: type[Dialect], machine: MachineSetup | None = None) -> list[tuple[str, MachineSetup]]:
    """Set-ups a dialect's own pipeline is chosen under: one per machine type it reads, and ``machine``
    (the examples' set-up) where given and it names no pipeline file of its own."""
    kinds: tuple[Literal["mill", "lathe"], ...] = ("mill", "lathe")
    found = [(f"a {kind} set-up", MachineSetup(input=InputSettings(machine_type=kind)))
             for kind in kinds if kind in dialect.MACHINE_TYPES]
    if machine is not None and machine.pipeline is None:
        found.append(("the examples' set-up", machine))
    return found


def pipeline_problems(dialect: type[Dialect], machine: MachineSetup | None = None) -> list[str]:
    """``python_pipeline`` (where the dialect declares one) builds the pipeline its file holds
    (``pipeline_file``), under each of ``pipeline_setups``: the same steps, of the same classes, with the
    same settings (the same XML, as ``make_xml_source`` writes it). The file is what a set-up's own
    pipeline starts from, so the two must not drift apart."""
    problems = []
    checked: set[tuple[str, bytes]] = set()
    for what, setup in pipeline_setups(dialect, machine):
        try:
            declared = dialect.python_pipeline(setup)
        except Exception as exc:  # a broken declaration is a finding, not a crash of the suite
            problems.append(f"{dialect.NAME}: python_pipeline fails under {what}: {type(exc).__name__}: {exc}")
            continue
        if declared is None:
            continue
        name = dialect.pipeline_file(setup)
        if name is None:
            problems.append(f"{dialect.NAME}: python_pipeline declares a pipeline under {what}, but there is no "
                            "pipeline file (PIPELINE_FILE) for it to match: ship one beside the module")
            continue
        try:
            from_file = dialect.file_pipeline(setup)
        except PostprocError as err:
            said = f"{dialect.NAME}: its pipeline file {name} does not load: {err}"
            if said not in problems:
                problems.append(said)
            continue
        ours, theirs = to_bytes(declared.make_xml_source()), to_bytes(from_file.make_xml_source())
        if (name, ours) in checked:
            continue  # the same declaration against the same file under another set-up: said once
        checked.add((name, ours))
        kinds = [type(step) for step in declared.steps] == [type(step) for step in from_file.steps]
        if ours != theirs or not kinds:
            problems.append(f"{dialect.NAME}: python_pipeline under {what} is not the pipeline of {name}"
                            + ("" if ours != theirs else " (the same XML, but steps of other classes: "
                               f"{[type(s).__qualname__ for s in declared.steps]})")
                            + f"\n--- python_pipeline:\n{ours.decode()}--- {name}:\n{theirs.decode()}")
    return problems


def hook_problems(dialect: type[Dialect], machine: MachineSetup | None = None) -> list[str]:
    """Hooks of a family base that run only for what a subclass declares (``HOOK_DECLARATIONS`` on the base:
    hook -> declarations): a step of the dialect's pipeline that overrides such a hook and leaves every one of
    its declarations empty has a hook that is never called, a reading that silently does not happen."""
    problems: list[str] = []
    seen: set[type] = set()
    for _, setup in pipeline_setups(dialect, machine):
        try:
            steps = dialect.file_pipeline(setup).steps
        except PostprocError:
            continue  # said by pipeline_problems
        for step in steps:
            kind = type(step)
            if kind in seen:
                continue
            seen.add(kind)
            bases = [cls for cls in kind.__mro__ if "HOOK_DECLARATIONS" in vars(cls)]
            if not bases:
                continue
            family = bases[-1]
            below = kind.__mro__[:kind.__mro__.index(family)]
            for hook, names in family.HOOK_DECLARATIONS.items():  # type: ignore[attr-defined]
                if any(hook in vars(cls) for cls in below) and not any(getattr(kind, n) for n in names):
                    problems.append(f"{dialect.NAME}: {kind.__qualname__} overrides {hook} but declares none of "
                                    f"{', '.join(names)}: {family.__qualname__} calls it only for what they name")
    return problems


# -- 5. translations to every other installed dialect --------------------------------------------------

def targets(case: DialectUnderTest) -> list[type[Dialect]]:
    """Every other installed dialect that reads and writes the machine type the examples are read as
    (a lathe's or a mill's)."""
    me = case.cls()
    machine = "lathe" if me.reads_lathe(case.machine()) else "mill"
    return [d for name, d in sorted(default_registry().dialects.items())
            if name != me.NAME and name not in case.skip_targets and d.READER is not None
            and d.WRITER is not None and machine in d.MACHINE_TYPES]


def cross_problems(case: DialectUnderTest, path: Path, target: type[Dialect], expand: bool) -> list[str]:
    """Translate ``path`` to ``target`` (cycles kept where it runs them, or all expanded): the result
    verifies at zero deviation, or the translation is refused with located errors only."""
    setup = case.machine()
    if expand:
        setup.cycles = dataclasses.replace(setup.cycles, expand="all")
    how = f"{case.dialect} -> {target.NAME}" + (" (cycles expanded)" if expand else "")
    text = read_text(path)
    out = io.StringIO()
    try:
        api.translate(io.StringIO(text), out, file=str(path), source=case.dialect, target=target.NAME, setup=setup,
                      diagnostics=quiet())
    except ErrorList as errs:
        return [f"{path}: {how}: a refusal without a location in the program: {e}" for e in errs.errors
                if e.location is None or e.location.file != str(path) or e.location.line < 1]
    try:
        report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in=str(path),
                              file_out=f"{path.stem}.{target.NAME}", source=case.dialect, target=target.NAME,
                              setup=setup, tolerance=0.0)
    except ErrorList as errs:
        return [f"{path}: {how}: translated, but the result cannot be simulated:\n"
                + "\n".join(f"  {e}" for e in errs.errors)]
    if not report.ok:
        return [f"{path}: {how}: translated, but it does not move the tool as the source does: {report.summary()}"]
    return []


# -- 6. generated programs --------------------------------------------------------------------------

def generated_problems(case: DialectUnderTest, program: NeutralProgram) -> list[str]:
    """A neutral program written in the dialect: written without errors, read back to the same text,
    its IR through XML unchanged, and its toolpath the toolpath the IR means (zero deviation)."""
    dialect, setup = case.cls(), case.machine()
    written = write_neutral(program.blocks(), dialect, setup)
    if written.crash is not None:
        return [f"the {dialect.NAME} writer crashed: {written.crash}"]
    if written.errors:
        return [f"the {dialect.NAME} writer refuses a program its capability table allows:\n"
                + "\n".join(f"  {e}" for e in written.errors)]
    text = written.text
    if dialect.READER is None:
        return []
    out = io.StringIO()
    try:
        api.translate(io.StringIO(text), out, file="generated.nc", source=dialect.NAME, target=dialect.NAME,
                      setup=setup, diagnostics=quiet())
    except ErrorList as errs:
        return [f"the {dialect.NAME} reader refuses what its writer wrote:\n"
                + "\n".join(f"  {e}" for e in errs.errors) + f"\n--- written:\n{text}"]
    if out.getvalue() != text:
        return [f"read back and written again, the {dialect.NAME} program changed at "
                f"{_first_difference(text, out.getvalue())}\n--- written:\n{text}"]
    blocks = api.read_program(io.StringIO(text), file="generated.nc", dialect=dialect.NAME, setup=setup)
    problems = blocks_xml_problems(blocks, dialect.NAME, "generated.nc")
    if problems:
        return problems
    meant = simulate_neutral(program.blocks(), dialect, setup)
    try:
        got = list(toolpath_events(io.StringIO(text), file="generated.nc", dialect=dialect, setup=setup))
    except ErrorList as errs:
        return [f"the {dialect.NAME} output cannot be simulated:\n" + "\n".join(f"  {e}" for e in errs.errors)]
    start = start_position(setup)
    report = compare(meant, got, start_in=start, start_out=start, tolerance=1e-9)
    if not report.ok:
        return [f"the {dialect.NAME} text does not move the tool as the IR it was written from "
                f"(IN: the IR's block, OUT: the text's line): {report.summary()}\n--- written:\n{text}"]
    return []
