"""What a start computes on path strings rather than ``pathlib`` objects (``pathlib`` imports ``urllib.parse`` and
``ipaddress``, modules a start has no other use for), held to ``pathlib``: the ``program`` name of the templates
(``postproc.lowering.sequences.path_stem``) and the entry-point cache's file (``postproc.entry_points``)."""

from __future__ import annotations

from pathlib import Path, PurePath

from hypothesis import given, settings
from hypothesis import strategies as st

from postproc import entry_points
from postproc.lowering.sequences import path_stem

PIECES = st.lists(st.sampled_from(["", ".", "..", "/", "//", "a", "b.nc", ".nc", "x.", "o1001.tar.gz", "...", "a b",
                                   "é.ngc", "-", "<stdin>"]), max_size=6)


@settings(max_examples=500, deadline=None)
@given(PIECES)
def test_the_program_name_is_pathlibs_stem(pieces: list[str]) -> None:
    path = "".join(pieces)
    assert path_stem(path) == PurePath(path).stem


@given(st.text(alphabet="ab./-", max_size=12))
def test_the_program_name_is_pathlibs_stem_on_any_text(path: str) -> None:
    assert path_stem(path) == PurePath(path).stem


def test_the_entry_point_cache_is_written_and_read_on_path_strings(tmp_path: Path) -> None:
    path = str(tmp_path / "deeper" / "cache.txt")
    entry_points._write(path, "one\ntwo\n")
    assert entry_points._read(path) == "one\ntwo\n" == Path(path).read_text(encoding="utf-8")
    assert [p.name for p in (tmp_path / "deeper").iterdir()] == ["cache.txt"]  # (no temporary file left)
    assert entry_points._read(str(tmp_path / "missing.txt")) is None
