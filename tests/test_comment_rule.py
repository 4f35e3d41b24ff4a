"""``CommentRule`` (``postproc.syntaxes.comment_rule``): an active comment is found by its syntax's words, with a
cheap test of the text's first characters before the regular expression; the word writer writes another dialect's
comments with its target's rule, so a Fanuc comment that would act in LinuxCNC is written inert."""

from __future__ import annotations

import io

from hypothesis import given, settings, strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.syntaxes.comment_rule import CommentRule
from postproc.syntaxes.comments import CommentSyntax
from postproc_linuxcnc.active_comments import COMMENTS, WORDS

# Characters that meet the words in any case, blanks, word ends, and non-ASCII letters that Python's
# IGNORECASE takes for ASCII ones (the long s, the dotless i, the Kelvin sign, the dotted capital I).
PIECES = st.sampled_from([*WORDS, *(w.lower() for w in WORDS), "Ms", "dE", "pR", "lo", "Py", "aB", " ", "\t", ",",
                          "_", "1", "x", "drill", "ſ", "ı", "K", "İ", "é", "MſG", "PRıNT", "\n", ")", "("])
TEXTS = st.one_of(st.text(max_size=12), st.lists(PIECES, max_size=5).map("".join))


@settings(max_examples=1500, deadline=None)
@given(text=TEXTS)
def test_the_first_characters_test_never_decides_other_than_the_pattern(text: str) -> None:
    rule = COMMENTS.rule
    assert rule.active is not None
    m = rule.active.match(text)
    assert rule.head(text) == (m.group(1) if m is not None else None)


@settings(max_examples=300, deadline=None)
@given(words=st.lists(st.from_regex(r"[A-Za-z][A-Za-z0-9]{0,5}", fullmatch=True), min_size=1, max_size=4),
       text=TEXTS, lead=st.sampled_from(["", " ", "\t", "x"]))
def test_any_words_the_same(words: list[str], text: str, lead: str) -> None:
    rule = CommentRule(True, tuple(words), None)
    assert rule.active is not None
    for probe in (text, lead + words[0] + text, lead + words[-1].swapcase() + text):
        m = rule.active.match(probe)
        assert rule.head(probe) == (m.group(1) if m is not None else None), probe


def test_the_pattern_is_linuxcnc_s() -> None:
    rule = COMMENTS.rule
    for text in (" MSG, x", "msg,x", "\tDEBUG, #1", "print,done", "LOGOPEN,f.txt", "logclose", "PROBEOPEN f",
                 "ABORT, stop", "py,x=1", "LOG,x"):
        assert rule.acts(text), text
    # look-alikes of ASCII letters, and a word run on into another letter, are inert [V: linuxcnc-uspace 2.9's
    # rs274 run here on "(PR\u0131NT,lookalike)", "(MSG\u00e9,e)", "(DEBUGx,y)": COMMENT, where "(msg,ok)" gave MESSAGE]
    for text in ("msgs are inert", "drill from line 5: G81 X1", "MSG_1", "LOGX", "PYTHON", "- MSG, x", "",
                 "PR\u0131NT,lookalike", "M\u017fG,x", "MSG\u00e9,e", "DEBUGx,y", "\u0130\u212a"):
        assert not rule.acts(text), text
    assert rule.comment(" MSG, a (b)") == "(- MSG, a [b])" and rule.comment("drill") == "(drill)"
    assert CommentRule(False, (), None).comment("a\tb") == ";a b"


def test_a_word_must_be_ascii_letters_and_digits() -> None:
    for word in ("1MSG", "MSG,", "", "MſG"):
        try:
            CommentSyntax(active_words=(word,)).rule
        except ValueError:
            continue
        raise AssertionError(word)


def _to(source: str, target: str, text: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source=source, target=target,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def test_another_dialect_s_comment_is_written_inert_for_linuxcnc_only() -> None:
    text = "G21 G90 G0 X0 Y0 Z1 ( MSG, change tool)\n(debug,x)\n(drill here)\nM30\n"
    linuxcnc = _to("fanuc", "linuxcnc", text)
    assert "(- MSG, change tool)" in linuxcnc and "(-debug,x)" in linuxcnc and "(drill here)" in linuxcnc
    grbl = _to("fanuc", "grbl", text)
    assert "( MSG, change tool)" in grbl and "(debug,x)" in grbl


def test_an_expanded_hole_s_note_is_a_plain_comment() -> None:
    text = "G21 G90 G17 G0 X0 Y0 Z5\nG98 G81 X1 Y1 Z-1 R1 F100\nX2\nG80\nM30\n"
    notes = [line for line in _to("fanuc", "linuxcnc", text).splitlines() if line.startswith("(")]
    assert notes and all(line.startswith("(drill from line") for line in notes), notes
