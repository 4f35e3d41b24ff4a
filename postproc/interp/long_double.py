"""Degree trigonometry as C computes it with x86-64 ``long double``, reproduced bit for bit.

Why: an interpreter written in C (LinuxCNC's ``rs274``, ``interp_execute.cc``) computes
``sin((x * M_PIl) / 180.0)`` with ``x`` a double: the product and the quotient are rounded to the x87
80-bit format (a 64-bit significand), ``sinl`` gives the sine of that argument rounded to 64 bits, and
storing it in a double rounds again to 53 bits. Because ``M_PIl`` is not pi, ``SIN[180]`` is
-5.0165576136843e-20 there (not 0, and not the 1.22e-16 of ``math.sin(math.pi)``), so
``FIX[SIN[180]]`` is -1 and ``COS[90] LT 0`` is true. The inverse functions take the double result of
``asin``/``acos``/``atan2`` and convert it with ``(r * 180.0) / M_PIl``, rounded the same two ways.

The transcendental values are computed in integer fixed point at a precision raised until the
64-bit rounding is certain (Ziv's strategy), so the result does not depend on the host's libm or
``long double`` (an ARM host has none of x86's). Exactness against glibc's ``sinl``/``cosl``/``tanl`` and
against ``rs274`` is tested in ``tests/test_long_double.py``.
"""

from __future__ import annotations

from typing import Callable

from ..ir.expr import EvalError

SIGNIFICAND = 64
"""Bits of the x87 extended format's significand."""

PI_L_NUM = 0xC90FDAA22168C235
PI_L_EXP = -62
"""``M_PIl`` = PI_L_NUM * 2**PI_L_EXP: pi rounded to 64 bits (up: it exceeds pi by about 5.0e-20)."""

_START_BITS = 160
"""Working precision of the first attempt, in bits below the binary point (raised by 64 on doubt)."""
_MAX_ATTEMPTS = 40


def sin_deg(x: float) -> float:
    """``(double) sinl((x * M_PIl) / 180.0L)``."""
    if x == 0.0:
        return x  # sinl(-0.0) is -0.0
    return _to_double(_rounded(_sin, _scaled_argument(x)))


def cos_deg(x: float) -> float:
    """``(double) cosl((x * M_PIl) / 180.0L)``."""
    if x == 0.0:
        return 1.0
    return _to_double(_rounded(_cos, _scaled_argument(x)))


def tan_deg(x: float) -> float:
    """``(double) tanl((x * M_PIl) / 180.0L)``."""
    if x == 0.0:
        return x
    return _to_double(_rounded(_tan, _scaled_argument(x)))


def degrees(r: float) -> float:
    """``(double) ((r * 180.0) / M_PIl)`` for a double ``r``: the product of two doubles is a double."""
    if r == 0.0:
        return r
    num, den = (r * 180.0).as_integer_ratio()
    m, e = _round_ratio(num, den * PI_L_NUM)
    return _to_double((m, e - PI_L_EXP))


# ---- rounding to the x87 format, and back to double --------------------------------------------------

def _scaled_argument(x: float) -> tuple[int, int]:
    """(m, e): ``(x * M_PIl) / 180.0L`` = m * 2**e, each operation rounded to 64 bits."""
    num, den = x.as_integer_ratio()
    m, e = _round_ratio(num * PI_L_NUM, den)
    m2, e2 = _round_ratio(m, 180)
    return m2, e2 + e + PI_L_EXP


def _round_ratio(num: int, den: int) -> tuple[int, int]:
    """num/den (den > 0) rounded to a 64-bit significand, to nearest with ties to even: (m, e) with
    the result m * 2**e (m == 0 only for num == 0)."""
    if num == 0:
        return 0, 0
    sign = -1 if num < 0 else 1
    num = abs(num)
    e = num.bit_length() - den.bit_length() - SIGNIFICAND - 1
    q, r = divmod(num << -e, den) if e < 0 else divmod(num, den << e)
    extra = q.bit_length() - SIGNIFICAND  # 1 or 2: the quotient lies in [2**64, 2**66)
    dropped = q & ((1 << extra) - 1)
    q >>= extra
    e += extra
    half = 1 << (extra - 1)
    if dropped > half or (dropped == half and (r or q & 1)):
        q += 1
        if q.bit_length() > SIGNIFICAND:
            q >>= 1
            e += 1
    return sign * q, e


def _to_double(value: tuple[int, int]) -> float:
    """A 64-bit-significand value converted to double (nearest, ties to even), as C's assignment does."""
    m, e = value
    if e >= 0:
        return float(m << e)
    return m / (1 << -e)  # int / int is correctly rounded, subnormals included


# ---- fixed point: values are integers scaled by 2**w ---------------------------------------------------

_pi_cache: list[int] = [0, 0]  # [bits, pi * 2**bits]


def _pi(bits: int) -> int:
    """floor(pi * 2**bits) (error below 1), by Machin's formula; the largest one computed is kept."""
    have, value = _pi_cache
    if have >= bits:
        return value >> (have - bits)
    w = bits + 16
    value = (16 * _atan_inverse(5, w) - 4 * _atan_inverse(239, w)) >> 16
    _pi_cache[0], _pi_cache[1] = bits, value
    return value


def _atan_inverse(n: int, w: int) -> int:
    """atan(1/n) * 2**w, truncated term by term (error below the number of terms)."""
    total = term = (1 << w) // n
    n2 = n * n
    k = 1
    while term:
        term //= n2
        k += 2
        total += -(term // k) if (k // 2) % 2 else term // k
    return total


def _reduce(m: int, e: int, w: int) -> tuple[int, int, int]:
    """(quadrant mod 4, r * 2**w, error bound) with argument = quadrant * pi/2 + r, |r| <= pi/4 or so."""
    extra = max(0, m.bit_length() + e) + 8
    p = w + extra
    pi_p = _pi(p)
    a = m << (e + p)  # e + p >= 96: _rounded chooses w so
    half_pi = pi_p >> 1
    k = (2 * a + half_pi) // (2 * half_pi)
    r = a - k * half_pi
    # pi_p errs by at most 2 units of 2**-p, half_pi by 1.5: r by 1.5 |k| of them, plus the shift
    return k % 4, r >> extra, (3 * abs(k) >> (extra + 1)) + 3


def _sin_cos(r: int, w: int) -> tuple[int, int, int]:
    """sin and cos of r / 2**w (|r| <= about pi/4 * 2**w), scaled by 2**w, and their error bound."""
    one = 1 << w
    r2 = (r * r) >> w
    s = term = r
    k = 1
    terms = 0
    while term:
        term = -(term * r2 >> w) // ((k + 1) * (k + 2))
        s += term
        k += 2
        terms += 1
    c = term = one
    k = 0
    while term:
        term = -(term * r2 >> w) // ((k + 1) * (k + 2))
        c += term
        k += 2
        terms += 1
    return s, c, 2 * terms + 4


def _quadrant(q: int, s: int, c: int) -> tuple[int, int]:
    if q == 0:
        return s, c
    if q == 1:
        return c, -s
    if q == 2:
        return -s, -c
    return -c, s


def _sin(m: int, e: int, w: int) -> tuple[int, int]:
    q, r, err = _reduce(m, e, w)
    s, c, err2 = _sin_cos(r, w)
    return _quadrant(q, s, c)[0], err + err2


def _cos(m: int, e: int, w: int) -> tuple[int, int]:
    q, r, err = _reduce(m, e, w)
    s, c, err2 = _sin_cos(r, w)
    return _quadrant(q, s, c)[1], err + err2


def _tan(m: int, e: int, w: int) -> tuple[int, int]:
    """tan as an interval's midpoint and half width, from the intervals of sin and cos."""
    q, r, err = _reduce(m, e, w)
    s, c, err2 = _sin_cos(r, w)
    s, c = _quadrant(q, s, c)
    d = err + err2
    if abs(c) <= d:
        return 0, 1 << (w + 2)  # cannot tell: more bits
    quotients = [((si << w) // ci, -((-(si << w)) // ci)) for si in (s - d, s + d) for ci in (c - d, c + d)]
    low = min(lo for lo, _ in quotients)
    high = max(hi for _, hi in quotients)
    return (low + high) // 2, (high - low) // 2 + 2


def _rounded(fn: Callable[[int, int, int], tuple[int, int]], arg: tuple[int, int]) -> tuple[int, int]:
    """fn at a non-zero argument, rounded to 64 bits. The precision grows until both ends of the error
    interval round alike: the sine, cosine or tangent of a non-zero rational is transcendental, never
    a tie, so this ends."""
    m, e = arg
    w = _START_BITS + max(0, -e - SIGNIFICAND)
    for _ in range(_MAX_ATTEMPTS):
        value, err = fn(m, e, w)
        low = _round_ratio(value - err, 1 << w)
        if low == _round_ratio(value + err, 1 << w):
            return low
        w += 64
    raise EvalError(f"cannot round a trigonometric function of {m}*2**{e}")  # pragma: no cover
