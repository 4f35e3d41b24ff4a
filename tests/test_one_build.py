"""The ``one_build`` marker (tests/conftest.py): ``make test``'s second pass skips a marked test, saying why,
the first runs it, and a mark without its reason is refused."""

from __future__ import annotations

import pytest

from tests.conftest import ONE_BUILD, pytest_collection_modifyitems


class _Item:
    """What the hook reads of a collected test."""

    def __init__(self, marker: pytest.Mark | None) -> None:
        self.nodeid = "tests/test_x.py::test_x"
        self.marker = marker
        self.added: list[pytest.MarkDecorator] = []

    def get_closest_marker(self, name: str) -> pytest.Mark | None:
        return self.marker if name == ONE_BUILD else None

    def add_marker(self, marker: pytest.MarkDecorator) -> None:
        self.added.append(marker)


def _collect(monkeypatch: pytest.MonkeyPatch, second: str, *items: _Item) -> None:
    monkeypatch.setenv("POSTPROC_SECOND_BUILD", second)
    pytest_collection_modifyitems(None, list(items))  # type: ignore[arg-type]


def test_the_second_pass_skips_a_marked_test_with_its_reason(monkeypatch: pytest.MonkeyPatch) -> None:
    marked, plain = _Item(pytest.mark.one_build(reason="a scan").mark), _Item(None)
    _collect(monkeypatch, "1", marked, plain)
    assert [m.mark.name for m in marked.added] == ["skip"] and "a scan" in marked.added[0].mark.kwargs["reason"]
    assert plain.added == []


@pytest.mark.parametrize("second", ["", "0"])
def test_the_first_pass_runs_it(monkeypatch: pytest.MonkeyPatch, second: str) -> None:
    marked = _Item(pytest.mark.one_build(reason="a scan").mark)
    _collect(monkeypatch, second, marked)
    assert marked.added == []


def test_a_mark_without_a_reason_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(pytest.UsageError, match="needs a reason"):
        _collect(monkeypatch, "", _Item(pytest.mark.one_build().mark))
