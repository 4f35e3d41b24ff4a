"""The line check every reader's lines pass (``postproc.syntaxes.lines``): non-ASCII outside comments, over-long
lines and numbers of more than 30 digits are located errors, for every readable dialect; comments keep
any character."""

from __future__ import annotations

import io

from hypothesis import given, settings, strategies as st

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.plugins import default_registry
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events

READABLE = sorted(n for n, c in default_registry().dialects.items() if c.READER is not None)


def _errors(program: str, dialect: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(program), io.StringIO(), file="p.nc", source=dialect, target=dialect,
                  setup=setup or MachineSetup())
    return [str(e) for e in info.value.errors]


def _metric(dialect: str, prologue: str) -> str:
    """Fagor's metric code is G71 (its G21 is no code of the 8070 reference), SINUMERIK's G710 (lengths and
    feeds; its G21 is no code)."""
    metric = {"fagor": "G71", "siemens": "G710"}.get(dialect)
    return prologue.replace("G21", metric) if metric else prologue


@pytest.mark.parametrize("dialect", READABLE)
@pytest.mark.parametrize("line, message", [
    ("G0 X\u0661\u0660.", "p.nc:2:5: error: character '\u0661' (U+0661) is not ASCII: outside comments a program "
                          "is ASCII"),
    ("G0 \uff3810.", "p.nc:2:4: error: character '\uff38' (U+FF38) is not ASCII: outside comments a program is "
                     "ASCII"),
    # a byte that is not UTF-8 is read as a surrogate (surrogateescape) and named as the byte the file holds
    ("G0 X\udcff2.", "p.nc:2:5: error: byte 0xFF (not UTF-8) is not ASCII: outside comments a program is ASCII"),
    ("G0 X" + "1" * 5000 + ".", "p.nc:2:5: error: a number with more than 30 digits cannot be read"),
    ("G0 X1" + "1" * 399, "p.nc:2:5: error: a number with more than 30 digits cannot be read"),
    ("G0 X" + "1" * 16 + "." + "1" * 16, "p.nc:2:5: error: a number with more than 30 digits cannot be read"),
])
def test_unreadable_line_is_a_located_error(dialect: str, line: str, message: str) -> None:
    # G90 is the absolute mode of a mill and the turning cycle of a lathe (GSK): a lathe gets G21 alone
    prologue = "G21" if "mill" not in default_registry().dialect(dialect).MACHINE_TYPES else "G21 G90"
    prologue = _metric(dialect, prologue)
    assert _errors(f"{prologue}\n{line}\nM30\n", dialect) == [message]


@pytest.mark.parametrize("dialect", READABLE)
def test_line_longer_than_the_limit_is_refused_before_reading(dialect: str) -> None:
    setup = MachineSetup(limits=Limits(line_length=40))
    line = "G0 X1. Y2. Z3." + " " * 40
    assert _errors(f"{_metric(dialect, 'G21')}\n{line}\nM30\n", dialect, setup) == [
        "p.nc:2:41: error: the line is 54 characters long, more than the limit of 40 (the set-up's "
        "<Limits lineLength>)"]


def test_default_line_limit_is_64k() -> None:
    assert Limits().line_length == 65_536
    line = "G0 X1." + " " * 70_000
    assert _errors(f"{line}\n", "fanuc")[0].startswith("p.nc:1:65537: error: the line is 70006 characters")


def test_every_bad_line_is_reported_and_line_numbers_stay() -> None:
    program = "G21\nG0 X\u0661.\nG0 X1.\nG1 X" + "9" * 40 + ". F100.\nM30\n"
    errors = _errors(program, "fanuc")
    assert [e.split(": error")[0] for e in errors] == ["p.nc:2:5", "p.nc:4:5"]


@pytest.mark.parametrize("comment", ["(caf\u00e9 \u0661\u0660 " + "1" * 50 + ")", "(caf\udce9)"])
def test_comments_keep_any_character(comment: str) -> None:
    program = f"G21 G90\nG0 X1. {comment}\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="fanuc")
    assert out.getvalue() == program


def test_thirty_digits_are_read() -> None:
    program = "G21 G90\nG0 X" + "1" * 15 + "." + "2" * 15 + "\nM30\n"
    moves = [e for e in toolpath_events(io.StringIO(program), file="p.nc", dialect="fanuc") if "move" in e]
    assert moves[0]["x"] == pytest.approx(111111111111111.2222)


def test_linuxcnc_semicolon_comment_keeps_any_character() -> None:
    program = "G21 G90\nG0 X1. ; caf\u00e9 \u0661\u0660\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.ngc", source="linuxcnc", target="linuxcnc")
    assert out.getvalue() == program


@pytest.mark.parametrize("dialect", ["fanuc", "linuxcnc"])
def test_signed_g_code_is_an_unknown_code_not_an_internal_error(dialect: str) -> None:
    """'G-.0' was an int('-') ValueError (found by the reader's fuzz test); never read as G0."""
    assert _errors("G-.0\nG-1 X1.\n", dialect) == ["p.nc:1:1: error: unknown G code G-.0",
                                                  "p.nc:2:1: error: unknown G code G-1"]


# -- reading a line only as far as its limit -------------------------------------------------------

class _Endless(io.TextIOBase):
    """A text stream of ``head``, then ``fill`` characters of ``char`` (None: without end), then ``tail``:
    ``/dev/zero`` or a 50 MB line without holding either."""

    def __init__(self, head: str, char: str, fill: int | None, tail: str) -> None:
        self.parts = [head]
        self.char, self.fill, self.tail = char, fill, tail

    def readline(self, size: int = -1) -> str:  # type: ignore[override]
        assert size > 0, "read without a bound"
        if self.parts:
            return self.parts.pop()
        if self.fill is None or self.fill > 0:
            n = size if self.fill is None else min(size, self.fill)
            if self.fill is not None:
                self.fill -= n
            return self.char * n
        line, _, self.tail = self.tail.partition("\n")
        return line + "\n" if _ or line else ""


def _stream_errors(stream: io.TextIOBase) -> list[str]:
    with pytest.raises(ErrorList) as info:
        translate(stream, io.StringIO(), file="p.nc", source="fanuc", target="grbl")
    return [str(e) for e in info.value.errors]


def test_a_line_of_50_mb_is_counted_in_pieces_and_reading_goes_on():
    from postproc.output.bounded import run_bounded

    def errors() -> list[str]:
        return _stream_errors(_Endless("G21 G90\n", "X", 50_000_000, "\nG0 X1.2.3\nM30\n"))

    found = run_bounded(errors, seconds=60, memory=48 << 20)  # the line whole: 50 MB, and its copies
    assert found.failure is None, found.failure
    assert found.value == [
        "p.nc:2:65537: error: the line is 50000000 characters long, more than the limit of 65536 (the set-up's "
        "<Limits lineLength>)",
        "p.nc:3:4: error: malformed word 'X1.2.3'"]


def test_an_endless_line_ends_the_reading(monkeypatch):
    import postproc.syntaxes.lines
    monkeypatch.setattr(postproc.syntaxes.lines, "MAX_SKIPPED", 1 << 20)
    errors = _stream_errors(_Endless("G21 G90\n", "\0", None, ""))
    assert len(errors) == 1 and errors[0].startswith("p.nc:2:65537: error: the line is more than ")
    assert errors[0].endswith(" characters long, more than the limit of 65536 (the set-up's <Limits lineLength>): "
                              "the rest of the input is not read")
    length = int(errors[0].split("more than ")[1].split(" ")[0])
    assert (1 << 20) + 65536 < length <= (1 << 20) + 65536 + 4096  # one piece past the bound


TEXT = st.lists(st.tuples(st.text(alphabet="GX1. ", max_size=30), st.sampled_from(["\n", "\r\n", "\r"])),
                max_size=12).map(lambda lines: "".join(text + end for text, end in lines))


@given(text=TEXT, tail=st.text(alphabet="GX1. ", max_size=30), limit=st.integers(1, 24),
       piece=st.sampled_from([4, 7, 4096]))
@settings(max_examples=300, deadline=None)
def test_lines_read_in_pieces_are_the_lines_read_whole(text, tail, limit, piece):
    # the same lines and the same errors whether a stream is read in pieces (of PIECE characters, or of
    # the limit and an end of line) or each line whole, CR LF cut between its characters included
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    program = text + tail
    got = []
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(postproc.syntaxes.lines, "PIECE", piece)
        for source in (io.StringIO(program, newline=""), list(io.StringIO(program, newline=""))):
            ctx = Context("p.nc", MachineSetup(limits=Limits(line_length=limit)), Diagnostics(ErrorLevel.WARN,
                          warn_stream=io.StringIO()), "fanuc")
            lines = list(postproc.syntaxes.lines.checked_lines(source, ctx))
            got.append((lines, [str(w) for w in ctx.diagnostics.warnings]))
    assert got[0] == got[1]

PLUS = "G21 G90 G0 X0 Y0 Z5\nG+1 X1 F100\nG+81 X2 Z-1 R1\nG+80\nG+0 X3\nM2\n"
"""A plus sign on a G number: LinuxCNC's rs274 runs G+1, G+81, G+80, G+0 as G1, G81, G80, G0 [V]."""


PLUSSES = {
    "fanuc": "G21 G90 G0 X0 Y0 Z5.\nG+1 X1. F100.\nG+81 X2. Z-1. R1.\nG+80\nG+0 X3.\nM30\n",
    "linuxcnc": PLUS, "mach3": PLUS, "grbl": PLUS.replace("G+81 X2 Z-1 R1\nG+80\n", ""),
    "isg": "G90 G+0 X0 Y0 Z5\nG+1 X1 F100\nG+0 X3\nM30\n", "fagor": "G90 G+0 X0 Y0 Z5\nG+1 X1 F100\nG+0 X3\nM30\n",
}


@pytest.mark.parametrize("dialect", sorted(PLUSSES))
def test_a_plus_sign_on_a_g_number_reads_as_the_code(dialect: str) -> None:
    """'G+1' and 'G+80' were 'unknown G code' while 'M+3' read as M3: one reading for every code."""
    program = PLUSSES[dialect]
    events = list(toolpath_events(io.StringIO(program), file="p.nc", dialect=dialect))
    assert [e for e in events if "move" in e]
    assert events == list(toolpath_events(io.StringIO(program.replace("G+", "G")), file="p.nc", dialect=dialect))


def test_a_plus_sign_on_a_g_number_moves_as_rs274_runs_it() -> None:
    from tests.support.rs274 import available, canonical_moves, motions, run_rs274
    if not available():
        pytest.skip("rs274 is not installed")
    ours = [e for e in toolpath_events(io.StringIO(PLUS), file="p.ngc", dialect="linuxcnc") if "move" in e]
    theirs = motions(canonical_moves(run_rs274(PLUS)))
    assert [(e["move"], e["x"], e["z"]) for e in ours] == [(e["move"], e["x"], e["z"]) for e in theirs]


@pytest.mark.parametrize("dialect", ["fanuc", "linuxcnc"])
def test_a_plus_sign_keeps_the_program_as_written_and_writes_the_code_elsewhere(dialect: str) -> None:
    out = io.StringIO()
    translate(io.StringIO(PLUS), out, file="p.nc", source="linuxcnc", target=dialect)
    assert ("G+1 X1" in out.getvalue()) == (dialect == "linuxcnc")


class _ReadlineOnly(io.TextIOBase):
    """A stream read only by ``readline`` (the pieces ``postproc.syntaxes.lines.pieces`` takes, line by line)."""

    def __init__(self, stream: io.StringIO) -> None:
        self.stream = stream

    def readline(self, size: int = -1) -> str:  # type: ignore[override]
        return self.stream.readline(size)


ODD_TEXT = st.lists(st.tuples(st.text(alphabet="GX1. 0123456789(é\v\f\x1c\x1d\x1e\x85\u2028;", max_size=60),
                              st.sampled_from(["\n", "\r\n", "\r", "\r\r\n", "\n\r"])), max_size=12).map(
    lambda lines: "".join(text + end for text, end in lines))


@given(text=ODD_TEXT, tail=st.text(alphabet="GX1. \r\u2028", max_size=30), limit=st.integers(1, 40),
       piece=st.sampled_from([4, 7, 16, 4096]), bom=st.booleans(), newline=st.sampled_from(["", None]))
@settings(max_examples=500, deadline=None)
def test_a_stream_read_many_lines_at_once_gives_the_lines_and_errors_read_line_by_line(text, tail, limit, piece,
                                                                                        bom, newline):
    # ``checked_lines`` reads a stream that splits lines at CR, LF and CR LF in pieces of many lines and splits
    # them itself (``_read_chunks``): the lines and errors are those of the same stream read a line at a
    # time, whatever the line ends, line lengths, other separators ``str.splitlines`` knows, non-ASCII
    # characters and long numbers, with a read ending anywhere (pieces of 4 or 7 characters)
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    program = ("\ufeff" if bom else "") + text + tail
    got = []
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(postproc.syntaxes.lines, "PIECE", piece)
        for source in (io.StringIO(program, newline=newline), _ReadlineOnly(io.StringIO(program, newline=newline)),
                       list(io.StringIO(program, newline=newline))):
            ctx = Context("p.nc", MachineSetup(limits=Limits(line_length=limit)), Diagnostics(ErrorLevel.WARN,
                          warn_stream=io.StringIO()), "fanuc")
            lines = list(postproc.syntaxes.lines.checked_lines(source, ctx))
            got.append((lines, [str(w) for w in ctx.diagnostics.warnings]))
    assert got[0] == got[1] == got[2]


def test_a_stream_that_splits_only_at_lf_is_read_line_by_line() -> None:
    # a stream opened with newline="\n" keeps a lone CR inside its line: read as it splits
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics
    ctx = Context("p.nc", MachineSetup(), Diagnostics(), "fanuc")
    assert list(postproc.syntaxes.lines.checked_lines(io.StringIO("G0 X1.\rG1 X2.\nM30\n"), ctx)) == ["G0 X1.\rG1 X2.\n",
                                                                                             "M30\n"]
    ctx = Context("p.nc", MachineSetup(), Diagnostics(), "fanuc")
    assert list(postproc.syntaxes.lines.checked_lines(io.StringIO("G0 X1.\rG1 X2.\nM30\n", newline=""), ctx)) == [
        "G0 X1.\r", "G1 X2.\n", "M30\n"]


@pytest.mark.parametrize("wrap", [list, _ReadlineOnly, lambda s: s])
def test_a_byte_order_mark_does_not_count_in_the_line_length(wrap) -> None:
    # a line of 4 characters after the mark is within a limit of 4 whichever way it is read (it was refused
    # as "4 characters long, more than the limit of 4" where its piece was as long as a cut one)
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    for program in ("\ufeffG1X.\rG1\n", "\ufeffG1X.\r\nG1\n", "\ufeffG1X1.\rG1\n"):
        ctx = Context("p.nc", MachineSetup(limits=Limits(line_length=4)), Diagnostics(ErrorLevel.WARN,
                      warn_stream=io.StringIO()), "fanuc")
        lines = list(postproc.syntaxes.lines.checked_lines(wrap(io.StringIO(program, newline="")), ctx))
        errors = [str(w) for w in ctx.diagnostics.warnings]
        if "X1." in program:  # 5 characters: too long, counted without the mark
            assert errors == ["p.nc:1:6: warning: the line is 5 characters long, more than the limit of 4 (the "
                              "set-up's <Limits lineLength>)"] and lines == ["\r", "G1\n"]
        else:
            assert errors == [] and lines == io.StringIO(program, newline="").readlines()


_CHECKED_TEXT = st.text(alphabet="GX1.0 (;)\t\u00e9\u0661\x0b", max_size=70)
CHECKED_LINES = st.lists(st.tuples(st.one_of(_CHECKED_TEXT, st.builds(lambda n, d: "X" + "1" * n + "." + d,
                                                                      st.integers(10, 40), st.text("19.", max_size=9))),
                                   st.sampled_from(["\n", "\r\n", "\r", ""])), max_size=30)


@given(lines=CHECKED_LINES, limit=st.integers(5, 80), bom=st.booleans())
@settings(max_examples=300, deadline=None)
def test_the_chunk_checks_are_line_problem_line_by_line(lines, limit, bom):
    # ``checked_lines`` checks a chunk of lines at once with a few C calls and only a chunk that fails them line
    # by line (``line_problem``): the lines it passes and the errors it reports are ``line_problem``'s on each
    # line, whatever the chunk holds (non-ASCII, long digit runs, comments, over-long lines)
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    program = (postproc.syntaxes.lines.BOM if bom else "") + "".join(text + end for text, end in lines)
    raw = io.StringIO(program, newline="").readlines()  # its physical lines, as a stream splits them
    ctx = Context("p.nc", MachineSetup(limits=Limits(line_length=limit)), Diagnostics(ErrorLevel.WARN,
                  warn_stream=io.StringIO()), "fanuc")
    got = list(postproc.syntaxes.lines.checked_lines(raw, ctx))
    expected, errors = [], []
    for number, line in enumerate(raw, 1):
        lead = number == 1 and line[:1] == postproc.syntaxes.lines.BOM
        problem = postproc.syntaxes.lines.line_problem(line[1:] if lead else line, limit)
        if problem is None:
            expected.append(line)
        else:
            expected.append(line[len(line.rstrip("\r\n")):])
            errors.append(f"p.nc:{number}:{problem[1] + lead}: warning: {problem[0]}")
    assert got == expected
    assert [str(w) for w in ctx.diagnostics.warnings] == errors


_RUN_LINES = st.lists(st.text(alphabet="GX1. 0123456789(é\v\f\x1c\x85\u2028;", max_size=60), max_size=40)


def _split(line: str) -> tuple[str, str]:
    """A physical line as (text, end of line), as a reader splits it."""
    text = line.rstrip("\r\n")
    return text, line[len(text):]


@given(lines=_RUN_LINES, end=st.sampled_from(["\n", "\r\n", "mixed"]), odd=ODD_TEXT, tail=st.sampled_from(
       ["", "G1 X1.", "X1\r", "\r"]), limit=st.integers(1, 70), piece=st.sampled_from([4, 7, 16, 64, 4096]),
       bom=st.booleans(), newline=st.sampled_from(["", None]))
@settings(max_examples=500, deadline=None)
def test_runs_are_the_checked_lines_split_from_their_ends(lines, end, odd, tail, limit, piece, bom, newline):
    # ``CheckedLines.runs`` passes a piece of lines that all end alike as their texts and that end: the lines and
    # errors are those the lines with their ends give, whatever the ends (one for the program, or mixed),
    # separators ``str.splitlines`` knows, long lines and numbers, a last line without an end, and however the
    # lines are given (a stream read in pieces, one read by ``readline``, a list)
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    body = odd if end == "mixed" else "".join(line + end for line in lines)
    program = ("\ufeff" if bom else "") + body + tail
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(postproc.syntaxes.lines, "PIECE", piece)
        for make in (lambda: io.StringIO(program, newline=newline),
                     lambda: _ReadlineOnly(io.StringIO(program, newline=newline)),
                     lambda: list(io.StringIO(program, newline=newline))):
            got = []
            for runs in (False, True):
                ctx = Context("p.nc", MachineSetup(limits=Limits(line_length=limit)), Diagnostics(
                    ErrorLevel.WARN, warn_stream=io.StringIO()), "fanuc")
                checked = postproc.syntaxes.lines.checked_lines(make(), ctx)
                if runs:
                    split = []
                    for texts, run_end, data in checked.runs():
                        if run_end is None:
                            assert data == b""
                            split.extend(_split(line) for line in texts)
                        else:
                            assert isinstance(texts, list) and texts and (run_end or len(texts) == 1)
                            assert data == b"" or data.startswith("".join(text + run_end for text in texts).encode())
                            split.extend((text, run_end) for text in texts)
                else:
                    split = [_split(line) for line in checked]
                got.append((split, [str(w) for w in ctx.diagnostics.warnings]))
            assert got[0] == got[1]


@pytest.mark.parametrize("end", ["\n", "\r\n"])
def test_a_stream_whose_lines_end_alike_comes_in_runs_of_texts(end) -> None:
    # the runs are taken where they apply (a stream read in pieces, every line ending alike; the last without an end
    # a run of its own), and not where the ends differ
    import postproc.syntaxes.lines
    from postproc.context import Context
    from postproc.errors import Diagnostics
    ctx = Context("p.nc", MachineSetup(), Diagnostics(), "fanuc")
    program = f"G0 X1.{end}G1 X2.{end}M30"
    assert list(postproc.syntaxes.lines.checked_lines(io.StringIO(program, newline=""), ctx).runs()) == [
        (["G0 X1.", "G1 X2."], end, f"G0 X1.{end}G1 X2.{end}".encode("ascii")), (["M30"], "", b"")]
    mixed = "G0 X1.\r\nG1 X2.\nM30\n"
    assert list(postproc.syntaxes.lines.checked_lines(io.StringIO(mixed, newline=""), ctx).runs()) == [
        (["G0 X1.\r\n", "G1 X2.\n", "M30\n"], None, b"")]


@given(lines=_RUN_LINES, cam=st.lists(st.sampled_from(["N10 G1 X1. Y2.", "G0 X1", "N20 G2 X1. I0.5", "#1=2.",
                                                        "O1234", "M98 P12", "G65 P9010 A1.", "N7 X-0. F100.", ""]),
                                       max_size=30), end=st.sampled_from(["\n", "\r\n"]), tail=st.booleans())
@settings(max_examples=200, deadline=None)
def test_the_fanuc_reader_reads_runs_as_it_reads_lines(lines, cam, end, tail):
    # the Fanuc reader reads the runs of checked lines (texts split from their end) and lines with their ends
    # into the same blocks and errors
    from dialects.fanuc.reader import FanucReader
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    import postproc.syntaxes.lines
    program = "".join(line + end for line in cam + lines) + ("G1 X5." if tail else "")
    got = []
    for runs in (True, False):
        ctx = Context("p.nc", MachineSetup(), Diagnostics(ErrorLevel.WARN, warn_stream=io.StringIO()), "fanuc")
        checked = postproc.syntaxes.lines.checked_lines(io.StringIO(program, newline=""), ctx)
        blocks = list(FanucReader(ctx).read(checked if runs else list(checked)))
        got.append(([(b.line, b.text, b.eol, b.words, b.values, b.sections, b.canonical) for b in blocks],
                    [str(w) for w in ctx.diagnostics.warnings]))
    assert got[0] == got[1]


@pytest.mark.parametrize("dialect", ["linuxcnc", "grbl"])
@given(lines=_RUN_LINES, ngc=st.lists(st.sampled_from(["N10 G1 X1. Y2.", "G0 X 1 0", "(PASS 1)", "G1 X1. (A) Y2.", "%",
                                                       "o100 sub", "#1=2.", "X[#1*2]", "/G1 X3.", "G1 X1/2", "M2",
                                                       "m30", "; note", "N7 X-0. F100.", "", "N1.5", "O12"]),
                                       max_size=30), end=st.sampled_from(["\n", "\r\n"]), tail=st.booleans())
@settings(max_examples=100, deadline=None)
def test_the_ngc_readers_read_runs_as_they_read_lines(dialect, lines, ngc, end, tail):
    # the RS274/NGC readers, as the Fanuc reader, read the runs of checked lines (texts split from their end) and
    # lines with their ends into the same blocks, warnings and errors
    from postproc.context import Context
    from postproc.errors import Diagnostics, ErrorLevel
    import postproc.syntaxes.lines
    reader = default_registry().dialect(dialect).READER
    program = "".join(line + end for line in ngc + lines) + ("G1 X5." if tail else "")
    got = []
    for runs in (True, False):
        ctx = Context("p.ngc", MachineSetup(), Diagnostics(ErrorLevel.WARN, warn_stream=io.StringIO()), dialect)
        checked = postproc.syntaxes.lines.checked_lines(io.StringIO(program, newline=""), ctx)
        blocks = list(reader(ctx).read(checked if runs else list(checked)))
        got.append(([(b.line, b.text, b.eol, b.words, b.values, b.sections) for b in blocks],
                    [str(w) for w in ctx.diagnostics.warnings], [str(e) for e in ctx.diagnostics.errors]))
    assert got[0] == got[1]
