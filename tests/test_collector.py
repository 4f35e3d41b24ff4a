"""The one pause of the cyclic collector (``postproc.collector.gc_paused``): off inside, given back as it was,
and what was made frozen only when asked."""

from __future__ import annotations

import gc
from typing import Iterator

import pytest

from postproc.collector import gc_paused


@pytest.fixture()
def collector() -> Iterator[None]:
    """The collector on and nothing frozen before each test, and as it was after it."""
    enabled = gc.isenabled()
    gc.enable()
    gc.unfreeze()
    try:
        yield
    finally:
        gc.unfreeze()
        (gc.enable if enabled else gc.disable)()


def test_the_collector_is_off_inside_and_on_again_after(collector: None) -> None:
    with gc_paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    assert gc.get_freeze_count() == 0


def test_a_pause_inside_a_pause_leaves_it_off(collector: None) -> None:
    with gc_paused():
        with gc_paused():
            pass
        assert not gc.isenabled()
    assert gc.isenabled()


def test_a_collector_that_was_off_stays_off(collector: None) -> None:
    gc.disable()
    with gc_paused():
        pass
    assert not gc.isenabled()


def test_an_error_inside_gives_the_collector_back(collector: None) -> None:
    with pytest.raises(KeyError), gc_paused():
        raise KeyError("x")
    assert gc.isenabled()


def test_freeze_freezes_what_was_made(collector: None) -> None:
    with gc_paused(freeze=True):
        made = [[] for _ in range(10)]
    assert gc.get_freeze_count() >= len(made)
    assert gc.isenabled()
