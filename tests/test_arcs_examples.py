"""``--arcs`` on the bundled examples that have arcs: each translation verifies against its source with the
same option (``verify --arcs``), in inches, under frames, in expanded lathe cycles; where the target keeps
a lathe cycle whose profile has arcs, ``lines`` is refused at the arc's line."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.lowering.arcs import parse_arc_option
from postproc.plugins import default_registry
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines

ROUTER = "examples/setups/router_tools_touched_off.xml"
GSK = "examples/setups/gsk_980tdc.xml"
FANUC_LATHE = "examples/setups/fanuc_0i_tf.xml"
CASES = [
    ("examples/fanuc/o1002_bracket_inch.nc", "fanuc", "linuxcnc", ROUTER, ("ijk", "r")),
    ("examples/fanuc/o1002_bracket_inch.nc", "fanuc", "grbl", ROUTER, ("lines:0.01",)),
    ("examples/fanuc/o1003_pocket_and_edge.nc", "fanuc", "linuxcnc", ROUTER, ("ijk", "r")),
    ("examples/fanuc/o1003_pocket_and_edge.nc", "fanuc", "grbl", ROUTER, ("lines:0.01",)),
    ("examples/fanuc/o1006_fixture_frames.nc", "fanuc", "grbl", ROUTER, ("r", "lines:0.005")),
    ("examples/linuxcnc/frames_rotated_origin.ngc", "linuxcnc", "fanuc", ROUTER, ("ijk", "lines:0.01")),
    ("examples/linuxcnc/cover_profile.ngc", "linuxcnc", "linuxcnc", ROUTER, ("r", "lines:0.01")),
    ("examples/gsk/o0101_stepped_shaft.nc", "gsk", "linuxcnc", GSK, ("r", "lines:0.01")),
    ("examples/gsk/o0101_stepped_shaft.nc", "gsk", "fanuc", GSK, ("ijk", "r")),
    ("examples/fanuc-lathe/o2001_stepped_shaft.nc", "fanuc", "gsk", FANUC_LATHE, ("ijk", "r")),
]


def _setup(root, path):
    return load_setup(str(root / path), groups=default_registry().setup_groups)


@pytest.mark.parametrize("path, source, target, machine, forms", CASES,
                         ids=[f"{c[0].split('/')[-1]}-{c[2]}" for c in CASES])
def test_example_translations_verify_with_the_same_option(root, path, source, target, machine, forms) -> None:
    text = (root / path).read_text()
    for form in forms:
        setup = _setup(root, machine)
        out = io.StringIO()
        translate(io.StringIO(text), out, file=path, source=source, target=target, setup=setup,
                  arcs=parse_arc_option(form), diagnostics=Diagnostics(warn_stream=io.StringIO()))
        option = parse_arc_option(form)
        report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in=path, file_out="out",
                              source=source, target=target, setup=_setup(root, machine),
                              chord_tolerance=option.tolerance if option.form == "lines" else None)
        assert report.ok, f"--arcs {form}: {report.summary()}"


def test_lines_in_a_kept_lathe_profile_is_refused_at_the_arc(root) -> None:
    path = "examples/fanuc-lathe/o2001_stepped_shaft.nc"
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO((root / path).read_text()), io.StringIO(), file=path, source="fanuc", target="gsk",
                  setup=_setup(root, FANUC_LATHE), arcs=parse_arc_option("lines:0.01"))
    message = str(info.value.errors[0])
    assert message.startswith(f"{path}:18:") and "profile of a lathe cycle" in message
    assert "G03" in (root / path).read_text().splitlines()[17] or "G02" in (root / path).read_text().splitlines()[17]
