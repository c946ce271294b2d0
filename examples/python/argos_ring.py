"""A foot-bot's rings of 24 proximity and 24 light sensors, as ARGoS's controllers read them, the twin of Java's
``robosim.examples.FootBotRing``: each reading a vector along its sensor's direction (7.5 degrees, then every 15),
summed, by ``robosim.portable``'s cosines and sines in the same order as Java's."""

from __future__ import annotations

from collections.abc import Sequence

from robosim.portable import RADIANS_PER_DEGREE, cos, sin

COS = [cos(RADIANS_PER_DEGREE * (7.5 + k * 15)) for k in range(24)]
SIN = [sin(RADIANS_PER_DEGREE * (7.5 + k * 15)) for k in range(24)]


def ring_sum(readings: Sequence[float]) -> tuple[float, float]:
    """The sum of ``readings`` (24, in ARGoS's order) as vectors along their sensors: (x ahead, y left)."""
    x = 0.0
    y = 0.0
    for k in range(len(readings)):
        x += readings[k] * COS[k]
        y += readings[k] * SIN[k]
    return x, y
