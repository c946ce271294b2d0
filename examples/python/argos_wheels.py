"""ARGoS's SetWheelSpeedsFromVector, as its foraging and flocking foot-bots steer, the twin of Java's
``robosim.examples.WheelTurning`` (the same operations in the same order, ``robosim.portable``'s angles and lengths):
toward a vector (x ahead, y left), at its length up to the top speed, with no turn, a soft turn or a hard turn,
switching between them with hysteresis at ARGoS's thresholds. One per robot."""

from __future__ import annotations

from robosim import Robot
from robosim.portable import RADIANS_PER_DEGREE, angle, length

NO_TURN, SOFT_TURN, HARD_TURN = "no_turn", "soft_turn", "hard_turn"


class WheelTurning:
    def __init__(self, robot: Robot, default_max_speed: float, scale: float) -> None:
        """The thresholds and top speed from ``robot``'s parameters by ARGoS's names, in the controller's units;
        ``scale``: mm/s a unit of them (1 for mm/s, 10 for ARGoS's cm/s)."""
        self.hard_turn = RADIANS_PER_DEGREE * float(robot.parameter("hard_turn_angle_threshold", 90.0))
        self.soft_turn = RADIANS_PER_DEGREE * float(robot.parameter("soft_turn_angle_threshold", 70.0))
        self.no_turn = RADIANS_PER_DEGREE * float(robot.parameter("no_turn_angle_threshold", 10.0))
        self.max_speed = float(robot.parameter("max_speed", default_max_speed))
        self.scale = scale
        self.mechanism = NO_TURN

    def drive(self, robot: Robot, x: float, y: float) -> None:
        """Sets ``robot``'s wheels to steer toward (x, y)."""
        a = angle(y, x)
        base = min(length(x, y), self.max_speed)
        turn = abs(a)
        if self.mechanism == HARD_TURN and turn <= self.soft_turn:
            self.mechanism = SOFT_TURN
        if self.mechanism == SOFT_TURN:
            if turn > self.hard_turn:
                self.mechanism = HARD_TURN
            elif turn <= self.no_turn:
                self.mechanism = NO_TURN
        if self.mechanism == NO_TURN:
            if turn > self.hard_turn:
                self.mechanism = HARD_TURN
            elif turn > self.no_turn:
                self.mechanism = SOFT_TURN
        if self.mechanism == NO_TURN:
            speed1 = base
            speed2 = base
        elif self.mechanism == SOFT_TURN:
            factor = (self.hard_turn - turn) / self.hard_turn
            speed1 = base - base * (1 - factor)
            speed2 = base + base * (1 - factor)
        else:
            speed1 = -self.max_speed
            speed2 = self.max_speed
        if a > 0:
            robot.set_wheel_speeds(speed1 * self.scale, speed2 * self.scale)
        else:
            robot.set_wheel_speeds(speed2 * self.scale, speed1 * self.scale)
