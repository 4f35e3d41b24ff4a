"""LinuxCNC programs written back to LinuxCNC from their words (``--normalize``, ``--renumber``, ``--units``,
``--transform``): what a comment's text holds changes nothing but the comment.

* ``@`` and ``^`` are polar words only outside comments: a line with one inside a comment (``(a @ ^ b)``, rs274
  reads it as text) was written as read, not normalized, and under ``--renumber`` a comment-only, o-word or
  ``%`` line with one got a block number, where the same line without it gets none (``% (@)``, which rs274
  refuses, became ``N30 % (@)``; a ``%`` with a comment is refused when read now: tests/test_linuxcnc.py).
* A ``;`` comment never acts, and rs274 acts on the last ``( )`` comment of a line only [V: rs274 2.9 run here]:
  ``; msg, hello`` was written ``( msg, hello)``, which rs274 runs as ``MESSAGE(" hello")``, and ``(msg, kept)
  ; note`` as ``(msg, kept) ( note)``, which shows no message. A ``;`` comment is written back as one.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import MachineSetup
from postproc_linuxcnc.active_comments import COMMENTS
from tests.support.rs274 import available, run_rs274

POLAR_IN_COMMENTS = ("%\no100 sub (@ sub)\nG1 X#1 F100 (a @ ^ b)\no100 endsub (^)\nG21 G90 ; semi @ ^\n"
                     "(n7 ^ x)\nN3 G1 X2 Y0 (n4 ^)\n/ G1 X3 (@)\no100 call [3] (@)\nM2 (^ end)\n%\n")


def _rewrite(source: str, renumber: tuple[int, int] | None = None, normalize: bool = False, **options: str) -> str:
    setup = MachineSetup()
    if renumber is not None:
        setup.output.renumber_start, setup.output.renumber_step = renumber
    setup.output.normalize = normalize
    out = io.StringIO(newline="")
    translate(io.StringIO(source, newline=""), out, file="t.ngc", source="linuxcnc", target="linuxcnc", setup=setup,
              **options)  # type: ignore[arg-type]
    return out.getvalue()


@pytest.mark.parametrize("options", [{"normalize": True}, {"renumber": (10, 10)}, {"renumber": (1, 5)}],
                         ids=["normalize", "renumber", "renumber 1,5"])
def test_polar_characters_in_comments_are_text(options: dict[str, object]) -> None:
    """The program is written as the same program with other characters in its comments is."""
    plain = POLAR_IN_COMMENTS.replace("@", "AT").replace("^", "CARET")
    written = _rewrite(POLAR_IN_COMMENTS, **options)  # type: ignore[arg-type]
    assert written.replace("@", "AT").replace("^", "CARET") == _rewrite(plain, **options)  # type: ignore[arg-type]
    assert "G1 X#1 F100. (a @ ^ b)" in written


def test_a_polar_word_beside_a_comment_keeps_its_line() -> None:
    """A real polar word still keeps its line as written (``LinuxcncWriter.normalized``)."""
    written = _rewrite("G21 G90 G0 X1 Y0\nG1 @5 ^30 F100 (a @ b)\nM2\n", renumber=(10, 10))
    assert written.splitlines()[1] == "N20 G1 @5 ^30 F100 (a @ b)"


SEMICOLON = ("G21 G90\nG1 X1 Y0 F100 ; msg, hello\n; debug, alone\nG1 X2 Y0 (msg, kept) ;  PRINT, x\n"
             "G1 X3 (msg, too) ; a note\nM2\n")
"""Three ``;`` comments that would act in parentheses, two ``( )`` comments that act, each before a ``;`` one."""
OPTIONS = {"normalize": {"normalize": True}, "renumber": {"renumber": (10, 10)}, "units": {"units": "inch"},
           "transform": {"transform": "translate 1,0,0"}}


def _active(text: str) -> list[str]:
    return [line[a:b] for line in text.splitlines() for a, b, passive in COMMENTS.comments(line) if not passive]


@pytest.mark.parametrize("name", OPTIONS)
def test_a_semicolon_comment_is_not_written_as_one_that_acts(name: str) -> None:
    written = _rewrite(SEMICOLON, **OPTIONS[name])  # type: ignore[arg-type]
    assert _active(written) == ["(msg, kept)", "(msg, too)"], written
    assert " ; msg, hello\n" in written and "\n; debug, alone\n" in written and "(msg, too) ; a note\n" in written


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("name", OPTIONS)
def test_rs274_shows_the_sources_messages_only(name: str) -> None:
    def messages(text: str) -> list[str]:
        return [line.split(None, 1)[1] for line in run_rs274(text) if "MESSAGE(" in line]
    written = _rewrite(SEMICOLON, **OPTIONS[name])  # type: ignore[arg-type]
    assert messages(written) == messages(SEMICOLON) == ['MESSAGE(" kept")', 'MESSAGE(" too")'], written
