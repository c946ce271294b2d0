"""Sines, cosines, angles and lengths by arithmetic alone, in the order of operations of Java's
``robosim.examples.PortableMath``: a Python controller and its Java twin give the same bits (a maths library's last bit
differs between Java's intrinsics and the C library Python uses), and so the same pose log. Accurate to about 1e-12.
``SplittableRandom`` draws what Java's ``java.util.SplittableRandom`` of the same seed draws."""

from __future__ import annotations

import math

#: Radians in a degree: the factor of Java's ``Math.toRadians`` and Python's ``math.radians``, written out.
RADIANS_PER_DEGREE = 0.017453292519943295
_QUARTER_PI = 0.7853981633974483
_HALF_PI = 1.5707963267948966
_PI = 3.141592653589793
_TAN_EIGHTH_PI = 0.41421356237309503
_MASK = (1 << 64) - 1
_GOLDEN_GAMMA = 0x9E3779B97F4A7C15


def angle(y: float, x: float) -> float:
    """The angle of (x, y) from +x, radians in [-pi, pi], as ``math.atan2(y, x)``; 0 for (0, 0)."""
    if x == 0 and y == 0:
        return 0.0
    ax = abs(x)
    ay = abs(y)
    steep = ay > ax
    z = ax / ay if steep else ay / ax
    base = 0.0
    if z > _TAN_EIGHTH_PI:
        z = (z - 1) / (z + 1)
        base = _QUARTER_PI
    z2 = z * z
    s = 0.0
    for k in range(25, 0, -2):
        s = 1.0 / k - z2 * s
    a = base + z * s
    if steep:
        a = _HALF_PI - a
    if x < 0:
        a = _PI - a
    return -a if y < 0 else a


def length(x: float, y: float) -> float:
    """The length of (x, y), as ``math.hypot`` (a square root is exact in both languages)."""
    return math.sqrt(x * x + y * y)


def cos(a: float) -> float:
    """The cosine of ``a`` radians."""
    r = a - 2 * _PI * math.floor(a / (2 * _PI) + 0.5)
    flip = r > _HALF_PI or r < -_HALF_PI
    if flip:
        r = _PI - r if r > 0 else -_PI - r
    r2 = r * r
    s = 0.0
    for k in range(20, 0, -2):
        s = 1 - r2 / (k * (k - 1)) * s
    return -s if flip else s


def sin(a: float) -> float:
    """The sine of ``a`` radians."""
    return cos(a - _HALF_PI)


def power(base: float, n: int) -> float:
    """``base`` to the whole power ``n`` >= 0 by multiplication."""
    p = 1.0
    for _ in range(n):
        p *= base
    return p


class SplittableRandom:
    """Java's ``java.util.SplittableRandom(seed)``: the same ``next_long`` and ``next_double`` for the same seed."""

    def __init__(self, seed: int) -> None:
        self._seed = seed & _MASK

    def next_long(self) -> int:
        """The next 64 bits, as Java's signed ``long``."""
        self._seed = (self._seed + _GOLDEN_GAMMA) & _MASK
        z = self._seed
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK
        z ^= z >> 31
        return z - (1 << 64) if z >= 1 << 63 else z

    def next_double(self) -> float:
        """A double in [0, 1): the top 53 bits of the next long."""
        return ((self.next_long() & _MASK) >> 11) * (1.0 / (1 << 53))
