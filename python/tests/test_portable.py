"""robosim.portable: close to the maths library's values, and Java's SplittableRandom's draws for the same seed (the
Java and Python twins of examples/argos give the same pose logs: runner's PythonControlIT)."""

import math
import random

from robosim.portable import RADIANS_PER_DEGREE, SplittableRandom, angle, cos, length, power, sin


def test_angles_sines_and_cosines_are_within_a_few_ulps_of_the_library() -> None:
    draw = random.Random(7)
    for _ in range(5000):
        x, y = draw.uniform(-5, 5), draw.uniform(-5, 5)
        assert abs(angle(y, x) - math.atan2(y, x)) < 1e-11
        assert length(x, y) == math.sqrt(x * x + y * y)
        a = draw.uniform(-20, 20)
        assert abs(cos(a) - math.cos(a)) < 1e-11
        assert abs(sin(a) - math.sin(a)) < 1e-11
    assert angle(0.0, 0.0) == 0.0
    assert angle(0.0, -1.0) == math.pi
    assert RADIANS_PER_DEGREE == math.radians(1)
    assert power(1.5, 3) == 1.5 * 1.5 * 1.5
    assert power(2.0, 0) == 1.0


def test_a_splittable_random_draws_what_javas_draws_for_the_same_seed() -> None:
    # new java.util.SplittableRandom(42): nextLong() twice; a new one's nextDouble()
    r = SplittableRandom(42)
    assert [r.next_long(), r.next_long()] == [-4767286540954276203, 2949826092126892291]
    assert SplittableRandom(42).next_double() == 0.7415648787718233
    assert 0.0 <= SplittableRandom(-3).next_double() < 1.0
