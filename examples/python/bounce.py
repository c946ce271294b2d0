"""Bounce, the same robot as Java's robosim.examples.Bounce: legs of 250 mm ahead and, when a sonar within 60 degrees
of ahead reads under 600 mm, a 45 degree turn towards the more open side. Without chance: the Java and the Python
robot give byte-identical pose logs (bounce.xml, runner's PythonControlIT)."""

import math

from robosim import Robot

CLEARANCE_MM = 600.0
LEG_MM = 250.0
TURN_DEG = 45.0


def normalise(deg: float) -> float:
    """``deg`` in (-180, 180] (math.fmod, as Java's %: the sign of the dividend)."""
    a = math.fmod(deg, 360.0)
    if a > 180:
        a -= 360
    elif a <= -180:
        a += 360
    return a


def control(robot: Robot) -> None:
    robot.set_velocity(robot.parameter("speed", robot.velocity()))
    angles = robot.sonar_angles_deg()
    turns = 0
    while True:
        ranges = robot.sonar_ranges()
        ahead = math.inf
        left = 0.0
        right = 0.0
        for angle, r in zip(angles, ranges, strict=True):
            a = normalise(angle)
            if abs(a) <= 60:
                ahead = min(ahead, r)
            if 0 < a < 180:
                left += r
            elif a < 0:
                right += r
        if ahead < CLEARANCE_MM:
            robot.turn(TURN_DEG if left >= right else -TURN_DEG)
            turns += 1
            robot.report("turns", turns)
        else:
            robot.move(LEG_MM)
