"""ISG's and the Fagor 8070's cutter compensation (issue 26, deliver 3 asked for it as a path): their manuals' text
names the modes but gives the start-up, corner and cancel constructions in figures only (``dialects/isg/
cutter_rules.py``, ``dialects/fagor/cutter_rules.py``), so compensation stays a setting, and verify says why; the
mode codes (ISG ``G25``/``G26``/``G138``/``G139``/``G236``-``G239``/``G05``, Fagor ``G136``-``G139``) were unknown G
codes: now kept verbatim, round-tripping in their own dialect and refused elsewhere and by the simulation, by
name."""

from __future__ import annotations

import io

import pytest

from postproc.errors import ErrorList
from postproc.simulate.verify import verify_lines
from postproc.api import translate
from tests.support.tools import with_tools

ISG = "G17 G90 G71\nG0 X0 Y0\n{code}\nG41 D1 G1 X10 F100\nG1 Y10\nG40 G1 X0\nM30\n"
FAGOR = ISG

ISG_CODES = {"G25": "linear transitions at outside corners under radius compensation",
             "G26": "circular transitions at outside corners under radius compensation",
             "G138": "direct selection of radius compensation", "G139": "indirect selection of radius compensation",
             "G236": "direct selection of radius compensation on the path",
             "G237": "perpendicular selection of radius compensation",
             "G238": "selection of radius compensation at an inside corner",
             "G239": "selection of radius compensation without a block",
             "G05": "tangential selection of radius compensation"}
FAGOR_CODES = {"G136": "circular transitions between radius-compensated paths",
               "G137": "linear transitions between radius-compensated paths",
               "G138": "direct start and end of radius compensation",
               "G139": "indirect start and end of radius compensation"}


def _translate(text: str, source: str, target: str, radii: dict[int, float] | None = None) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="a", source=source, target=target, setup=with_tools(radii=radii))
    return out.getvalue()


@pytest.mark.parametrize(("dialect", "code", "meaning"), [("isg", c, m) for c, m in ISG_CODES.items()]
                         + [("fagor", c, m) for c, m in FAGOR_CODES.items()])
def test_a_mode_code_round_trips_and_is_refused_elsewhere_by_name(dialect: str, code: str, meaning: str) -> None:
    text = ISG.format(code=code)
    assert code in _translate(text, dialect, dialect).splitlines()
    with pytest.raises(ErrorList) as err:
        _translate(text, dialect, "linuxcnc")
    named = "G5" if code == "G05" else code  # (the message names the code by its number)
    assert any(e.message == f"{named} ({meaning}) from {dialect} has no equivalent in linuxcnc" for e in err.value.errors)


@pytest.mark.parametrize("dialect", ["isg", "fagor"])
def test_the_simulation_refuses_a_mode_code_by_name(dialect: str) -> None:
    code = "G26" if dialect == "isg" else "G136"
    text = ISG.format(code=code)
    with pytest.raises(ErrorList) as err:
        verify_lines(io.StringIO(text), io.StringIO(text), file_in="a", file_out="b", source=dialect, target=dialect,
                     setup=with_tools())
    assert any(e.message.startswith(f"{code} (") and e.message.endswith("cannot be simulated") for e in err.value.errors)


@pytest.mark.parametrize(("dialect", "why"), [
    ("isg", "its start-up and cancel moves (the selection methods G139, its initial state, and G138) are given by "
            "figures only in the TF5200 programming manual [?]: dialects/isg/cutter_rules.py"),
    ("fagor", "its start, corner and cancel constructions (G136/G137, G138/G139) are given by figures only in the "
              "8070 programming manual [?]: dialects/fagor/cutter_rules.py"),
])
def test_verify_says_why_the_compensation_is_a_setting(dialect: str, why: str) -> None:
    fanuc = "G21 G90 G17\nG00 X0 Y0\nG41 D01 G01 X10. F100.\nY10.\nG40 G00 X0 Y0\nM30\n"
    out = _translate(fanuc, "fanuc", dialect)
    assert "G41" in out  # kept native: both families have it
    report = verify_lines(io.StringIO(fanuc), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target=dialect, setup=with_tools())
    assert report.ok
    assert report.ignored[-1] == f"cutter compensation under {dialect}'s rules: compared as a setting, not as a path: {why}"


def test_no_note_where_the_compensation_is_a_path() -> None:
    # Fanuc to LinuxCNC: both sides simulated under their own rules, compared as paths
    fanuc = "G21 G90 G17\nG00 X0 Y0\nG41 D01 G01 X10. F100.\nY10.\nG40 G00 X0 Y0\nM30\n"
    out = _translate(fanuc, "fanuc", "linuxcnc", radii={1: 2.0})
    report = verify_lines(io.StringIO(fanuc), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="linuxcnc", setup=with_tools(radii={1: 2.0}))
    assert report.ok and not any("compared as a setting" in line for line in report.ignored)
