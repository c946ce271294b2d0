"""Wander in Python (Java's robosim.examples.Wander): sonar obstacle avoidance. It drives ahead in 250 mm legs and,
when a sonar within 60 degrees of ahead reads under 600 mm, turns 30 to 90 degrees towards the more open side, the
turn's size drawn from a generator seeded by the robot's seed (the run's seed and its name: the same seed, the same
run). Its speed is the parameter ``speed`` (mm/s); it reports how often it has turned (``turns``), for a sweep."""

import math
import random

from robosim import Robot

CLEARANCE_MM = 600.0
LEG_MM = 250.0


class Wander:
    def run(self, robot: Robot) -> None:
        chance = random.Random(robot.seed)
        robot.set_velocity(robot.parameter("speed", robot.velocity()))
        angles = [math.remainder(a, 360.0) for a in robot.sonar_angles_deg()]
        ahead_sonars = [i for i, a in enumerate(angles) if abs(a) <= 60]
        robot.sleep(1)
        turns = 0
        while True:
            ranges = robot.sonar_ranges()
            ahead = min((ranges[i] for i in ahead_sonars), default=math.inf)
            if ahead < CLEARANCE_MM:
                left = sum(r for r, a in zip(ranges, angles, strict=True) if 0 < a < 180)
                right = sum(r for r, a in zip(ranges, angles, strict=True) if a < 0)
                by = 30 + chance.randrange(61)
                robot.turn(by if left >= right else -by)
                turns += 1
                robot.report("turns", turns)
            else:
                robot.move(LEG_MM)


control = Wander
