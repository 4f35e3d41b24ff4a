"""``postproc.commands.export.write_chunks``: the toolpath's JSON lines reach a binary stream, its raw file, a text
stream alike, whole where a file takes a chunk in several writes, after what the stream held before."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

from postproc.commands.export import write_chunks, write_jsonl
from postproc.simulate.move_record import MoveRecord

EVENTS: list[Any] = [{"toolpath": 1, "units": "mm", "dialect": "fanuc"}] + [
    MoveRecord(n, "feed", ("x", "y", "z"), [n / 8, -n * 1.25, 0.5], 1500, None, [n / 8, -n * 1.25, 120.5])
    for n in range(1, 700)] + [{"line": 700, "event": "end"}]
"""More lines than one chunk of ``write_lines`` (256), a record and dictionaries."""


def _text() -> str:
    out = io.StringIO()
    write_jsonl(iter(EVENTS), out)
    return out.getvalue()


class _Stingy(io.RawIOBase):
    """A raw file that takes at most ``most`` bytes a write (as a file may take less than it is given)."""

    def __init__(self, most: int) -> None:
        self.most, self.data = most, bytearray()

    def writable(self) -> bool:
        return True

    def write(self, b: Any) -> int:
        taken = bytes(b[: self.most])
        self.data += taken
        return len(taken)


def test_a_buffered_file_gets_the_text_whole_after_what_its_buffer_held(tmp_path: Path) -> None:
    path = tmp_path / "t.jsonl"
    with open(path, "wb", buffering=1 << 20) as out:
        out.write(b"held\n")  # still in the buffer: written before the chunks, which skip it
        write_jsonl(iter(EVENTS), out)
        out.write(b"after\n")
    assert path.read_bytes() == b"held\n" + _text().encode() + b"after\n"
    assert _text().count("\n") == len(EVENTS)


def test_a_file_that_takes_less_than_it_is_given_gets_the_rest(tmp_path: Path) -> None:
    stingy = _Stingy(1000)
    buffered = io.BufferedWriter(stingy)
    write_chunks(buffered)("x" * 2500)  # not a FileIO: through the buffered writer, which writes the rest itself
    buffered.flush()
    assert bytes(stingy.data) == b"x" * 2500
    with open(tmp_path / "t", "wb") as out:
        fd = out.raw
        write = write_chunks(out)
        original = fd.write
        fd.write = lambda b: original(bytes(b[:777]))  # type: ignore[method-assign]
        write("y" * 5000 + "\n")
    assert (tmp_path / "t").read_bytes() == b"y" * 5000 + b"\n"


def test_a_binary_stream_and_a_text_stream_get_the_same_text() -> None:
    binary = io.BytesIO()
    write_jsonl(iter(EVENTS), binary)
    assert binary.getvalue() == _text().encode()


def test_the_command_writes_json_lines_as_bytes_the_same(cli: Any, tmp_path: Path) -> None:
    program = tmp_path / "p.nc"
    program.write_text("%\nO1\nG21 G90 G0 X1. Y2.\n" + "".join(
        f"G1 X{n / 8:.4f} Y{-n * 1.25:.3f} Z-.5 F1500.\n" for n in range(600)) + "M30\n%\n")
    r = cli("toolpath", program, "--dialect", "fanuc", "-o", tmp_path / "p.jsonl")
    assert r.status == 0, r.err
    written = (tmp_path / "p.jsonl").read_bytes()
    r = cli("toolpath", program, "--dialect", "fanuc")
    assert r.out == written
    assert written.count(b"\n") == 603 and b"\r" not in written  # the header, 601 moves, the end
