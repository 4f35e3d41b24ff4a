"""verify: run a program and its translation through their own dialects to toolpaths and compare them.

Both toolpaths stream in lockstep, so memory does not grow with program length. Each is normalised
first: zero-length moves are dropped (the simulator already does), consecutive straight moves of the
same kind and feed that continue one line are merged (points within half the tolerance of the line
count as on it), and so are consecutive arcs on one circle. Then moves are compared pairwise: end
points give the deviation, for arcs the largest distance between the paths each side's controller cuts
(``postproc.geometry.arc_paths``, docs/verify.md "Arcs"), never their centres'; a different kind of move, feed, plane, or a
different machine event (dwell, spindle, orientation, tool, coolant, stop, end) is a structural
mismatch, reported at its first place; after it the two paths no longer line up and comparing stops.
"""


from __future__ import annotations

import copy
import dataclasses
import io
import math
from typing import Any, Callable, Iterable, Iterator, Mapping

from ..errors import Diagnostics, ErrorList, PostprocError, UsageError
from ..plugins import Registry, default_registry
from ..dialect import Dialect
from ..setup.foreign_codes import foreign_table
from ..setup.machine_setup import MachineSetup
from ..drawing.overlay import Overlay
from ..transforms.carry import mirrors_xy
from ..transforms.events import moved_events
from ..transforms.spec import ProgramTransform
from .normal_move import Move
from .move_record import MoveRecord, as_events
from .compare import (Report, _controlled, compare, compare_after_end, compare_settings, describe,
                      normalise)
from ..collector import gc_paused
from .events import Event
from .lost_tool_data import lost_tool_data
from .toolpath import start_position, toolpath_events, toolpath_stream

__all__ = ["Move", "Report", "compare", "compare_after_end", "compare_settings", "describe", "normalise",
           "verify_files", "verify_lines"]


# -- files -----------------------------------------------------------------------------------------

def verify_lines(lines_in: Iterable[str], lines_out: Iterable[str], *, file_in: str, file_out: str,
                 source: str, target: str, setup: MachineSetup | None = None,
                 target_setup: MachineSetup | None = None, tolerance: float = 0.001,
                 registry: Registry | None = None, allow_ignored: bool = False,
                 overlay: Overlay | None = None, arguments: Mapping[str, float] | None = None,
                 transform: ProgramTransform | None = None, chord_tolerance: float | None = None) -> Report:
    """Compare two programs given as lines. Raises ``ErrorList`` with both programs' errors, if any.
    ``allow_ignored``: settings that move the tool may differ (they are listed either way).
    ``overlay``: collects both toolpaths as they stream past, for a picture of the two. ``arguments``: both
    are macro files run with these call arguments (``toolpath_events``); a program whose dialect has no
    such arguments (a flattened translation) is run without them. ``transform``: OUT was translated with it
    (``translate --transform``), so IN's toolpath is moved by it before the comparison (a units conversion
    needs nothing: both toolpaths are in mm). ``chord_tolerance``: OUT is a translation with
    ``--arcs lines:TOL`` (``compare``)."""
    if not math.isfinite(tolerance) or tolerance < 0:
        raise UsageError(f"the tolerance must be a finite number of at least 0, got {tolerance:g}")
    setup = setup or MachineSetup()
    if target_setup is None:
        target_setup = _same_machine(setup, source, registry)
    dialects = registry or default_registry()
    diag_in, diag_out = Diagnostics(), Diagnostics()
    after_in: list[int] = []
    after_out: list[int] = []
    settings_in: list[tuple[int, str, str]] = []
    settings_out: list[tuple[int, str, str]] = []
    data_in: list[tuple[int, str, str, float]] = []
    data_out: list[tuple[int, str, str, float]] = []
    compensate = _both_compensate(source, target, registry, setup, target_setup)
    out_arguments = arguments if arguments and dialects.dialect(target).MACRO_ARGUMENTS else None
    kept: Callable[[str], bool] | None = None
    mirrored = transform is not None and mirrors_xy(transform.map)  # OUT's sides are the other ones
    if not compensate and dialects.dialect(source).cutter_rules(setup) is not None:
        if isinstance(lines_out, io.IOBase) and lines_out.seekable():  # a file: read again, not held
            mark = lines_out.tell()
            compensate = not _compensates(lines_out, file_out, target, target_setup, dialects)
            lines_out.seek(mark)
            if not compensate:
                lines_in = list(lines_in)  # read twice too
                kept = _kept_native(lines_out, file_out, target, target_setup, dialects, out_arguments, mirrored,
                                    _starts(lines_in, file_in, source, setup, dialects, arguments))
                lines_out.seek(mark)
        else:
            lines_out = list(lines_out)  # read twice: the output is looked through first
            compensate = not _compensates(lines_out, file_out, target, target_setup, dialects)
            if not compensate:
                lines_in = list(lines_in)  # read twice too
                kept = _kept_native(lines_out, file_out, target, target_setup, dialects, out_arguments, mirrored,
                                    _starts(lines_in, file_in, source, setup, dialects, arguments))
        compensate = compensate or kept is not None
    with gc_paused():  # both simulations stream as the comparison pulls them (``toolpath_stream``)
        events_in: Iterator[Event | MoveRecord] = toolpath_stream(
            lines_in, file=file_in, dialect=source, setup=setup, registry=registry, diagnostics=diag_in,
            live_after_end=after_in, unsimulated=settings_in, compensate=compensate, arguments=arguments,
            kept_native=kept, mark_held=transform is not None, tool_data=data_in)
        events_out: Iterator[Event | MoveRecord] = toolpath_stream(
            lines_out, file=file_out, dialect=target, setup=target_setup, registry=registry, diagnostics=diag_out,
            live_after_end=after_out, unsimulated=settings_out, compensate=compensate, arguments=out_arguments,
            assumed_start=True, tool_data=data_out)  # OUT's reads of an axis the source never placed (``toolpath_stream``)
        start_in = start_position(setup)
        if transform is not None:
            events_in = moved_events(as_events(events_in), transform, start_in)  # (the start is where the machine stands)
        if overlay is not None:
            reading = dialects.dialect(source)
            overlay.begin(start_position(setup), start_position(target_setup), reading.reads_lathe(setup))
            # the picture shows the paths compared (the controlled points), where the deviation is circled
            events_in = overlay.source_events(_controlled(as_events(events_in)))
            events_out = overlay.target_events(_controlled(as_events(events_out)))
        report = compare(events_in, events_out, start_in=start_in, start_out=start_position(target_setup),
                         tolerance=tolerance, chord_tolerance=chord_tolerance,
                         mapped=_mapped_codes(dialects.dialect(source), dialects.dialect(target), target_setup))
    report.allow_ignored = allow_ignored
    compare_after_end(report, after_in, after_out)
    fixed = dialects.dialect(target).PATH_CONTROL
    asked = [value for _, kind, value in settings_in if kind == "path control"]
    if fixed is not None and (fixed in _EXACT_MODES or asked and all(value == fixed.replace("_", " ")
                                                                      for value in asked)):
        # (a target whose one mode reaches every point answers any source: its power-on mode, recorded at the
        # output's first move, is no difference either)
        settings_in = [s for s in settings_in if s[1] != "path control"]
        settings_out = [s for s in settings_out if s[1] != "path control"]
        if asked:
            report.ignored.append(_one_path_mode(target, fixed))
    settings_in, settings_out = _exact_path_as_stop(report, settings_in, settings_out)
    if (dialects.dialect(target).PATH_CONTROL_AT_START in _EXACT_MODES
            and dialects.dialect(source).PATH_CONTROL_AT_START not in _EXACT_MODES):
        settings_in, settings_out = _stricter_start(report, target, settings_in, settings_out)
    if transform is not None and mirrors_xy(transform.map):
        settings_in = [(line, kind, _other_side(value) if kind == "cutter compensation" else value)
                       for line, kind, value in settings_in]
    compare_settings(report, settings_in, settings_out)
    if any(kind == "cutter compensation" for _, kind, _ in settings_in + settings_out):
        _why_a_setting(report, ((dialects.dialect(source), setup), (dialects.dialect(target), target_setup)))
    if setup.machine.tool_lengths == "touched_off":
        report.ignored.append("tool lengths: zero on both sides, the set-up's tools are touched off at their "
                              "change (<Machine toolLengths=\"touched_off\">)")
    if report.mismatch is not None or report.max_deviation > tolerance or report.left_out_moves:
        # what explains it, where the source's tool data in force is not the translation's
        report.lost = lost_tool_data(data_in, data_out, file_in=file_in, file_out=file_out,
                                     address_in=dialects.dialect(source).LENGTH_REGISTER_ADDRESS,
                                     address_out=dialects.dialect(target).LENGTH_REGISTER_ADDRESS)
    errors = diag_in.errors + diag_out.errors
    if errors:
        raise ErrorList(errors)
    return report


_EXACT_MODES = frozenset(("exact_stop", "exact_path"))
"""The path control modes that reach every programmed point (``PathControl``)."""


def _exact_path_as_stop(report: Report, settings_in: list[tuple[int, str, str]],
                        settings_out: list[tuple[int, str, str]]
                        ) -> tuple[list[tuple[int, str, str]], list[tuple[int, str, str]]]:
    """Both sides' settings with the exact path read as the exact stop, where one side has an exact path and the
    two then agree: the two reach the same programmed points, which is what the simulation compares; they
    differ only in whether the machine stops at each block end (grbl's power-on G61 written as Fanuc's G61, an
    exact stop [K]: ``PathControl``). The note says so. Otherwise both are returned as they are."""
    def as_stop(settings: list[tuple[int, str, str]]) -> list[tuple[int, str, str]]:
        return [(line, kind, "exact stop" if kind == "path control" and value == "exact path" else value)
                for line, kind, value in settings]

    paths = [s for s in settings_in + settings_out if s[1] == "path control" and s[2] == "exact path"]
    if not paths:
        return settings_in, settings_out
    new_in, new_out = as_stop(settings_in), as_stop(settings_out)
    if [s[2] for s in new_in if s[1] == "path control"] != [s[2] for s in new_out if s[1] == "path control"]:
        return settings_in, settings_out
    report.ignored.append("path control: the exact path (line " + str(paths[0][0]) + ") compared as the exact stop: "
                          "the same programmed points reached, whether the machine stops at each block end not compared")
    return new_in, new_out


def _one_path_mode(target: str, fixed: str) -> str:
    """Why a target's one path control mode answers the source's: an exact path reaches every programmed
    point, which is all the simulation compares (a blending source only lets the path leave them)."""
    if fixed in _EXACT_MODES:
        return (f"path control: {target} always runs the exact path (every programmed point reached), which "
                "the source's modes ask for or allow")
    return f"path control: {target} always runs in {fixed.replace('_', ' ')} mode, as the source asks"


def _why_a_setting(report: Report, sides: tuple[tuple[type[Dialect], MachineSetup], ...]) -> None:
    """Cutter compensation compared as a setting: say why for each dialect whose rules are not simulated and that
    says why (``Dialect.CUTTER_RULES_LACK``: ISG's and the Fagor 8070's start-up and cancel moves are in their
    manuals' figures only), so the note is no silent gap."""
    named: set[str] = set()
    for dialect, machine in sides:
        if dialect.NAME in named or dialect.cutter_rules(machine) is not None or not dialect.CUTTER_RULES_LACK:
            continue
        named.add(dialect.NAME)
        report.ignored.append(f"cutter compensation under {dialect.NAME}'s rules: compared as a setting, not as a "
                              f"path: {dialect.CUTTER_RULES_LACK}")


def _other_side(value: str) -> str:
    """A cutter compensation setting ('left D1') on the other side of the path: a program moved by a
    transform that mirrors the XY plane cuts on the other side (``translate --transform`` writes it so)."""
    side, _, rest = value.partition(" ")
    swapped = {"left": "right", "right": "left"}.get(side, side)
    return f"{swapped} {rest}".rstrip()


def _both_compensate(source: str, target: str, registry: Registry | None, setup: MachineSetup,
                     target_setup: MachineSetup) -> bool:
    """Cutter radius compensation is simulated on both sides or on neither: a dialect without its rules
    keeps the programmed path, and the setting is compared instead (``compare_settings``). A target
    without compensation at all (grbl) receives the compensated path itself (``postproc.compensation.
    lowering``): the source's is simulated then."""
    from ..plugins import default_registry
    reg = registry or default_registry()
    out = reg.dialect(target)
    return reg.dialect(source).cutter_rules(setup) is not None and (out.cutter_rules(target_setup) is not None
                                                              or not out.CUTTER_COMPENSATION)


def _compensates(lines: Iterable[str], file: str, dialect: str, setup: MachineSetup, registry: Registry) -> bool:
    """Whether a program turns cutter radius compensation on (or cannot be read: the caller's run says
    why). A translation that resolved the source's compensation into its path has none left, so the
    source's compensated path is what it must cut: compared as a path, not as a setting."""
    from ..reading import read_blocks
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    try:
        _, blocks = read_blocks(iter(lines), file, registry.dialect(dialect), setup, diagnostics)
        for block in blocks:
            cc = block.sections.get("CutterCompensation")
            if cc is not None and getattr(cc, "mode", "off") != "off":
                return True
    except PostprocError:
        return True
    return bool(diagnostics.errors)


def _starts(lines: Iterable[str], file: str, dialect: str, setup: MachineSetup, registry: Registry,
            arguments: Mapping[str, float] | None, assumed_start: bool = False) -> list[str] | None:
    """A program's cutter compensation starts ("left D4", ...) in execution order, compensation not simulated;
    None when its run fails (its own run then says why)."""
    settings: list[tuple[int, str, str]] = []
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    for _ in toolpath_events(lines, file=file, dialect=dialect, setup=setup, registry=registry,
                             diagnostics=diagnostics, check=False, unsimulated=settings, compensate=False,
                             arguments=arguments, assumed_start=assumed_start):
        pass
    if diagnostics.errors:
        return None
    return [value for _, kind, value in settings if kind == "cutter compensation" and value != "off"]


def _kept_native(lines: Iterable[str], file: str, dialect: str, setup: MachineSetup, registry: Registry,
                 arguments: Mapping[str, float] | None, mirrored: bool = False,
                 source_starts: list[str] | None = None) -> Callable[[str], bool] | None:
    """Which stretches of the source's cutter compensation the output kept native, for a source whose
    rules are simulated and an output whose are not, which compensates some stretches itself and was given
    others resolved into its path (ISG, where a D would bring another length: ``postproc.isg_family.
    tool_data``). The output's compensation settings in execution order ("left D4", ...) are matched in
    order against the source's: a source stretch the output also turns on is compared as a setting, one it
    does not was resolved, and is compared as the source's compensated path (DESIGN.md: verify compares
    controlled points). None too (all compared as settings) where the output keeps every stretch, or turns on
    one the source does not (``source_starts``, the source's in order). ``mirrored``: OUT was written under a transform that mirrors the plane, its sides are
    the other ones. None when the output's run fails (its own run then says why)."""
    found = _starts(lines, file, dialect, setup, registry, arguments, assumed_start=True)  # (OUT's)
    if found is None or source_starts is None:
        return None
    out_starts = [_other_side(value) if mirrored else value for value in found]
    rest = iter(source_starts)
    if out_starts == source_starts or not all(value in rest for value in out_starts):
        return None  # every stretch kept, or the output's are not the source's: compared as settings
    starts = iter(out_starts)
    pending = [next(starts, None)]

    def kept(value: str) -> bool:
        if value != pending[0]:
            return False
        pending[0] = next(starts, None)
        return True
    return kept


def _mapped_codes(source: type[Dialect], target: type[Dialect], target_setup: MachineSetup) -> dict[str, str]:
    """The source family's machine codes the target set-up's ``<ForeignCodes>`` maps (code -> what it becomes);
    none between dialects of one family, where the codes pass as written."""
    family = source.family()
    if family == target.family():
        return {}
    return {code: mapped.becomes() for (of, code), mapped in foreign_table(target_setup.foreign_codes).items()
            if of == family}


def _same_machine(setup: MachineSetup, source: str, registry: Registry | None) -> MachineSetup:
    """The target runs on the source's machine: a program a lathe-only dialect read (GSK) is a lathe's
    on the target's side too, whatever type the set-up names."""
    from ..plugins import default_registry
    reading = (registry or default_registry()).dialect(source)
    if setup.input.machine_type == "lathe" or not reading.reads_lathe(setup):
        return setup
    lathe = copy.copy(setup)
    lathe.input = dataclasses.replace(setup.input, machine_type="lathe")
    return lathe


def verify_files(in_path: str, out_path: str, *, source: str, target: str,
                 setup: MachineSetup | None = None, target_setup: MachineSetup | None = None,
                 tolerance: float = 0.001, registry: Registry | None = None,
                 allow_ignored: bool = False) -> Report:
    """Compare a program file with its translation (the ``postproc verify`` command)."""
    with _open(in_path) as a, _open(out_path) as b:
        return verify_lines(a, b, file_in=in_path, file_out=out_path, source=source, target=target,
                            setup=setup, target_setup=target_setup, tolerance=tolerance, registry=registry,
                            allow_ignored=allow_ignored)


def _open(path: str) -> Any:
    try:
        return open(path, "r", encoding="utf-8", errors="surrogateescape", newline="")
    except OSError as exc:
        raise UsageError(f"cannot read {path}: {exc.strerror}") from None


def _stricter_start(report: Report, target: str, settings_in: list[tuple[int, str, str]],
                    settings_out: list[tuple[int, str, str]]
                    ) -> tuple[list[tuple[int, str, str]], list[tuple[int, str, str]]]:
    """Both sides' settings without what precedes the output's first blending mode, where the output's
    controller starts in exact stop and the source's blends (``Dialect.PATH_CONTROL_AT_START``: a Fanuc program
    for a SINUMERIK, which powers on in G60) and the two agree from the first blending mode each sets on (or
    the output never blends). Until then the output stops exactly at every programmed point, which is what
    the simulation compares; the source's blending only lets the path leave them (grbl's one mode is accepted
    so: ``_one_path_mode``). A one-shot exact stop (its exact stop, then the mode before, at one line) is no
    blending mode set. The note says so. Otherwise both are returned as they are, and compared."""
    ins = [s for s in settings_in if s[1] == "path control"]
    outs = [s for s in settings_out if s[1] == "path control"]
    if not outs or outs[0][2] not in ("exact stop", "exact path"):
        return settings_in, settings_out
    i, o = _first_blending(ins), _first_blending(outs)
    if o < len(outs) and (i == len(ins) or [s[2] for s in ins[i:]] != [s[2] for s in outs[o:]]):
        return settings_in, settings_out
    report.ignored.append(f"path control: the {target} controller starts in exact stop (line {outs[0][0]}) where the "
                          "source's blends, until the program sets a blending mode: every programmed point is reached")
    gone_in, gone_out = set(ins[:i]), set(outs[:o])
    return [s for s in settings_in if s not in gone_in], [s for s in settings_out if s not in gone_out]


def _first_blending(changes: list[tuple[int, str, str]]) -> int:
    """The index of the first change to a blending mode that is not the end of a one-shot exact stop (an
    exact stop and the mode before at one line); ``len(changes)`` where there is none."""
    for k, (line, _, value) in enumerate(changes):
        if value not in ("exact stop", "exact path") and not (k > 0 and changes[k - 1][0] == line
                                                               and changes[k - 1][2] == "exact stop"):
            return k
    return len(changes)
