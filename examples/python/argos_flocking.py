"""ARGoS's footbot_flocking in Python, the twin of Java's ``robosim.examples.FootBotFlocking``
(examples/argos/flocking.xml with ``--param control=python:../python/argos_flocking.py``): the beacon red, driving
along the sum of a vector toward the light (a quarter of the top speed long) and the mean generalized Lennard-Jones
vector of the red blobs its camera sees nearer than 1.8 target distances, clamped to the top speed; worked in ARGoS's
units (cm, cm/s), the wheels set in mm/s. Its angles and lengths are ``robosim.portable``'s, in the Java class's order
of operations: the two give the same pose log (runner's PythonControlIT)."""

from __future__ import annotations

from argos_ring import ring_sum
from argos_wheels import WheelTurning

from robosim import Robot
from robosim.portable import RADIANS_PER_DEGREE, cos, length, power, sin

BEACON = 12
RED = 0xFF0000
MM_PER_CM = 10


def control(robot: Robot) -> None:
    steer = WheelTurning(robot, 10.0, MM_PER_CM)
    max_speed = steer.max_speed
    target = float(robot.parameter("target_distance", 75.0))
    gain = float(robot.parameter("gain", 1000.0))
    exponent = float(robot.parameter("exponent", 2.0))
    if exponent != int(exponent) or exponent < 0:
        raise ValueError(f"exponent is a whole number >= 0 here, got {exponent}")
    robot.set_led(BEACON, "red")
    robot.step()  # readings come with a step: none before the first
    while True:
        lx, ly = ring_sum(robot.sensor("light"))
        ll = length(lx, ly)
        if ll > 0:
            lx *= 0.25 * max_speed / ll
            ly *= 0.25 * max_speed / ll
        blobs = robot.sensor("camera")  # (colour, distance mm, angle deg) a blob
        fx = 0.0
        fy = 0.0
        seen = 0
        for b in range(0, len(blobs) - 2, 3):
            d = blobs[b + 1] / MM_PER_CM
            if int(blobs[b]) == RED and d < target * 1.80:
                norm = power(target / d, int(exponent))
                lj = -gain / d * (norm * norm - norm)
                a = RADIANS_PER_DEGREE * blobs[b + 2]
                fx += lj * cos(a)
                fy += lj * sin(a)
                seen += 1
        if seen > 0:
            fx /= seen
            fy /= seen
            fl = length(fx, fy)
            if fl > max_speed:
                fx *= max_speed / fl
                fy *= max_speed / fl
        steer.drive(robot, lx + fx, ly + fy)
        robot.step()
