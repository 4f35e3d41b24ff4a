"""grbl 1.1 keeps 79 characters of a line (``LINE_BUFFER_SIZE`` 80 in ``protocol.h``, spaces and comments not
counted; error 11 beyond): a longer line has its numbers written shorter where that is exact, or is refused
with a located error, never written (issue 31, item 4). The rule applies to every line written - blocks,
copies of grbl's own lines, templates' output."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines
from postproc_grbl.text import KEPT, kept, shortened

from tests.support.grbl_rules import GrblError, _protocol, grbl_problems

DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"
LONG = "N12345 G17 G21 G90 G54 G94 G1 X-12345.123456 Y-12345.123456 Z-12345.123456 F12345.123456 S12345 M3 M8\n"
"""88 characters without spaces: more than grbl keeps, with no digit to spare."""
ZEROS = "N12345 G17 G21 G90 G54 G94 G1 X-12345.100000 Y-12345.100000 Z-0.500000 F12345.000000 S12345 M3 M8\n"
"""As long, but its numbers have zeros to spare: 73 characters written shortest."""


def _translate(program: str, source: str = "fanuc", setup: object = None) -> str:
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source=source, target="grbl", setup=setup)
    return out.getvalue()


@pytest.mark.parametrize("source", ["fanuc", "linuxcnc", "grbl"])
def test_a_line_grbl_cannot_hold_is_refused_where_it_was_read(source: str) -> None:
    """It was written with exit 0 (and grbl answered error 11)."""
    with pytest.raises(ErrorList) as info:
        _translate("G21 G90\n" + LONG + "M30\n", source)
    assert str(info.value).startswith("in.nc:2:1: error: the line keeps 88 characters without spaces and "
                                      "comments, more than the 79 grbl 1.1 holds (LINE_BUFFER_SIZE 80, error 11)")


@pytest.mark.parametrize("source", ["fanuc", "linuxcnc", "grbl"])
def test_a_long_line_with_zeros_to_spare_is_written_shorter_and_exact(source: str) -> None:
    program = "G21 G90\n" + ZEROS + "M30\n"
    text = _translate(program, source)
    assert kept(text.splitlines()[1]) <= KEPT and grbl_problems(text) == []
    if source == "grbl":  # copied as written, then shortened
        assert text.splitlines()[1] == "N12345 G17 G21 G90 G54 G94 G1 X-12345.1 Y-12345.1 Z-.5 F12345 S12345 M3 M8"
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                          source=source, target="grbl", tolerance=0.0)
    assert report.ok, report.summary()


def test_comments_and_spaces_do_not_count() -> None:
    """protocol.c drops them before the line buffer: a long comment is no reason to refuse a line."""
    line = "G1 X1 Y2 F100 (" + "C" * 200 + ") ; " + "D" * 100
    assert _translate(f"G21 G90\n{line}\nM30\n", "grbl").splitlines()[1] == line


def test_a_template_line_grbl_cannot_hold_is_refused_at_the_template(tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + '<MachineSetup name="m" dialect="grbl">\n  <Templates>\n'
                    "    <Header>(A)\nG10 L2 P1 X-1234567890123456789.123456 Y-1234567890123456789.123456 "
                    "Z-1234567890123456789.123456</Header>\n  </Templates>\n</MachineSetup>\n")
    with pytest.raises(ErrorList) as info:
        _translate("G21 G90\nG0 X1\nM30\n", "fanuc", load_setup(path))
    assert str(info.value).startswith(f"{path}:4:1: error: the line keeps 91 characters")


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="GXYZF0123456789.-+ ()/;\t", max_size=160))
def test_kept_counts_what_the_protocol_layer_keeps(line: str) -> None:
    """Differential: ``kept`` against the suite's own reading of protocol.c (``grbl_rules._protocol``)."""
    try:
        expected = len(_protocol(line))
    except GrblError:
        expected = KEPT + 1  # error 11: more than it keeps
    assert min(kept(line), KEPT + 1) == expected


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.sampled_from("XYZFIJ"), st.decimals(allow_nan=False, allow_infinity=False,
                                                                   places=6, min_value=-99999, max_value=99999)),
                min_size=1, max_size=6))
def test_a_shortened_number_reads_as_the_same_value(words: list[tuple[str, object]]) -> None:
    """Property: every word's number written shorter is the same decimal (grbl's read_float reads '-.5')."""
    line = " ".join(f"{letter}{value}" for letter, value in words)
    short = shortened(line)
    assert [float(w[1:]) for w in short.split()] == [float(str(value)) for _, value in words]
    assert kept(short) <= kept(line)


@given(st.text(alphabet=st.characters(blacklist_categories=()), max_size=40))
def test_plain_ascii_says_what_the_realtime_rule_says(text: str) -> None:
    """``plain_ascii`` (one encoding with ``replace``, then a byte table) holds exactly for ASCII text without a
    character grbl acts on (``REALTIME``), whatever the text holds: surrogates (a byte read with surrogateescape),
    characters beyond the BMP, control characters."""
    from postproc.grbl_family.text import REALTIME, plain_ascii
    assert plain_ascii(text) == (text.isascii() and not REALTIME.search(text))
    for extra in ("\udcff", "\U0001f600", "\x7f", "?", "\u00e9"):
        assert not plain_ascii(text + extra)
