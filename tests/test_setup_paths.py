"""The set-up loader's paths as text (``postproc.xmlio.path_text``, ``postproc.setup.paths``), held to ``pathlib``, whose
objects they replace on every ``--machine`` run: the same spelling of a file in every message and location, the same
folder, joined path and name, the same answer to "is it a file"."""

from __future__ import annotations

import os
from pathlib import Path, PurePath

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.setup import paths
from postproc.xmlio import path_text

PIECES = st.lists(st.sampled_from(["", ".", "..", "/", "//", "///", "a", "b.xml", ".xml", "x.", "...", "a b", "é.xml",
                                   "-", "<stdin>", "./", "../"]), max_size=7)
PATHS = st.builds("".join, PIECES) | st.text(alphabet="ab./", max_size=12)


@settings(max_examples=1000, deadline=None)
@given(PATHS)
def test_a_path_is_spelt_parted_and_named_as_pathlib_does(path: str) -> None:
    pure = PurePath(path)
    assert path_text(path) == str(pure)
    assert path_text(pure) == str(pure)  # (a path object given: its own text)
    assert paths.parent_text(path) == str(pure.parent)
    assert paths.name_text(path) == pure.name


@settings(max_examples=1000, deadline=None)
@given(PATHS, PATHS)
def test_a_path_is_joined_as_pathlib_does(folder: str, name: str) -> None:
    assert paths.join_text(folder, name) == str(PurePath(folder) / name)


@pytest.mark.skipif(os.name != "posix", reason="a FIFO")
def test_is_file_is_pathlibs(tmp_path: Path) -> None:
    (tmp_path / "f.xml").write_text("<MachineSetup/>")
    (tmp_path / "d").mkdir()
    os.mkfifo(tmp_path / "fifo")
    (tmp_path / "link").symlink_to(tmp_path / "f.xml")
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    (tmp_path / "dangling").symlink_to(tmp_path / "missing")
    for name in ("f.xml", "f.xml/", "f.xml/x", "d", "d/", "fifo", "link", "loop", "dangling", "missing", "./f.xml",
                 "d/../f.xml", "f.xml\0"):
        path = str(tmp_path) + "/" + name
        assert paths.is_file(path) == Path(path).is_file(), name


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="a folder that may not be searched (not as root)")
def test_is_file_raises_where_pathlib_does(tmp_path: Path) -> None:
    shut = tmp_path / "shut"
    shut.mkdir()
    (shut / "f.xml").write_text("<MachineSetup/>")
    shut.chmod(0)
    try:
        with pytest.raises(PermissionError):
            Path(shut / "f.xml").is_file()
        with pytest.raises(PermissionError):
            paths.is_file(str(shut / "f.xml"))
    finally:
        shut.chmod(0o700)
