"""Seed of ``make fuzz`` (defects, issue 26/30 run): a SINUMERIK line of words written without blanks.

``malformed siemens`` made ``Y0G1G1G1...`` (40,000 words on one line): the reader took every word's name as the
whole run of letters and digits from it to the line's end, scanned and copied it again at each word, so a line
took time quadratic in its length (5 s for 5,000 words, about 150 s for 20,000; the fuzz's limit is 5 s). Now each
word is read where it stands; the scanning is counted here (a count, not a clock: the machine is shared).
"""

from __future__ import annotations

import io

import pytest

import dialects.siemens.reader as reader
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events


def _events(text: str) -> list[dict[str, object]]:
    return list(toolpath_events(io.StringIO(text), file="in.nc", dialect="siemens"))


def test_a_long_line_of_words_is_scanned_once(monkeypatch: pytest.MonkeyPatch) -> None:
    scanned = [0]
    name_at = reader.name_at

    def counting(text: str, pos: int) -> int:
        end = name_at(text, pos)
        scanned[0] += end - pos
        return end

    monkeypatch.setattr(reader, "name_at", counting)
    line = "Y0" + "G1" * 20000 + " Z33"
    with pytest.raises(ErrorList) as caught:
        _events(f"%_N_A_MPF\n{line}\nM30\n")
    assert str(caught.value.errors[0]) == "in.nc:2:3: error: G codes G1 and G1 are both in modal group 01"
    assert scanned[0] <= 4 * len(line)  # a few passes over the line (it was about 20,000 lines' worth)


def test_words_without_blanks_read_as_with_them() -> None:
    head = "%_N_A_MPF\nG17 G90 G0 X0 Y0 Z10\n"
    assert _events(head + "G1X10Y20Z5F100\nM30\n") == _events(head + "G1 X10 Y20 Z5 F100\nM30\n")


def test_an_address_twice_in_a_run_is_still_refused() -> None:
    with pytest.raises(ErrorList) as caught:
        _events("%_N_A_MPF\nG0X1X2\nM30\n")
    assert str(caught.value.errors[0]) == "in.nc:2:5: error: address X appears twice in one block"
