"""ARGoS's footbot_flocking in Python, the twin of Java's ``robosim.examples.FootBotFlocking``
(examples/argos/flocking.xml with ``--param control=python:../python/argos_flocking.py``): the beacon red, driving
along the sum of a vector toward the light (a quarter of the top speed long) and the mean generalized Lennard-Jones
vector of the red blobs its camera sees nearer than 1.8 target distances, clamped to the top speed; worked in ARGoS's
units (cm, cm/s), the wheels set in mm/s. Its angles and lengths are ``robosim.portable``'s, in the Java class's order
of operations: the two give the same pose log (runner's PythonControlIT)."""

from __future__ import annotations

from robosim import Robot
from robosim.portable import RADIANS_PER_DEGREE, angle, cos, length, power, sin

BEACON = 12
RED = 0xFF0000
MM_PER_CM = 10
COS = [cos(RADIANS_PER_DEGREE * (7.5 + k * 15)) for k in range(24)]  # each light reading's direction
SIN = [sin(RADIANS_PER_DEGREE * (7.5 + k * 15)) for k in range(24)]
NO_TURN, SOFT_TURN, HARD_TURN = "no_turn", "soft_turn", "hard_turn"


def control(robot: Robot) -> None:
    hard_turn = RADIANS_PER_DEGREE * float(robot.parameter("hard_turn_angle_threshold", 90.0))
    soft_turn = RADIANS_PER_DEGREE * float(robot.parameter("soft_turn_angle_threshold", 70.0))
    no_turn = RADIANS_PER_DEGREE * float(robot.parameter("no_turn_angle_threshold", 10.0))
    max_speed = float(robot.parameter("max_speed", 10.0))
    target = float(robot.parameter("target_distance", 75.0))
    gain = float(robot.parameter("gain", 1000.0))
    exponent = float(robot.parameter("exponent", 2.0))
    if exponent != int(exponent) or exponent < 0:
        raise ValueError(f"exponent is a whole number >= 0 here, got {exponent}")
    turning = NO_TURN
    robot.set_led(BEACON, "red")
    robot.step()  # readings come with a step: none before the first
    while True:
        light = robot.sensor("light")
        lx = 0.0
        ly = 0.0
        for k in range(len(light)):
            lx += light[k] * COS[k]
            ly += light[k] * SIN[k]
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
        turning = wheels(robot, lx + fx, ly + fy, max_speed, hard_turn, soft_turn, no_turn, turning)
        robot.step()


def wheels(robot: Robot, x: float, y: float, max_speed: float, hard_turn: float, soft_turn: float, no_turn: float,
           turning: str) -> str:
    """ARGoS's SetWheelSpeedsFromVector, in cm/s, set in mm/s; returns the turning mechanism it is in now."""
    a = angle(y, x)
    base = min(length(x, y), max_speed)
    turn = abs(a)
    if turning == HARD_TURN and turn <= soft_turn:
        turning = SOFT_TURN
    if turning == SOFT_TURN:
        if turn > hard_turn:
            turning = HARD_TURN
        elif turn <= no_turn:
            turning = NO_TURN
    if turning == NO_TURN:
        if turn > hard_turn:
            turning = HARD_TURN
        elif turn > no_turn:
            turning = SOFT_TURN
    if turning == NO_TURN:
        speed1 = base
        speed2 = base
    elif turning == SOFT_TURN:
        factor = (hard_turn - turn) / hard_turn
        speed1 = base - base * (1 - factor)
        speed2 = base + base * (1 - factor)
    else:
        speed1 = -max_speed
        speed2 = max_speed
    if a > 0:
        robot.set_wheel_speeds(speed1 * MM_PER_CM, speed2 * MM_PER_CM)
    else:
        robot.set_wheel_speeds(speed2 * MM_PER_CM, speed1 * MM_PER_CM)
    return turning
