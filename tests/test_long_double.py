"""LinuxCNC's trigonometry at exact angles: rs274 scales degrees with ``M_PIl`` in ``long double``.

Three kinds of evidence: values pinned from runs of the packaged rs274 (they hold without it),
``postproc.interp.long_double`` against glibc's own ``sinl``/``cosl``/``tanl`` through ctypes on x86-64, and a
seeded random differential against rs274 that reads every bit of each result (skipped without it).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import io
import math
import platform
import random
import re

import pytest

from postproc.interp import long_double
from postproc.errors import ErrorList
from postproc.interp.evaluation import MappingEnv, evaluate_number
from postproc.ir.expr import Arithmetic, Vacancy
from postproc.rs274.expressions import LINUXCNC_SPELLING, parse_expr
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, run_rs274

LCNC = MappingEnv({}, Vacancy.ZERO, arithmetic=Arithmetic.X86_64_C)

# Printed by rs274 (LinuxCNC 2.9.0~pre1, Debian 12, x86-64) for ``#1=[expr]`` ``(DEBUG, #1)``.
RS274_PRINTED = [
    ("FIX[SIN[180]]", -1.0), ("FUP[SIN[180]]", 0.0), ("FIX[SIN[360]]", 0.0), ("FUP[SIN[360]]", 1.0),
    ("FIX[COS[90]]", -1.0), ("FUP[COS[90]]", 0.0), ("FIX[COS[270]]", 0.0), ("FUP[COS[270]]", 1.0),
    ("[COS[90] LT 0]", 1.0), ("[COS[270] GT 0]", 1.0), ("[SIN[180] LT 0]", 1.0), ("[SIN[-180] GT 0]", 1.0),
    ("[SIN[360] GT 0]", 1.0), ("[TAN[180] LT 0]", 0.0), ("FIX[TAN[360]]", 0.0),
    ("[SIN[30] EQ 0.5]", 1.0), ("FIX[SIN[30]*2]", 1.0), ("FIX[COS[60]*2]", 1.0), ("FIX[TAN[45]]", 1.0),
    ("FUP[TAN[45]]", 1.0), ("FIX[SIN[90]]", 1.0), ("FIX[COS[0]]", 1.0), ("FIX[COS[180]]", -1.0),
    ("FUP[COS[180]]", -1.0), ("FIX[ASIN[1]]", 90.0), ("FUP[ASIN[1]]", 90.0), ("FIX[ACOS[-1]]", 180.0),
    ("FUP[ACOS[-1]]", 180.0), ("FIX[ATAN[1]/[1]]", 45.0), ("FUP[ATAN[1]/[1]]", 45.0),
    ("FIX[ACOS[0]]", 90.0), ("FUP[ACOS[0]]", 90.0), ("FIX[ATAN[-1]/[-1]]", -135.0),
    ("FIX[SIN[45]*SIN[45]*2]", 1.0), ("FUP[SIN[45]*SIN[45]*2]", 2.0), ("ROUND[SIN[180]]", 0.0),
    ("FIX[SIN[-1]]", -1.0),
]


def _value(text: str) -> float:
    _, tree = parse_expr(text, 0, LINUXCNC_SPELLING)
    return evaluate_number(tree, LCNC)


@pytest.mark.parametrize("text, printed", RS274_PRINTED, ids=[t for t, _ in RS274_PRINTED])
def test_boundary_values_as_rs274_prints_them(text: str, printed: float) -> None:
    assert _value(text) == printed


def test_the_residuals_at_exact_angles() -> None:
    """rs274 printed ``[SIN[180]*1000000000000000000]`` as -0.050166 and ``COS[90]`` scaled so as
    -0.025083: pi rounded to 64 bits (``M_PIl``) exceeds pi by 5.0e-20, and the argument is rounded twice."""
    assert round(long_double.sin_deg(180.0) * 1e18, 6) == -0.050166
    assert round(long_double.cos_deg(90.0) * 1e18, 6) == -0.025083
    # exact where the long double rounding lands on the value (rs274: SIN[30]-0.5 and TAN[45]-1 print 0)
    assert long_double.sin_deg(30.0) == 0.5 and long_double.tan_deg(45.0) == 1.0
    assert long_double.cos_deg(0.0) == 1.0 and math.copysign(1.0, long_double.sin_deg(-0.0)) == -1.0


def test_pi_l_is_pi_rounded_to_64_bits() -> None:
    """Hand derivation: pi = 0xC90FDAA22168C234C4C6628B... * 2**-62; the 65th bit is 1 and bits follow,
    so rounding to 64 bits goes up, to ...235."""
    assert long_double.PI_L_NUM == 0xC90FDAA22168C235 and long_double.PI_L_NUM.bit_length() == 64
    assert abs(long_double.PI_L_NUM * 2.0 ** long_double.PI_L_EXP - math.pi) < 1e-15


def test_round_beyond_a_c_int_is_refused_not_copied() -> None:
    """rs274 prints ROUND[3000000000] as -2147483648 (an int conversion out of range): refused here."""
    with pytest.raises(Exception, match="beyond the C int"):
        _value("ROUND[3000000000]")
    assert _value("ROUND[2147483647.4]") == 2147483647.0
    assert _value("ROUND[-2.5]") == -3.0 and _value("ROUND[0.49999999999999994]") == 1.0  # rs274: -3, 1


def test_fanuc_arithmetic_stays_double() -> None:
    """The dialect family decides: IEEE double gives sin(pi) = 1.2246e-16, so FIX (toward zero) is 0."""
    env = MappingEnv({}, Vacancy.NULL)
    _, tree = parse_expr("SIN[180]", 0, LINUXCNC_SPELLING)
    assert evaluate_number(tree, env) == math.sin(math.pi)


def test_a_linuxcnc_toolpath_takes_the_sign_rs274_computes() -> None:
    """``FIX[SIN[180]]`` moved X to -1 in rs274 (STRAIGHT_TRAVERSE(-1.0000, 1.0000, ...)); postproc said 0."""
    text = "G21 G90\nG0 X[FIX[SIN[180]]] Y[COS[90] LT 0] Z[FUP[COS[90]]]\nM2\n"
    moves = [e for e in toolpath_events(io.StringIO(text), file="t.ngc", dialect="linuxcnc") if "move" in e]
    assert [(m["x"], m["y"], m["z"]) for m in moves] == [(-1, 1, 0)]


def test_round_beyond_int_is_a_located_error_in_a_program() -> None:
    text = "G21 G90\nG0 X[ROUND[3000000000]]\nM2\n"
    with pytest.raises(ErrorList, match=r"t\.ngc:2:\d+: error: .*beyond the C int"):
        list(toolpath_events(io.StringIO(text), file="t.ngc", dialect="linuxcnc"))


# ---- against glibc, through ctypes (x86-64 Linux only) -----------------------------------------------

def _libm() -> ctypes.CDLL | None:
    if platform.machine() not in ("x86_64", "AMD64") or ctypes.sizeof(ctypes.c_longdouble) != 16:
        return None
    name = ctypes.util.find_library("m")
    return ctypes.CDLL(name) if name else None


LIBM = _libm()


def _x87(m: int, e: int) -> ctypes.c_longdouble:
    """The 80-bit value m * 2**e (m of exactly 64 bits) packed as x86-64 stores it."""
    sign = 0x8000 if m < 0 else 0
    m = abs(m)
    raw = m.to_bytes(8, "little") + (sign | (e + 63 + 16383)).to_bytes(2, "little") + bytes(6)
    return ctypes.c_longdouble.from_buffer_copy(raw)


@pytest.mark.skipif(LIBM is None, reason="needs x86-64 long double and libm")
def test_the_kernels_agree_with_glibc_bit_for_bit() -> None:
    """sinl and cosl of the 80-bit argument, stored in a double, as ``long_double`` computes them; tanl
    within one unit in the last place (glibc's tanl is not always correctly rounded: see evaluation.py)."""
    assert LIBM is not None
    funcs = {}
    for name in ("sinl", "cosl", "tanl"):
        fn = getattr(LIBM, name)
        fn.argtypes, fn.restype = [ctypes.c_longdouble], ctypes.c_longdouble
        funcs[name] = fn
    rnd = random.Random(31)
    xs = [float(d) for d in range(-720, 721, 15) if d] + [rnd.uniform(-1e4, 1e4) for _ in range(3000)]
    xs += [rnd.choice([-1, 1]) * 10 ** rnd.uniform(-300, 300) for _ in range(1000)]
    tan_off = 0
    for x in xs:
        m, e = long_double._scaled_argument(x)
        arg = _x87(m, e)
        assert funcs["sinl"](arg) == long_double.sin_deg(x), x
        assert funcs["cosl"](arg) == long_double.cos_deg(x), x
        theirs, ours = funcs["tanl"](arg), long_double.tan_deg(x)
        if theirs != ours:
            assert math.nextafter(ours, theirs) == theirs, x
            tan_off += 1
    assert tan_off <= len(xs) // 1000


# ---- against rs274: every bit of each result ---------------------------------------------------------

def _scaled_program(exprs: list[str], values: list[float]) -> str:
    """Each result times a power of two chosen from our value, so rs274 prints an integer of 53 bits
    (``%f``) that holds every bit, when its result has our exponent."""
    lines = ["G21"]
    for i, (text, ours) in enumerate(zip(exprs, values)):
        k = 52 - math.frexp(ours)[1] + 1 if ours else 0
        lines.append(f"#1=[{text}]")
        lines.append(f"#2=[#1*[2**{k}]]" if k >= 0 else f"#2=[#1/[2**{-k}]]")
        lines.append(f"(DEBUG, r{i} #2)")
    return "\n".join(lines + ["M2"]) + "\n"


def _rs274_bits(exprs: list[str], values: list[float]) -> list[tuple[float, float]]:
    text = _scaled_program(exprs, values)
    out = [line for line in run_rs274(text) if "MESSAGE" in line]
    pairs = []
    for i, ours in enumerate(values):
        m = re.search(rf'" r{i} (\S+)"', out[i])
        assert m, out[i]
        k = 52 - math.frexp(ours)[1] + 1 if ours else 0
        pairs.append((float(m.group(1)), math.ldexp(ours, k)))
    return pairs


def _angles(rnd: random.Random, n: int) -> list[float]:
    out = [0.0, 30.0, 45.0, 60.0, 90.0, 180.0, 270.0, 360.0, -90.0, -180.0, -45.0, 720.0, 1e6, -3600.0]
    for _ in range(n):
        k = rnd.random()
        if k < 0.4:
            out.append(float(rnd.randint(-2000, 2000) * rnd.choice([1, 15, 30, 45, 90])))
        elif k < 0.8:
            out.append(round(rnd.uniform(-1000, 1000), rnd.randint(0, 4)))
        else:
            out.append(float(rnd.randint(-10 ** 9, 10 ** 9)))
    return out


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(3))
def test_random_angles_bit_for_bit_against_rs274(seed: int) -> None:
    rnd = random.Random(seed)
    exprs: list[str] = []
    for a in _angles(rnd, 60):
        spelled = repr(a) if a >= 0 else f"[0-{-a!r}]"  # rs274 reads no exponent; these have none
        exprs += [f"SIN[{spelled}]", f"COS[{spelled}]"]
    for _ in range(30):
        u = repr(round(rnd.uniform(-1, 1), rnd.randint(1, 6)))
        v = repr(round(rnd.uniform(-1, 1), rnd.randint(1, 6)))
        exprs += [f"ASIN[{u}]", f"ACOS[{u}]", f"ATAN[{u}]/[{v}]"]
    values = [_value(t) for t in exprs]
    for text, (theirs, ours) in zip(exprs, _rs274_bits(exprs, values)):
        assert theirs == ours, (text, theirs, ours)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_tangent_against_rs274() -> None:
    """TAN at exact and random angles: equal, or one unit in the last place where glibc's tanl misses
    (TAN[271] is such a case: its long double result sits one unit below the correctly rounded one)."""
    rnd = random.Random(5)
    angles = _angles(rnd, 80)
    exprs = [f"TAN[{a!r}]" if a >= 0 else f"TAN[[0-{-a!r}]]" for a in angles]
    values = [_value(t) for t in exprs]
    off = 0
    for text, (theirs, ours) in zip(exprs, _rs274_bits(exprs, values)):
        off += theirs != ours
        assert abs(theirs - ours) <= 1.0, (text, theirs, ours)
    assert off <= 2
