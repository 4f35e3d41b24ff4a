"""The writers' straight path (``WordWriter.straight_move``) writes exactly what ``generate`` writes.

A CAM program's usual block (``N.. X.. Y.. Z.. F..``) is written by a few comparisons instead of the
section dispatch, for the writers whose overrides say they write such a block as the base does
(``STRAIGHT_OVERRIDES``). Random programs of such blocks, mixed with what must leave the path (arcs,
other axes, numbers with more places than are written exactly, incremental moves that carry rounding,
block numbers with leading zeros, a units change), are translated twice: as shipped, and with the
path turned off (an empty ``STRAIGHT_OVERRIDES`` makes the class fall back to ``generate``); text,
warnings and errors must be the same.
"""

from __future__ import annotations

import io

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.rs274.writer import COPY_METHODS, WordWriter
from postproc.setup import MachineSetup

TARGETS = ("linuxcnc", "grbl", "fanuc")
"""fanuc: the program normalised back to Fanuc (``straight_copy``: a straight block is its source line)."""


def _writer(target: str) -> type[WordWriter]:
    writer = default_registry().dialect(target).WRITER
    assert isinstance(writer, type) and issubclass(writer, WordWriter)
    return writer


@st.composite
def numbers(draw: st.DrawFn) -> str:
    """An axis or feed number: mostly canonical (what CAM writes), sometimes with more places than a
    writer spells exactly, a trailing zero, no leading zero or no point (the general path's cases)."""
    places = draw(st.integers(min_value=0, max_value=8))
    whole = draw(st.integers(min_value=-99999, max_value=99999))
    value = whole / 10 ** places
    text = f"{value:.{places}f}".rstrip("0") if places else f"{whole}."
    if text in ("-0.", "-0"):
        text = "0."
    shape = draw(st.sampled_from(["canonical"] * 6 + ["trailing zero", "no leading zero", "integer"]))
    if shape == "trailing zero":
        text += "0"
    elif shape == "no leading zero" and text.startswith(("0.", "-0.")) and text not in ("0.", "-0."):
        text = text.replace("0.", ".", 1)
    elif shape == "integer":
        text = str(whole)
    return text


@st.composite
def lines(draw: st.DrawFn) -> list[str]:
    out = [draw(st.sampled_from(["G21", "G20"])), draw(st.sampled_from(["G90", "G91"])),
           draw(st.sampled_from(["G1 F100.", "G0", "G1"]))]
    for i in range(draw(st.integers(min_value=1, max_value=12))):
        kind = draw(st.sampled_from(["move"] * 8 + ["arc", "mode", "units", "rapid"]))
        number = draw(st.sampled_from([f"N{10 * (i + 1)} ", f"N0{i + 1} ", ""]))
        if kind == "arc":
            end = draw(st.integers(min_value=-999, max_value=999))  # never where it starts (a full circle)
            out.append(f"{number}G2 X{end}.25 R99999.")  # a chord the radius reaches
            out.append(draw(st.sampled_from(["G1", "G0"])))  # then straight moves again
        elif kind == "mode":
            out.append(draw(st.sampled_from(["G90", "G91", "G1", "G0"])))
        elif kind == "units":
            out.append(draw(st.sampled_from(["G20", "G21"])) + " F50.")
        else:
            axes = draw(st.lists(st.sampled_from("XYZAB"), min_size=1, max_size=4, unique=True))
            if kind == "rapid":
                number += "G0 "
            words = [f"{axis}{draw(numbers())}" for axis in axes]
            if draw(st.booleans()):
                feed = draw(numbers()).lstrip("-")
                words.append(f"F{feed}" if feed.strip("0.") else "F100.")
            out.append(number + " ".join(words))
    return out


def _run(program: list[str], target: str) -> str:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    setup = MachineSetup()
    setup.output.normalize = target == "fanuc"
    try:
        translate([line + "\n" for line in program], out, file="p.nc", source="fanuc", target=target,
                  diagnostics=diagnostics, setup=setup)
    except ErrorList as err:
        return "errors:\n" + str(err)
    return out.getvalue() + "\n".join(str(w) for w in diagnostics.warnings)


@pytest.mark.parametrize("target", TARGETS)
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(program=lines())
@example(program=["G21", "G90", "G1 F100.", "N10 X1.5 Y-2.25 Z0.001 F1200."])
@example(program=["G21", "G91", "G1 F100.", "X0.0000001", "X1.5"])
def test_straight_path_writes_what_generate_writes(program: list[str], target: str,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    writer = _writer(target)
    fast = _run(program, target)
    with monkeypatch.context() as patch:
        patch.setattr(writer, "STRAIGHT_OVERRIDES", frozenset())
        assert not writer.straight_path() and (target != "fanuc" or not writer.straight_path(COPY_METHODS))
        slow = _run(program, target)
    assert fast == slow


@pytest.mark.parametrize("target", TARGETS)
def test_cam_blocks_take_the_straight_path(target: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """The path is on for the shipped writers, and a CAM program's straight blocks take it (the test
    above would pass with the path never taken)."""
    writer_class = _writer(target)
    assert writer_class.straight_path(COPY_METHODS if target == "fanuc" else ())
    taken: list[str] = []

    class Counting(writer_class):  # type: ignore[valid-type,misc]
        def straight_move(self, block: Block) -> str | None:
            text = super().straight_move(block)
            if text is not None:
                taken.append(text)
            return text

    monkeypatch.setattr(default_registry().dialect(target), "WRITER", Counting)
    program = ["G21 G90 G17", "G0 X0. Y0.", "N10 G1 Z-1. F300.", "N20 X10.5 Y2.25", "N30 X-3.125 Y0.5 F1200.",
               "X0.000001 Y7.", "N40 Y8.5 Z-1.5", "G0 X5.", "N50 X2."]
    out = _run(program, target)
    if target == "fanuc":  # normalised back: every block of a move (motion code or not) is its source line
        assert taken == [line + "\n" for line in program[1:]]
    else:
        assert taken == ["N20 G1 X10.5 Y2.25\n", "N30 G1 X-3.125 Y0.5 F1200.\n", "G1 X0.000001 Y7.\n",
                         "N40 G1 Y8.5 Z-1.5\n", "N50 G0 X2.\n"]
    assert all(line in out for line in taken)


class _Overriding(WordWriter):
    """A plugin writer that overrides how motion is written and says nothing about straight moves."""

    def motion_words(self, s: object, block: Block) -> list[str]:  # type: ignore[override]
        return ["G1", "X0."]


class _DeclaringBase(WordWriter):
    """Declares its own ``motion_words`` agrees with the base."""

    STRAIGHT_OVERRIDES = frozenset({"motion_words"})

    def motion_words(self, s: object, block: Block) -> list[str]:  # type: ignore[override]
        return super().motion_words(s, block)  # type: ignore[arg-type]


class _OverridingAgain(_DeclaringBase):
    """Overrides ``motion_words`` again: its parent's declaration does not speak for it."""

    def motion_words(self, s: object, block: Block) -> list[str]:  # type: ignore[override]
        return ["G1", "X0."]


def test_an_undeclared_override_turns_the_path_off() -> None:
    assert WordWriter.straight_path()
    assert not _Overriding.straight_path()
    assert _DeclaringBase.straight_path()
    assert not _OverridingAgain.straight_path()


def test_canonical_numbers_have_at_most_max_places() -> None:
    """``straight_move`` relies on it: a writer exact to ``MAX_PLACES`` places writes every canonical number
    as written, so only its magnitude is tested (``postproc.numbers.SHORT_RANGE``)."""
    from postproc.numbers import CANONICAL_BLOCK, MAX_PLACES
    from postproc.rs274.canonical_line import by_regex, scan

    most, more = "X0." + "1" * MAX_PLACES, "X0." + "1" * (MAX_PLACES + 1)
    assert CANONICAL_BLOCK.fullmatch(most) and not CANONICAL_BLOCK.fullmatch(more)
    assert scan(most) and not scan(more) and by_regex(most) and not by_regex(more)
