"""Subprogram identity across dialects (issue #31, items 2 and 3): the definition and every call of a
subprogram say the same name in the target (``postproc.interp.subprogram_names``), and the definition has the
form its calls need.

Expected texts are derived by hand from the rules: Fanuc programs are ``O0001``-``O9999`` and a name gets
the first free number from 2000; rs274 runs ``O<n>`` .. ``M99`` only by ``M98`` and ``o<n> sub`` only by
``o<n> call`` ("Fanuc 'O....' subroutine must be called with 'M98'", RS274_NOTES.md). Each output is read
back by the target's reader and compared with ``verify``; LinuxCNC outputs also run in rs274.
"""

from __future__ import annotations

import io
import math
import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, UnsupportedError
from postproc.interp.subprogram_names import NameRule, SubprogramNames
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274

FANUC = NameRule(numbers=range(1, 10000), spare=range(2000, 8000), names=False)
needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _translate(text: str, source: str, target: str) -> tuple[str, str]:
    out = io.StringIO(newline="")
    warnings = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def _verified(text: str, out: str, source: str, target: str) -> None:
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="out.nc",
                          source=source, target=target, tolerance=0.0)
    assert report.ok, report.summary()


def _same_in_rs274(fanuc: str, ngc: str) -> None:
    ours = [e for e in toolpath_events(io.StringIO(fanuc), file="in.nc", dialect="fanuc") if "move" in e]
    theirs = [e for e in canonical_moves(run_rs274(ngc), start=(0.0, 0.0, 0.0)) if "move" in e]
    assert len(ours) == len(theirs)
    for a, b in zip(ours, theirs):
        assert a["move"] == b["move"] and math.dist((a["x"], a["y"], a["z"]), (b["x"], b["y"], b["z"])) < 2e-4


# -- the names -----------------------------------------------------------------------------------------

def test_a_number_fanuc_can_write_stays_and_the_others_get_spare_ones_in_order() -> None:
    names = SubprogramNames(FANUC)
    assert [names.of(n) for n in ("100", "<probe>", "12345", "100", "<probe>", "9999")] == [
        "100", "2000", "2001", "100", "2000", "9999"]


def test_a_number_already_given_to_another_subprogram_is_refused() -> None:
    names = SubprogramNames(FANUC)
    names.of("<probe>")
    with pytest.raises(UnsupportedError, match=r"subprogram 2000 \(its number is already given to subprogram "
                                               r"<probe>\)"):
        names.of("2000")


def test_a_computed_call_is_refused_once_a_number_changed_and_the_other_way_round() -> None:
    names = SubprogramNames(FANUC)
    names.of("12345")
    with pytest.raises(UnsupportedError, match="computed program number after subprogram 12345 was numbered 2000"):
        names.computed()
    names = SubprogramNames(FANUC)
    names.computed()
    with pytest.raises(UnsupportedError, match="subprogram 12345 numbered 2000 after a call of a computed"):
        names.of("12345")


def test_one_kind_rules_refuse_a_subprogram_called_both_ways() -> None:
    names = SubprogramNames(NameRule(numbers=range(0, 100), spare=range(0), names=True, one_kind=True))
    assert names.use("7", "sub", "M98 on line 2") == "7"
    assert names.kind("7") == "sub"
    with pytest.raises(UnsupportedError, match="G65 on line 3 of subprogram 7 after M98 on line 2"):
        names.use("7", "macro", "G65 on line 3")


# -- LinuxCNC -> Fanuc (item 2) ---------------------------------------------------------------------------

def test_a_numbered_o_word_subprogram_and_its_call_say_the_same_fanuc_number() -> None:
    ngc = "o100 sub\nG1 X#1 F100\no100 endsub\nG21 G90 G0 X0 Y0 Z5\no100 call [2]\nM2\n"
    out, warnings = _translate(ngc, "linuxcnc", "fanuc")
    assert warnings == ""
    assert out == "G21 G90 G00 X0. Y0. Z5.\nG65 P100 A2.\nM02\nO0100\nG01 X#1 F100.\nM99\n"
    _verified(ngc, out, "linuxcnc", "fanuc")


def test_numbers_fanuc_cannot_write_and_names_get_spare_numbers_for_definition_and_calls() -> None:
    ngc = ("o<probe> sub\nG1 X#1 F100\no<probe> endsub\no12345 sub\nG1 Y#1 F100\no12345 endsub\n"
           "G21 G90 G0 X0 Y0 Z5\no12345 call [3]\no<probe> call [2]\nM2\n")
    out, warnings = _translate(ngc, "linuxcnc", "fanuc")
    assert warnings == ""
    assert out == ("G21 G90 G00 X0. Y0. Z5.\nG65 P2001 A3.\nG65 P2000 A2.\nM02\n"
                   "O2000\nG01 X#1 F100.\nM99\nO2001\nG01 Y#1 F100.\nM99\n")
    _verified(ngc, out, "linuxcnc", "fanuc")


def test_a_number_taken_by_a_named_subprogram_first_is_flattened_with_the_reason() -> None:
    ngc = ("o<probe> sub\nG1 X#1 F100\no<probe> endsub\no2000 sub\nG1 Z#1 F100\no2000 endsub\n"
           "G21 G90 G0 X0 Y0 Z5\no<probe> call [2]\no2000 call [4]\nM2\n")
    out, warnings = _translate(ngc, "linuxcnc", "fanuc")
    assert "subprogram 2000 (its number is already given to subprogram <probe>)" in warnings
    assert "G65" not in out and "O2000" not in out
    _verified(ngc, out, "linuxcnc", "fanuc")


# -- Fanuc -> LinuxCNC (item 3) ---------------------------------------------------------------------------

G65_FANUC = ("%\nO0001\nG21 G90 G0 X0 Y0 Z5.\nG65 P9001 A2. B3.\nG65 P9001 A-1.5 B1.\nM30\n"
             "O9001\nWHILE [#2 GT 0] DO1\nG91 G1 X#1 F100.\n#2=#2-1\nEND1\nG90\nM99\n%\n")


def test_a_program_called_by_g65_is_written_as_an_o_word_subprogram() -> None:
    out, warnings = _translate(G65_FANUC, "fanuc", "linuxcnc")
    assert "flattened" not in warnings
    assert "o9001 sub\n" in out and "o9001 call [2.] [3.]\n" in out
    assert out.count("o9001 return\n") == 1 and out.index("o9001 endsub\n") < out.rindex("%")
    assert "O9001" not in out
    _verified(G65_FANUC, out, "fanuc", "linuxcnc")


@needs_rs274
def test_the_o_word_subprogram_runs_in_rs274_as_the_fanuc_program_moves() -> None:
    out, _ = _translate(G65_FANUC, "fanuc", "linuxcnc")
    _same_in_rs274(G65_FANUC, out)


M98_FANUC = ("%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#1=3.\nM98 P9001 L2\nM30\nO9001\nG91 G1 X#1 F100.\nG90\nM99\n%\n")


@needs_rs274
def test_a_program_called_by_m98_stays_an_o_program_and_runs_in_rs274() -> None:
    out, warnings = _translate(M98_FANUC, "fanuc", "linuxcnc")
    assert "M98 P9001 L2\n" in out and "O9001\n" in out and "M99\n" in out and "sub" not in out
    _verified(M98_FANUC, out, "fanuc", "linuxcnc")
    _same_in_rs274(M98_FANUC, out)


def test_a_program_called_both_by_m98_and_g65_is_flattened_naming_both_calls() -> None:
    fanuc = "%\nO0001\nG21 G90 G0 X0 Y0 Z5.\nM98 P9001\nG65 P9001 A2.\nM30\nO9001\nG91 G1 X1. F100.\nG90\nM99\n%\n"
    out, warnings = _translate(fanuc, "fanuc", "linuxcnc")
    assert ("the call on line 5 of subprogram 9001 after the subprogram call (M98) on line 4" in warnings)
    lines = out.splitlines()
    assert not any(line.startswith(("M98", "o")) for line in lines)
    _verified(fanuc, out, "fanuc", "linuxcnc")


# -- to ISG: a numbered subprogram is refused by name, definition and calls alike -------------------------

def test_a_numbered_subprogram_has_no_isg_name_its_definition_and_calls_alike() -> None:
    ngc = "o100 sub\nG1 X1 F100\no100 endsub\nG21 G90 G0 X0 Y0 Z5\no100 call\nM2\n"
    out, warnings = _translate(ngc, "linuxcnc", "isg")
    assert "the isg dialect cannot express the numbered subprogram 100" in warnings
    assert "%L" not in out and "LL" not in out
    _verified(ngc, out, "linuxcnc", "isg")
