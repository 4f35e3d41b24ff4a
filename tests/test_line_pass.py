"""The straight and copy lanes' texts pass the target's line rule by their length alone (``Lane.passes_below``,
set by ``postproc.fast.lane.passes_below``): the writer then gives such a text to no rule.

Held two ways on random programs of canonical blocks, long ones among them (a block number of many digits,
numbers of many places: no text of the lane reaches grbl's 79 kept characters, ``LONG``): every text a lane writes shorter than its
``passes_below`` passes the rule's own ``fits`` (the claim itself), and a translation with the lengths known
writes what one without them writes (every text through the rule), warnings and errors included."""

from __future__ import annotations

import io

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import postproc.fast.lane
from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.fast.straight import CopyLane, SourceLane, StraightLane
from postproc.ir import Block
from postproc.numbers import CANONICAL_BLOCK
from postproc.output.line_format import LineRule
from postproc.output.writer_base import Lane, Writer
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup

TARGETS = ("grbl", "grblhal", "linuxcnc")
"""Targets whose line rule a lane's length tells (grbl's and grblHAL's ``GrblLines``, LinuxCNC's
``ByteLengthLines``)."""


@st.composite
def number(draw: st.DrawFn) -> str:
    """A canonical number (``X12.5``'s ``12.5``), up to six whole digits (some outside the lane's range) and
    six places."""
    whole = draw(st.integers(min_value=-999999, max_value=999999))
    places = draw(st.integers(min_value=0, max_value=6))
    frac = "".join(draw(st.lists(st.sampled_from("0123456789"), min_size=places, max_size=places))).rstrip("0")
    if whole == 0 and draw(st.booleans()) and frac:
        return f"-0.{frac}"
    return f"{whole}.{frac}"


@st.composite
def program(draw: st.DrawFn) -> list[str]:
    """Straight moves, mostly canonical and some long (a block number of up to 7 digits: grbl refuses one over
    10,000,000), maybe in inches,
    with a line end of LF, CR LF or CR; now and then a comment or an arc (the general path's)."""
    out = [draw(st.sampled_from(["G21 G90", "G20 G90"])), "G1 F100."]
    for _ in range(draw(st.integers(min_value=1, max_value=10))):
        kind = draw(st.sampled_from(["move"] * 8 + ["comment", "arc"]))
        digits = draw(st.integers(min_value=0, max_value=7))
        head = f"N{draw(st.integers(min_value=10 ** (digits - 1), max_value=10 ** digits - 1))} " if digits else ""
        if kind == "comment":
            out.append(head + "G1 X1. (A COMMENT OF SOME LENGTH, WITH A '?' IN IT, WHICH GRBL ACTS ON)")
        elif kind == "arc":
            out.extend(["G0 X0. Y0.", head + "G2 X2. Y0. I1. J0."])
        else:
            axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
            code = draw(st.sampled_from(["", "", "G1 ", "G0 ", "G01 "]))
            words = [f"{axis}{draw(number())}" for axis in sorted(axes)]
            if draw(st.booleans()):
                words.append(f"F{draw(number()).lstrip('-')}".replace("F0.", "F100.").replace("F-", "F"))
            out.append(head + code + " ".join(words))
    return out


def _run(lines: list[str], target: str, eol: str) -> str:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    try:
        translate([line + eol for line in lines], out, file="p.nc", source="fanuc", target=target,
                  diagnostics=diagnostics, setup=MachineSetup())
    except ErrorList as err:
        return "errors:\n" + str(err)
    return out.getvalue() + "\n".join(str(w) for w in diagnostics.warnings)


def _rule(target: str) -> LineRule:
    rule = getattr(default_registry().dialect(target), "LINE_RULE", None)
    assert isinstance(rule, LineRule)
    return rule


LONG = ["G21 G90", "G1 F100.", "N9999999 G1 X-999999.999999 Y-999999.999999 Z-999999.999999 F999999.999999",
        "N9999999 X-999999.999999 Y-999999.999999 Z-999999.999999 F999999.999999",
        "N1234567 X-123456.123456 Y-123456.123456 Z-123456.123456"]
"""The longest blocks the straight lane writes for grbl (numbers of the lane's range, ``numbers.SHORT_RANGE``,
and a block number grbl takes, at most 10,000,000): 74 characters and a line end, under grbl's 79."""


@pytest.mark.parametrize("target", TARGETS)
@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(lines=program(), eol=st.sampled_from(["\n", "\r\n", "\r"]))
@example(lines=LONG, eol="\n")
@example(lines=LONG, eol="\r\n")
def test_a_lane_text_shorter_than_passes_below_passes_the_rule(lines: list[str], eol: str, target: str,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    rule = _rule(target)
    checked: list[str] = []
    install = postproc.fast.lane.install

    def watching(writer: Writer) -> None:
        install(writer)
        lane = writer.lane
        assert lane is not None and lane.passes_below > 0

        class Watched(Lane):
            def write(self, block: Block) -> str | None:
                assert lane is not None
                text = lane.write(block)
                if text is not None and len(text) < lane.passes_below:
                    body = text.rstrip("\r\n")
                    assert CANONICAL_BLOCK.fullmatch(body) and text[len(body):] in ("\n", "\r\n", "\r"), text
                    assert rule.fits(text), text
                    checked.append(text)
                return text
        watched = Watched()
        watched.passes_below = lane.passes_below
        writer.lane = watched

    monkeypatch.setattr(postproc.fast.lane, "install", watching)
    _run(lines, target, eol)
    if lines is LONG:
        assert len(checked) == 3


@pytest.mark.parametrize("target", TARGETS)
@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(lines=program(), eol=st.sampled_from(["\n", "\r\n", "\r"]))
@example(lines=LONG, eol="\n")
@example(lines=LONG, eol="\r")
def test_lengths_known_write_what_the_rule_writes(lines: list[str], eol: str, target: str,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    known = _run(lines, target, eol)
    with monkeypatch.context() as patch:
        patch.setattr(postproc.fast.lane, "passes_below", lambda lane, rule: 0)
        ruled = _run(lines, target, eol)
    assert known == ruled


def _lane(target: str, source: str = "fanuc", normalize: bool = False) -> Lane | None:
    dialect = default_registry().dialect(target)
    setup = MachineSetup()
    setup.output.normalize = normalize
    ctx = default_registry().dialect(source).context("p.nc", setup, Diagnostics())
    writer = dialect.WRITER(ctx, source, dialect)  # type: ignore[misc]
    postproc.fast.lane.install(writer)
    return writer.lane


def test_the_lengths_of_the_shipped_rules() -> None:
    """grbl keeps 79 characters, grblHAL 256, LinuxCNC 252 bytes; a copy of grbl's own blocks, not canonical
    (``SourceLane``), is looked at by the rule; a target without a rule has nothing to pass."""
    lanes = {target: _lane(target) for target in ("grbl", "grblhal", "linuxcnc", "fanuc")}
    assert {t: (type(lane), lane.passes_below) for t, lane in lanes.items() if lane is not None} == {
        "grbl": (StraightLane, 80), "grblhal": (StraightLane, 257), "linuxcnc": (StraightLane, 253),
        "fanuc": (SourceLane, 0)}
    copy = _lane("grbl", "grbl")
    assert isinstance(copy, SourceLane) and copy.passes_below == 0
    normalized = _lane("grbl", "grbl", normalize=True)
    assert isinstance(normalized, CopyLane) and normalized.passes_below == 80


class _Stricter(LineRule):
    """A rule of a plugin's own: only its ``fits`` can tell."""

    def fits(self, text: str) -> bool:
        return len(text) < 10


def test_a_rule_of_another_class_is_asked_for_every_text() -> None:
    from postproc_grbl.text import LINES

    class Overriding(type(LINES)):  # type: ignore[misc]
        def fits(self, text: str) -> bool:
            return False

    lane = _lane("grbl")
    assert lane is not None
    assert postproc.fast.lane.passes_below(lane, _Stricter()) == 0
    assert postproc.fast.lane.passes_below(lane, Overriding("grbl", "grbl 1.1", 80, len, "")) == 0
    assert postproc.fast.lane.passes_below(lane, None) == 0
    assert postproc.fast.lane.passes_below(lane, LINES) == 80
