"""The entry-point cache (``postproc.entry_points``) answers what ``importlib.metadata`` answers, and stops
answering from the cache as soon as the installation changes: a distribution added or removed, its
``entry_points.txt`` edited, a folder put on ``sys.path``."""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import pytest

from postproc import entry_points as ep
from postproc.plugins import PROJECT, make_plugin_manager

GROUP = "postproc_cache_probe"
"""A group only these tests' fake distributions declare (the real ``postproc`` group is compared too)."""


def _age(path: Path, seconds: float = 60.0) -> None:
    """Set ``path`` and everything under it ``seconds`` into the past: times that differ from a later
    change's (other folders on ``sys.path`` may change while the suite runs: the tests that need a cache
    written say ``settle=-1``)."""
    past = time.time() - seconds
    for p in [path, *path.rglob("*")]:
        os.utime(p, (past, past))


def _distribution(site: Path, name: str, entries: str) -> Path:
    info = site / f"{name}-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(f"[{GROUP}]\n{entries}\n")
    return info


@pytest.fixture
def site(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "site"
    folder.mkdir()
    monkeypatch.syspath_prepend(str(folder))
    monkeypatch.delenv("POSTPROC_NO_ENTRY_POINT_CACHE", raising=False)
    return folder


def test_the_real_group_is_what_importlib_metadata_finds(tmp_path: Path) -> None:
    first = ep.entry_points(PROJECT, cache_dir=tmp_path)
    assert first == ep.discover(PROJECT)
    assert ("fanuc", "dialects.fanuc") in first
    assert ep.entry_points(PROJECT, cache_dir=tmp_path) == first


def test_a_cached_answer_is_used_while_nothing_changes(site: Path, tmp_path: Path) -> None:
    _distribution(site, "probe_a", "a = json")
    _age(site)
    cache = tmp_path / "cache"
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]
    (written,) = cache.iterdir()
    # the cache is what answers now: a planted answer under the same key comes back
    written.write_text(written.read_text().replace("a=json", "a=planted"))
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "planted")]


def test_two_ways_of_starting_keep_their_own_answers(site: Path, tmp_path: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    """The ``postproc`` script and ``python -m postproc`` (another first entry on ``sys.path``) taking
    turns: each finds its own cached answer, neither discovers again because of the other."""
    _distribution(site, "probe_a", "a = json")
    _age(site)
    cache = tmp_path / "cache"
    other = tmp_path / "bin"
    other.mkdir()
    _age(other)
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]
    monkeypatch.syspath_prepend(str(other))
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]
    assert len(list(cache.iterdir())) == 2
    for written in cache.iterdir():
        written.write_text(written.read_text().replace("a=json", "a=planted"))
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "planted")]
    monkeypatch.undo()
    monkeypatch.syspath_prepend(str(site))
    monkeypatch.delenv("POSTPROC_NO_ENTRY_POINT_CACHE", raising=False)
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "planted")]


def test_a_new_distribution_is_seen(site: Path, tmp_path: Path) -> None:
    _distribution(site, "probe_a", "a = json")
    _age(site)
    cache = tmp_path / "cache"
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]
    _distribution(site, "probe_b", "b = os.path:join")
    _age(site)
    assert sorted(ep.entry_points(GROUP, cache_dir=cache, settle=-1)) == [("a", "json"), ("b", "os.path:join")]


def test_a_removed_distribution_is_gone(site: Path, tmp_path: Path) -> None:
    _distribution(site, "probe_a", "a = json")
    info = _distribution(site, "probe_b", "b = os")
    _age(site)
    cache = tmp_path / "cache"
    assert len(ep.entry_points(GROUP, cache_dir=cache, settle=-1)) == 2
    for f in info.iterdir():
        f.unlink()
    info.rmdir()
    _age(site)
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]


def test_an_edited_entry_points_file_is_seen(site: Path, tmp_path: Path) -> None:
    info = _distribution(site, "probe_a", "a = json")
    _age(site)
    cache = tmp_path / "cache"
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]
    (info / "entry_points.txt").write_text(f"[{GROUP}]\na = os\n")
    _age(site, 30.0)  # a different (still settled) time, as an edit leaves
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "os")]


def test_an_unsettled_installation_is_not_cached(site: Path, tmp_path: Path) -> None:
    _distribution(site, "probe_a", "a = json")  # written just now: a coarse clock could not tell
    cache = tmp_path / "cache"
    assert ep.entry_points(GROUP, cache_dir=cache) == [("a", "json")]
    assert not cache.exists()


def test_a_broken_cache_file_is_ignored(site: Path, tmp_path: Path) -> None:
    _distribution(site, "probe_a", "a = json")
    _age(site)
    cache = tmp_path / "cache"
    ep.entry_points(GROUP, cache_dir=cache, settle=-1)
    (written,) = cache.iterdir()
    written.write_text("{not a cache")
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]


def test_an_unwritable_cache_folder_only_costs_the_discovery(site: Path, tmp_path: Path) -> None:
    _distribution(site, "probe_a", "a = json")
    _age(site)
    blocked = tmp_path / "file"
    blocked.write_text("")
    assert ep.entry_points(GROUP, cache_dir=blocked / "cache", settle=-1) == [("a", "json")]


def test_another_distribution_finder_turns_the_cache_off(site: Path, tmp_path: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    class Finder:
        @staticmethod
        def find_distributions(*args: object, **kwargs: object) -> list[object]:
            return []

    _distribution(site, "probe_a", "a = json")
    _age(site)
    monkeypatch.setattr(sys, "meta_path", [*sys.meta_path, Finder()])
    cache = tmp_path / "cache"
    assert ep.entry_points(GROUP, cache_dir=cache, settle=-1) == [("a", "json")]  # would be written
    assert not cache.exists()


def test_load_resolves_like_an_entry_point() -> None:
    import os.path as osp
    assert ep.load("os.path") is osp
    assert ep.load("os.path:join") is osp.join
    assert ep.load(" os : path.join [extra]") is osp.join


def test_the_plugin_manager_loads_what_pluggy_would() -> None:
    ours = make_plugin_manager()
    theirs = make_plugin_manager(entry_points=False)
    theirs.load_setuptools_entrypoints(PROJECT)
    assert sorted(name for name, _ in ours.list_name_plugin()) == sorted(name for name, _ in theirs.list_name_plugin())
