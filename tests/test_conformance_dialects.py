"""The conformance suite (``postproc.testing``) run on every installed dialect, as a plugin author runs it.

Each case names a dialect, its example programs, known-bad programs and, for a lathe, the set-up its
examples are read under. Every installed dialect must have a case (a test holds it), so a new
dialect (Fagor, a plugin) joins the suite by adding one line here; hypothesis draws MAX_EXAMPLES
programs per generated check.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from postproc.plugins import default_registry
from postproc.testing import ConformanceTests, DialectUnderTest

ROOT = Path(__file__).resolve().parents[1]
HERE = ROOT / "tests" / "conformance"
ZERO_TOOLS = ROOT / "tests/support/zero_tools.xml"
"""The mill examples set tool length offsets: the simulation needs their registers (measured as zero here)."""

CASES = {
    "fanuc": DialectUnderTest("fanuc", ROOT / "examples/fanuc", ROOT / "tests/golden/fanuc/invalid", ZERO_TOOLS),
    "fanuc-lathe": DialectUnderTest("fanuc", ROOT / "examples/fanuc-lathe", HERE / "fanuc-lathe/invalid",
                                    ROOT / "examples/setups/fanuc_0i_tf.xml", name="fanuc-lathe"),
    "gsk": DialectUnderTest("gsk", ROOT / "examples/gsk", HERE / "gsk/invalid"),
    "isg": DialectUnderTest("isg", ROOT / "examples/isg", HERE / "isg/invalid",
                            ROOT / "examples/setups/isg_twincat_cylinder.xml"),  # prof_open_close.nc: axis U
    "fagor": DialectUnderTest("fagor", ROOT / "examples/fagor", HERE / "fagor/invalid"),
    "siemens": DialectUnderTest("siemens", ROOT / "examples/siemens", HERE / "siemens/invalid",
                                ROOT / "examples/setups/siemens_840d_mill.xml"),
    "linuxcnc": DialectUnderTest("linuxcnc", ROOT / "examples/linuxcnc", HERE / "linuxcnc/invalid", ZERO_TOOLS),
    "grbl": DialectUnderTest("grbl", HERE / "grbl", HERE / "grbl/invalid"),
    "grblhal": DialectUnderTest("grblhal", HERE / "grblhal", HERE / "grblhal/invalid",
                                ROOT / "tests/support/grblhal_expressions.xml"),
    "mach3": DialectUnderTest("mach3", ROOT / "plugins/example_dialect/examples",
                              ROOT / "plugins/example_dialect/examples/invalid", ZERO_TOOLS),
}
"""One case per installed dialect (two for Fanuc: mill and lathe)."""


@pytest.fixture(params=sorted(CASES))
def postproc_conformance(request: pytest.FixtureRequest) -> DialectUnderTest:
    case = CASES[request.param]
    if case.dialect not in default_registry().dialects:
        pytest.skip(f"the {case.dialect} dialect is not installed")
    return case


class TestConformance(ConformanceTests):
    pass


def test_every_installed_dialect_has_a_case() -> None:
    covered = {case.dialect for case in CASES.values()}
    missing = sorted(set(default_registry().dialects) - covered)
    assert not missing, f"installed dialects without a conformance case in {__file__}: {missing}"
