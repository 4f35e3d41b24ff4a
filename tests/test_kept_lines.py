"""The compact store of a program's streamed prefix (``postproc.syntaxes.kept_lines``) holds what a
``deque(maxlen=...)`` of the same lines holds: the last lines appended, oldest first, whatever their kind."""

from __future__ import annotations

from collections import deque

from hypothesis import given, strategies as st

from postproc.syntaxes.kept_lines import CHUNK, Kept, KeptLines

_TEXTS = st.text(alphabet="GX01.; \r\n(é", max_size=6)
_ITEMS: st.SearchStrategy[Kept] = st.one_of(_TEXTS, st.tuples(_TEXTS, st.sampled_from(["\r\n", "\r", ""])),
                                            st.none())


@given(st.integers(0, 3 * CHUNK), st.lists(st.one_of(_TEXTS, _ITEMS), max_size=5 * CHUNK))
def test_holds_what_a_bounded_deque_holds(maxlen: int, items: list[Kept]) -> None:
    kept, reference = KeptLines(maxlen), deque(maxlen=maxlen)
    for item in items:
        kept.append(item)
        reference.append(item)
    assert len(kept) == len(reference) and bool(kept) == bool(reference)
    assert list(kept) == list(reference)
    assert list(reversed(kept)) == list(reversed(reference))


def test_plain_lines_are_joined_in_chunks() -> None:
    kept = KeptLines(10 * CHUNK)
    for i in range(3 * CHUNK + 5):
        kept.append(f"N{i} X{i}.")
    assert [type(chunk) for chunk in kept.chunks] == [str, str, str] and len(kept.open) == 5
    assert list(kept)[CHUNK] == f"N{CHUNK} X{CHUNK}."


def test_drops_across_chunks_as_a_deque_does() -> None:
    items: list[Kept] = [None if i % 97 == 0 else (f"N{i}", "\r\n") if i % 300 == 7 else f"N{i}"
                         for i in range(4 * CHUNK + 11)]
    for maxlen in (0, 1, CHUNK - 1, CHUNK, CHUNK + 3, 2 * CHUNK + 1, 5 * CHUNK):
        kept, reference = KeptLines(maxlen), deque(maxlen=maxlen)
        for n, item in enumerate(items, 1):
            kept.append(item)
            reference.append(item)
            if n % 50 == 0 or n == len(items):
                assert list(kept) == list(reference) and len(kept) == len(reference), (maxlen, n)


def test_a_chunk_with_one_line_break_inside_a_line_is_kept_as_lines() -> None:
    for at in (0, CHUNK // 2, CHUNK - 1):
        items: list[Kept] = [f"N{i}" if i != at else "N1 \\\nX2." for i in range(CHUNK + 1)]
        kept = KeptLines(4 * CHUNK)
        for item in items:
            kept.append(item)
        assert type(kept.chunks[0]) is list and list(kept) == items, at
