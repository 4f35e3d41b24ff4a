"""``<Output addressDecimals inchAddressDecimals>``: places per address, honoured by every writer.

Each output is read back by the target's reader and verified against the source. Rounding to fewer
places is a real change: a program whose values lie on the grid of the places verifies at zero
deviation; one whose values do not deviates by at most half a unit of the last place (derived by hand
below), and each address that rounding moved is warned about once.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import read_program, translate
from postproc.errors import ConfigError, Diagnostics, ErrorLevel
from postproc.setup.machine_setup import MachineSetup, OutputSettings, load_setup
from postproc.simulate.verify import verify_lines

WRITERS = ["fanuc", "linuxcnc", "grbl", "mach3", "isg", "fagor"]
ON_GRID = """G21 G90 G17
S1200 M3
G0 X12.5 Y-3.25 Z5.
G1 Z-1.5 F250.
G2 X22.5 Y-3.25 I5. J0.
G91 G1 X0.75 Y0.25
G90 G0 Z5.
M30
"""
"""Every length on the 0.01 mm grid, feeds and speeds whole."""
OFF_GRID = """G21 G90 G17
G0 X1.23456 Y2.5 Z5.
G1 Z-1.2345 F250.
G91 G1 X0.33333
Y0.33333
X0.33333
Y0.33334
X0.33334
G90 G0 Z5.
M30
"""
"""Values that two places cannot hold; the X increments sum to exactly 1 mm. (The moves turn at each
block: rounding three collinear increments would bend the line, which ``verify`` reports as another
structure, not as a deviation.)"""


def _translate(text: str, target: str, setup: MachineSetup) -> tuple[str, Diagnostics]:
    out = io.StringIO()
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text), out, file="p.nc", source="fanuc", target=target, setup=setup,
              diagnostics=diagnostics)
    read_program(io.StringIO(out.getvalue()), file="out", dialect=target, setup=setup)  # the target reads it
    return out.getvalue(), diagnostics


def _deviation(text: str, written: str, target: str, setup: MachineSetup, tolerance: float) -> float:
    report = verify_lines(io.StringIO(text), io.StringIO(written), file_in="p.nc", file_out="o.nc",
                          source="fanuc", target=target, setup=setup, tolerance=tolerance)
    assert report.ok, report.summary()
    return report.max_deviation


def _words(text: str, letter: str) -> list[str]:
    return [w for line in text.splitlines() if not line.startswith(("(", ";"))
            for w in line.split() if w[:1] == letter and len(w) > 1 and w[1] in "-.0123456789"]


@pytest.mark.parametrize("target", WRITERS)
def test_values_on_the_grid_verify_at_zero(target: str) -> None:
    setup = MachineSetup(output=OutputSettings(address_decimals="XYZIJ2 F0 S0"))
    written, diagnostics = _translate(ON_GRID, target, setup)
    assert _deviation(ON_GRID, written, target, setup, 0.0) == 0.0
    assert not [w for w in diagnostics.warnings if "rounded" in w.message]
    assert "X12.5" in _words(written, "X") or "X12.50" in _words(written, "X")
    assert _words(written, "F") == ["F250."]
    assert _words(written, "S") == ["S1200"]  # no decimal point: S0


@pytest.mark.parametrize("target", WRITERS)
def test_fewer_places_round_within_half_a_unit_and_warn_once_per_address(target: str) -> None:
    setup = MachineSetup(output=OutputSettings(address_decimals="XYZ2"))
    written, diagnostics = _translate(OFF_GRID, target, setup)
    # X1.23456 -> 1.23 (0.00456 off), Z-1.2345 -> -1.23 (0.0045 off): the largest deviation is a point
    # off by (0.00456, 0, 0.0045) at most, within the 0.005 mm of two places on each axis
    deviation = _deviation(OFF_GRID, written, target, setup, 0.005 * 3 ** 0.5)
    assert 0.0045 <= deviation <= 0.005 * 3 ** 0.5
    rounded = sorted(w.message.split(":")[1].split()[0] for w in diagnostics.warnings if "is rounded" in w.message)
    assert rounded == ["X", "Y", "Z"]  # once each, however many words it rounds
    # rounding never accumulates in incremental mode: written increments sum to the source's 1 mm
    increments = [float(w[1:]) for w in _words(written.split("G91", 1)[1].split("G90", 1)[0], "X")]
    assert len(increments) == 3 and sum(increments) == pytest.approx(1.0, abs=1e-9)
    assert all(len(w.split(".")[1].rstrip("0")) <= 2 for w in _words(written, "X") + _words(written, "Y"))


def test_inch_programs_take_their_own_places() -> None:
    text = "G20 G90 G17\nG0 X1.23456 Y0.5\nG1 X2. F10.\nM30\n"
    setup = MachineSetup(output=OutputSettings(address_decimals="X1", inch_address_decimals="X3"))
    written, _ = _translate(text, "linuxcnc", setup)
    assert _words(written, "X") == ["X1.235", "X2."]
    # 1.23456 in -> 1.235 in: 0.00044 in = 0.011176 mm, within half of 0.001 in (0.0127 mm)
    deviation = _deviation(text, written, "linuxcnc", setup, 0.0005 * 25.4)
    assert deviation == pytest.approx(0.00044 * 25.4, abs=1e-6)


def test_mach3_keeps_its_fixed_width_with_the_set_ups_places() -> None:
    setup = MachineSetup(output=OutputSettings(address_decimals="XYZIJ3"))
    written, _ = _translate(ON_GRID, "mach3", setup)
    assert "G0 X12.500 Y-3.250 Z5.000" in written


def test_a_same_dialect_program_is_rewritten_with_the_places() -> None:
    """Decimals per address imply normalizing: a block is not copied with the places it had."""
    setup = MachineSetup(output=OutputSettings(address_decimals="XYZ2 F0"))
    written, _ = _translate("G21 G90\nG1 X1.23456 Y2. F100.7\nM30\n", "fanuc", setup)
    assert written.splitlines()[1] == "G1 X1.23 Y2. F101."


@pytest.mark.parametrize("value, message", [
    ("XYZ7", "at most 6 places"),
    ("N3", "'N' is not one of"),
    ("x3", "'x' is not one of"),
    ("X3 X2", "X is given twice"),
    ("3", "each entry is address letters then places"),
    ("XY", "each entry is address letters then places"),
])
def test_bad_entries_are_located_errors(tmp_path: Path, value: str, message: str) -> None:
    path = tmp_path / "m.xml"
    path.write_text(f'<MachineSetup>\n  <Output addressDecimals="{value}"/>\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as info:
        load_setup(path)
    assert message in str(info.value) and f"{path}:2:" in str(info.value)


def test_inch_places_go_to_seven(tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text('<MachineSetup>\n  <Output inchAddressDecimals="XYZ7 F8"/>\n</MachineSetup>\n')
    with pytest.raises(ConfigError, match="at most 7 places"):
        load_setup(path)
    path.write_text('<MachineSetup>\n  <Output inchAddressDecimals="XYZ7 F2"/>\n</MachineSetup>\n')
    assert load_setup(path).output.address_places(inch=True) == {"X": 7, "Y": 7, "Z": 7, "F": 2}
