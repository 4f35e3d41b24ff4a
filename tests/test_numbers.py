"""Writing numbers: ``format_decimal`` by its properties, and the defects it fixed, end to end."""

from __future__ import annotations

import io
import struct
from decimal import Decimal

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import ErrorList, ProgramError
from postproc.numbers import EXACT, EXACT_INCH, MAX_PLACES, decimal_value, format_decimal
from postproc.setup.machine_setup import MachineSetup, OutputSettings
from postproc.simulate.verify import verify_lines

FINITE = st.floats(min_value=-1e29, max_value=1e29)
"""Numbers a writer may write: at most 29 digits before the point (``MAX_DIGITS``: more is refused,
``tests/test_isg_long_numbers.py``)."""
PLACES = st.integers(min_value=0, max_value=7)


def _places(text: str) -> int:
    return len(text.partition(".")[2])


@given(value=FINITE, places=PLACES, leading_zero=st.booleans(), exact=st.sampled_from([EXACT, EXACT_INCH]))
def test_parses_back_within_half_a_unit_of_the_last_place(value: float, places: int, leading_zero: bool,
                                                          exact: float) -> None:
    text = format_decimal(value, places, leading_zero, exact)
    error = abs(Decimal(text) - Decimal(value))
    assert error <= Decimal(5) * Decimal(10) ** -(_places(text) + 1), text
    # Never rounds silently: read back as a float (as any reader does), it is within ``exact``. (In exact
    # decimals it may be further: 137438953472.04 is the double 137438953472.0400085..., same float.)
    assert abs(float(text) - value) <= exact, text
    assert _places(text) <= max(places, MAX_PLACES if exact == EXACT else 8)


@given(value=FINITE, places=PLACES, leading_zero=st.booleans())
def test_spelling(value: float, places: int, leading_zero: bool) -> None:
    text = format_decimal(value, places, leading_zero)
    whole, point, frac = text.partition(".")
    assert point == "." and set(text) <= set("-0123456789.")  # never 'inf', 'nan' or an exponent
    assert not frac.endswith("0")
    if Decimal(text) == 0:
        assert text == "0."  # never '-0.'
    if leading_zero:
        assert whole.lstrip("-") != ""
    elif frac:
        assert whole.lstrip("-") != "0"


@pytest.mark.parametrize("value, places, leading_zero, expected", [
    (50.0, 0, True, "50."), (100.0, 0, True, "100."), (0.0, 0, True, "0."), (12.5, 0, True, "12.5"),
    (-0.0, 3, True, "0."), (-1e-9, 3, True, "0."), (0.5, 3, False, ".5"), (-0.25, 3, False, "-.25"),
    (0.0, 3, False, "0."), (10.0, 3, True, "10."), (1 / 3, 3, True, "0.333333"), (2.0 / 3.0, 7, True, "0.6666667"),
])
def test_examples(value: float, places: int, leading_zero: bool, expected: str) -> None:
    assert format_decimal(value, places, leading_zero) == expected


@pytest.mark.parametrize("value, message", [
    (float("inf"), "cannot write the number inf: it is beyond the range of a float"),
    (float("-inf"), "cannot write the number -inf: it is beyond the range of a float"),
    (float("nan"), "cannot write a value that is not a number (nan)"),
])
def test_a_non_finite_number_is_refused(value: float, message: str) -> None:
    with pytest.raises(ProgramError) as exc:
        format_decimal(value, 3)
    assert exc.value.message == message


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_decimals_0_writes_whole_numbers_with_their_point(target: str) -> None:
    """Issue 8: ``decimals="0"`` wrote ``G0 X5 Y1 Z`` for ``X50. Y100. Z0.``."""
    setup = MachineSetup(output=OutputSettings(decimals=0))
    out = io.StringIO()
    translate(io.StringIO("G21 G90\nG0 X50. Y100. Z0.\nG1 X12.5 F100.\n"), out, file="d.nc", source="fanuc",
              target=target, setup=setup)
    assert out.getvalue().splitlines()[1:3] == ["G0 X50. Y100. Z0.", "G1 X12.5 F100."]


def test_an_inch_number_keeps_the_places_that_half_a_micrometre_needs() -> None:
    """Found by ``make fuzz``: inch values were rounded within 5e-7 in (12.7 nm, coarser than the
    toolpath's 1 nm), so Y-0.0000004 (10 nm) was written as Y0. and the toolpaths differed."""
    assert format_decimal(-0.0000004, 4, True, EXACT_INCH) == "-0.0000004"
    out = io.StringIO()
    program = "G20 G90 G0 X0. Y0. Z1.\nY-0.0000004\n"
    translate(io.StringIO(program), out, file="i.nc", source="fanuc", target="linuxcnc")
    assert out.getvalue().splitlines()[1] == "G0 Y-0.0000004"
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="i.nc", file_out="o.nc",
                          source="fanuc", target="linuxcnc", tolerance=0.0)
    assert report.ok, report.summary()


def test_a_number_beyond_the_float_range_is_a_located_error() -> None:
    """Issue 8: ``X1000...0.`` (401 digits) was written as ``Xinf``."""
    program = "G21 G90\nG0 X1" + "0" * 400 + ".\n"
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(program), io.StringIO(), file="big.nc", source="fanuc", target="linuxcnc")
    assert [str(e) for e in exc.value.errors] == [
        "big.nc:2:5: error: a number with more than 30 digits cannot be read"]


@pytest.mark.parametrize("attribute, message", [
    ('decimals="7"', "decimals: Input should be less than or equal to 6"),
    ('decimals="-1"', "decimals: Input should be greater than or equal to 0"),
    ('inchDecimals="8"', "inchDecimals: Input should be less than or equal to 7"),
])
def test_config_check_validates_the_decimals_ranges(cli, tmp_path, attribute: str, message: str) -> None:
    """0 is valid (whole numbers keep their point, 'X50.'); beyond 6 (7 in inch) is finer than 0.001 um."""
    path = tmp_path / "m.xml"
    path.write_text(f'<MachineSetup name="m">\n  <Output {attribute}/>\n</MachineSetup>\n')
    result = cli("config", "check", path)
    assert (result.status, result.err) == (1, f"{path}:2:1: error: <Output> {message}\n")


def test_config_check_accepts_decimals_0(cli, tmp_path) -> None:
    path = tmp_path / "m.xml"
    path.write_text('<MachineSetup name="m">\n  <Output decimals="0" inchDecimals="0"/>\n</MachineSetup>\n')
    assert cli("config", "check", path).status == 0


def _same_float(a: float, b: float) -> bool:
    """Bit for bit: -0.0 is not 0.0 here, and NaN is itself."""
    return struct.pack("<d", a) == struct.pack("<d", b)


def _float_or_error(text: str) -> object:
    try:
        return float(text)
    except ValueError:
        return ValueError


plain_decimals = st.builds(
    lambda sign, whole, point, fraction: sign + whole + point + fraction,
    st.sampled_from(["", "-"]), st.text("0123456789", max_size=18), st.sampled_from(["", "."]),
    st.text("0123456789", max_size=18))


@given(text=st.one_of(plain_decimals, st.text("0123456789.-+eE_ \u0661\u0663", max_size=12)))
@example(text="117.837")
@example(text="-0.")
@example(text="0.1")
@example(text="-.5")
@example(text="999999999999999.")  # 15 digits: computed
@example(text="9999999999999999.")  # 16: float's
@example(text="0.30000000000000004")
@example(text="1.7976931348623157")
@example(text=".")
@example(text="")
@example(text="1.2.3")
@example(text="+1.5")
@example(text="1_0.5")
@example(text=" 1.5")
@example(text="\u0661.5")  # an Arabic-Indic digit: float reads it, decimal_value leaves it to float
def test_decimal_value_is_float_bit_for_bit(text: str) -> None:
    expected = _float_or_error(text)
    if expected is ValueError:
        with pytest.raises(ValueError):
            decimal_value(text)
        return
    assert isinstance(expected, float)
    assert _same_float(decimal_value(text), expected), text


@given(value=st.floats(allow_nan=False, allow_infinity=False, min_value=-1e9, max_value=1e9),
       places=st.integers(0, 6))
def test_decimal_value_reads_back_what_the_writer_writes(value: float, places: int) -> None:
    text = format_decimal(value, places)
    assert _same_float(decimal_value(text), float(text))
