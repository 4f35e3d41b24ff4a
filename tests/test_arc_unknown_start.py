"""An arc whose absolute end word in its plane meets a start unknown on that axis (found this session: after
``G1 X10. Z-1.`` with Y never programmed, ``G2 X20. Y5. I5. J0.`` was translated to LinuxCNC with exit 0, and
rs274 refused it, "Radius to end of arc differs from radius to start").

The controller checks such an arc from wherever the machine stands, so it accepts it about one place only:
the translation to another dialect refuses it with a located error (program the axis first). An arc whose
shape does not depend on the unknown start (the axis not in its end words, or incremental) is still
translated, and rs274 runs it; a copy to the source's own dialect runs as the source does and is kept."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from tests.support.rs274 import RS274Error, available, run_rs274

needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

UNKNOWN_Y = "G21 G90 G17\nG1 X10. Z-1. F100.\nG2 X20. Y5. I5. J0.\nM30\n"
"""Y never programmed before an arc that ends at an absolute Y (valid only from Y5)."""


def _translate(program: str, source: str = "fanuc", target: str = "linuxcnc") -> str:
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source=source, target=target)
    return out.getvalue()


@needs_rs274
def test_rs274_refuses_the_arc_from_its_start() -> None:
    """The oracle: this NGC text is what the translation wrote before the fix."""
    with pytest.raises(RS274Error, match="Radius to end of arc differs"):
        run_rs274(UNKNOWN_Y)


@pytest.mark.parametrize("source", ["fanuc", "linuxcnc"])
@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "fanuc"])
def test_an_arc_from_an_unknown_start_is_refused_where_it_was_read(source: str, target: str) -> None:
    if source == target:
        assert _translate(UNKNOWN_Y, source, target) == UNKNOWN_Y  # a copy: the source's controller's case
        return
    with pytest.raises(ErrorList) as info:
        _translate(UNKNOWN_Y, source, target)
    assert str(info.value).startswith(f"in.nc:3:9: error: the arc ends at an absolute Y from a start whose Y "
                                      f"is unknown")
    assert f"the {target} controller checks the arc" in str(info.value)


@needs_rs274
@pytest.mark.parametrize("arc", ["G2 X20. I5. J0.", "G91 G2 X10. Y0. I5. J0."])
def test_an_arc_whose_shape_does_not_depend_on_the_unknown_start_runs(arc: str) -> None:
    """Y kept (absent or incremental): the same half circle from any Y; rs274 runs the translation."""
    run_rs274(_translate(f"G21 G90 G17\nG1 X10. Z-1. F100.\n{arc}\nM30\n"))  # RS274Error if refused


def test_an_absolute_end_that_fits_one_start_is_refused_too() -> None:
    """``Y0.`` fits only a machine standing at Y0 (where rs274 starts, and the set-up's start for the
    simulation): the real controller stands wherever the last job left it, so the translation asks for Y."""
    with pytest.raises(ErrorList, match="program Y before the arc"):
        _translate("G21 G90 G17\nG1 X10. Z-1. F100.\nG2 X20. Y0. I5. J0.\nM30\n")


def test_after_a_refused_arc_the_next_is_its_consequence() -> None:
    """The refused arc leaves Y unknown: the next arc's unknown start is not a second error."""
    program = "G21 G90 G17\nG0 X10. Y0.\nG1 F100.\nG2 X-10.02 Y0. I-10. J0.\nG2 X0. Y10.01 I10.01 J0.\nM30\n"
    with pytest.raises(ErrorList) as info:
        _translate(program, "linuxcnc", "fanuc")
    assert [str(e).split(": error: ")[0] for e in info.value.errors] == ["in.nc:4:16"]


@needs_rs274
def test_an_arc_after_y_is_programmed_runs() -> None:
    program = "G21 G90 G17\nG1 X10. Y5. Z-1. F100.\nG2 X20. Y5. I5. J0.\nM30\n"
    run_rs274(_translate(program))


SUB_FIRST = ("o100 sub\nG2 X10 Y0 I5 J0 F100\no100 endsub\nG17 G21 G90 G0 X0 Y0 Z5\nG1 Z-1 F100\no100 call\n"
             "M2\n")
"""A subprogram defined before the moves that call it: in the order of the text its arc comes first, with X and Y
unknown; run, it starts at X0 Y0, on its circle (radius 5 at both ends, by hand)."""


@needs_rs274
def test_an_arc_read_before_the_moves_that_run_first_is_not_refused() -> None:
    """Where the text is not the order of execution (a call, a loop, a computed word), the start is the run's to
    know: the arc is not refused on the text's order (it was, for this valid LinuxCNC program, before the check
    left such programs to the run), and rs274 runs the translation."""
    run_rs274(SUB_FIRST)  # the source is valid LinuxCNC
    out = _translate(SUB_FIRST, source="linuxcnc", target="fanuc")
    assert "G02 X10. Y0. I5. J0." in out
