"""The batch's account of itself: messages as files finish, the JSON lines report, the summary.

The report has exactly one line per file, written (and flushed) as each file's result arrives, in the
order they finish: an interrupted batch leaves the lines of the files it finished.
"""

from __future__ import annotations

import json
import time
from dataclasses import dataclass, field
from typing import TextIO

from ...errors import UsageError
from .work import EXIT_OK, FileResult

SHOWN_FAILURES = 10
"""The summary names at most this many failed files (the report has them all)."""

STATUS_LABELS = (("ok", "ok"), ("error", "errors"), ("verify", "verify failed"),
                 ("usage", "not read or not written"), ("internal", "internal errors"))


class Report:
    """The ``--report`` file: one JSON object per file."""

    def __init__(self, path: str) -> None:
        self.path = path
        try:
            self.stream: TextIO = open(path, "w", encoding="utf-8")
        except OSError as exc:
            raise UsageError(f"cannot write {path}: {exc.strerror}") from None

    def add(self, result: FileResult) -> None:
        # ASCII: a file name or message with bytes that are not UTF-8 (kept as surrogates) stays valid JSON
        self.stream.write(json.dumps(result.as_json()) + "\n")
        self.stream.flush()

    def close(self) -> None:
        self.stream.close()


@dataclass
class Tally:
    """Counts for the summary, kept as results arrive."""

    files: int
    """How many files the batch has."""
    started: float = field(default_factory=time.monotonic)
    done: int = 0
    blocks: int = 0
    by_status: dict[str, int] = field(default_factory=dict)
    warned: int = 0
    """Files translated ok that had warnings (the summary's "ok N (M with warnings)": M of those N)."""
    verified: int = 0
    worst_deviation: tuple[float, str] | None = None
    failures: list[FileResult] = field(default_factory=list)
    exit: int = EXIT_OK
    """The worst file's exit status."""

    def add(self, result: FileResult) -> None:
        self.done += 1
        self.blocks += result.blocks
        self.by_status[result.status] = self.by_status.get(result.status, 0) + 1
        self.warned += result.status == "ok" and bool(result.warnings)  # of the files counted ok
        if result.max_deviation is not None:
            self.verified += 1
            if self.worst_deviation is None or result.max_deviation > self.worst_deviation[0]:
                self.worst_deviation = (result.max_deviation, result.file)
        if result.exit != EXIT_OK:
            self.failures.append(result)
        self.exit = max(self.exit, result.exit)

    def summary(self, *, source: str, target: str, where: str, report: str | None) -> str:
        """A screenful at most: counts, rates, the largest deviation, the first failures."""
        seconds = max(time.monotonic() - self.started, 1e-9)
        head = (f"postproc: {self.done} of {self.files} files from {source} to {target} in {seconds:.1f} s "
                f"({self.done / seconds:,.1f} files/s, {self.blocks / seconds:,.0f} blocks/s; {where})")
        lines = [head]
        for status, label in STATUS_LABELS:
            count = self.by_status.get(status, 0)
            if count or status == "ok":
                extra = f" ({self.warned} with warnings)" if status == "ok" and self.warned else ""
                lines.append(f"  {label:<24}{count:>8}{extra}")
        if self.done < self.files:
            lines.append(f"  {'not done (interrupted)':<24}{self.files - self.done:>8}")
        if self.worst_deviation is not None:
            deviation, file = self.worst_deviation
            lines.append(f"  {'verified':<24}{self.verified:>8}, largest deviation {deviation:.4f} mm ({file})")
        if self.failures:
            shown = self.failures[:SHOWN_FAILURES]
            more = f"; all in {report}" if report else "; --report FILE lists every file"
            lines.append(f"failed ({len(shown)} of {len(self.failures)} shown{more}):")
            lines.extend(f"  {_first_line(r)}" for r in shown)
        return "\n".join(lines)


def _first_line(result: FileResult) -> str:
    """The file's first error, named by its location (or by the file, for one that has none)."""
    first = result.errors[0] if result.errors else result.status
    return first if first.startswith(f"{result.file}:") else f"{result.file}: {first.removeprefix('postproc: ')}"


def messages(result: FileResult) -> list[str]:
    """What a file's result prints on standard error: its errors and warnings, as the single-file
    command prints them."""
    return result.errors + result.warnings
