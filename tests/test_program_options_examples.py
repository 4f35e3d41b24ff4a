"""Every bundled mill example under ``--units`` and ``--transform`` (issue #27's done-when: their outputs verify
against their sources with the same transform, on the bundled examples): back to its own dialect, converted to
the other units, and moved by a shift with a Z part (its reference returns kept: ``postproc.transforms.carry``)
and by a rotation about a point. ``verify`` is the check (the transform's comparison is not vacuous:
``tests/test_transforms_verify.py``, ``test_verify_fails_with_another_transform``). The lathe examples:
``tests/test_frames_lathe_units.py`` and ``tests/test_transforms_lathe.py``; ``--arcs``: ``tests/test_arcs_examples.py``.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines
from postproc.transforms import parse_transform

ROOT = Path(__file__).resolve().parents[1]
TOUCHED_OFF = str(ROOT / "examples" / "setups" / "router_tools_touched_off.xml")
EXAMPLES = [(p, dialect) for folder, dialect, pattern in (("fanuc", "fanuc", "*.nc"), ("linuxcnc", "linuxcnc", "*.ngc"),
                                                          ("isg", "isg", "*.nc"), ("fagor", "fagor", "*.nc"),
                                                          ("siemens", "siemens", "*.mpf"))
            for p in sorted((ROOT / "examples" / folder).glob(pattern))]
MOVE = "rotate 30 about 10,20; translate 2,-3,-1"
REFUSED = {
    ("prof_open_close.nc", "units"): "#SLOPE (acceleration profile)",  # ISG's command kept as written
    ("prof_open_close.nc", "transform"): "#SLOPE (acceleration profile)",
    ("o1003_pocket_and_edge.nc", "transform"): "an arc in the ZX plane cannot be transformed by this map",
}
"""(example, option) -> what the located refusal names."""


@pytest.mark.parametrize("option", ["units", "transform"])
@pytest.mark.parametrize("path, dialect", EXAMPLES, ids=[p.name for p, _ in EXAMPLES])
def test_a_bundled_example_verifies_under_the_option(path: Path, dialect: str, option: str) -> None:
    text = path.read_text(encoding="utf-8")
    inch = any(code in text.upper().split() for code in ("G20", "G70"))
    options: dict[str, Any] = {"units": "mm" if inch else "inch"} if option == "units" else {"transform": MOVE}
    out = io.StringIO(newline="")
    try:
        translate(io.StringIO(text, newline=""), out, file=path.name, source=dialect, target=dialect,
                  setup=load_setup(TOUCHED_OFF), on_unsupported="warn",
                  diagnostics=Diagnostics(warn_stream=io.StringIO()), **options)
    except ErrorList as err:
        refusal = REFUSED.get((path.name, option))
        assert refusal is not None and refusal in str(err.errors[0]), err.errors
        assert str(err.errors[0]).startswith(f"{path.name}:")  # located
        return
    assert (path.name, option) not in REFUSED
    transform = parse_transform(MOVE) if option == "transform" else None
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out.getvalue(), newline=""), file_in="a",
                          file_out="b", source=dialect, target=dialect, setup=load_setup(TOUCHED_OFF),
                          allow_ignored=True, transform=transform)
    assert report.ok and report.moves >= 5, report.summary() + "\n" + out.getvalue()
