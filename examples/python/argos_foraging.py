"""ARGoS's footbot_foraging in Python, the twin of Java's ``robosim.examples.FootBotForaging``
(examples/argos/foraging.xml with ``--param control=python:../python/argos_foraging.py``): resting in the nest (LEDs
red), exploring (green: diffusion, with anti-phototaxis while still in the nest), returning to the nest (blue:
diffusion and phototaxis), and ARGoS's food, collision and social rules. The loop functions tell it ``food`` when it
picks an item up and ``dropped`` when it drops one in the nest. Its angles, lengths and chances are
``robosim.portable``'s, in the Java class's order of operations: the two give the same pose log (runner's
PythonControlIT)."""

from __future__ import annotations

from argos_ring import ring_sum
from argos_wheels import WheelTurning

from robosim import Robot
from robosim.portable import RADIANS_PER_DEGREE, SplittableRandom, angle, length

NONE, SUCCESSFUL, UNSUCCESSFUL = 0, 1, 2  # what a robot tells of its last exploration (range-and-bearing byte 0)
RAB_RECORD = 12  # a foot-bot's range-and-bearing record: distance, bearing, its ten bytes
RESTING, EXPLORING, RETURN_TO_NEST = "resting", "exploring", "return_to_nest"


def clamp(p: float) -> float:
    return max(0.0, min(1.0, p))


class Forager:
    def __init__(self, robot: Robot) -> None:
        self.robot = robot
        self.random = SplittableRandom(robot.seed)
        low, high = str(robot.parameter("go_straight_angle_range", "-5:5")).split(":")
        self.go_straight_min = RADIANS_PER_DEGREE * float(low.strip())
        self.go_straight_max = RADIANS_PER_DEGREE * float(high.strip())
        self.delta = float(robot.parameter("delta", 0.1))
        self.steer = WheelTurning(robot, 100.0, 1.0)
        self.max_speed = self.steer.max_speed
        self.rest_to_explore = float(robot.parameter("initial_rest_to_explore_prob", 0.1))
        self.explore_to_rest = float(robot.parameter("initial_explore_to_rest_prob", 0.1))
        self.food_explore_to_rest = float(robot.parameter("food_rule_explore_to_rest_delta_prob", 0.01))
        self.food_rest_to_explore = float(robot.parameter("food_rule_rest_to_explore_delta_prob", 0.01))
        self.collision_explore_to_rest = float(robot.parameter("collision_rule_explore_to_rest_delta_prob", 0.01))
        self.social_explore_to_rest = float(robot.parameter("social_rule_explore_to_rest_delta_prob", 0.01))
        self.social_rest_to_explore = float(robot.parameter("social_rule_rest_to_explore_delta_prob", 0.01))
        self.minimum_resting_time = int(float(robot.parameter("minimum_resting_time", 50.0)))
        self.minimum_unsuccessful_explore_time = int(float(robot.parameter("minimum_unsuccessful_explore_time", 600.0)))
        self.minimum_search_time = int(float(robot.parameter("minimum_search_for_place_in_nest_time", 50.0)))
        self.state = RESTING
        self.in_nest = True
        self.time_exploring_unsuccessfully = 0
        self.time_rested = self.minimum_resting_time  # ARGoS's: a decision at the start, not after a wait
        self.time_searching = 0
        self.last_exploration = NONE
        self.has_food = False
        self.total_food = 0

    def run(self) -> None:
        self.robot.set_leds("red")
        self.say(NONE)
        self.robot.step()  # readings come with a step: none before the first
        while True:
            self.hear()
            if self.state == RESTING:
                self.rest()
            elif self.state == EXPLORING:
                self.explore()
            else:
                self.return_to_nest()
            self.robot.report("food_items", self.total_food)
            self.robot.step()

    def hear(self) -> None:
        while (m := self.robot.receive()) is not None:
            if m.sender != "loop":
                continue
            if m.text == "food":
                self.has_food = True
            elif m.text == "dropped":
                self.has_food = False
                self.total_food += 1

    def say(self, result: int) -> None:
        self.robot.set_rab_data([result] + [0] * (RAB_RECORD - 3))

    def rest(self) -> None:
        if self.time_rested > self.minimum_resting_time and self.random.next_double() < self.rest_to_explore:
            self.robot.set_leds("green")
            self.state = EXPLORING
            self.time_rested = 0
            return
        self.time_rested += 1
        if self.time_rested == 1:
            self.say(NONE)  # the last exploration's result is told once
        heard = self.robot.sensor("rab")
        for k in range(0, len(heard) - RAB_RECORD + 1, RAB_RECORD):
            said = int(heard[k + 2])
            if said == SUCCESSFUL:
                self.rest_to_explore = clamp(self.rest_to_explore + self.social_rest_to_explore)
                self.explore_to_rest = clamp(self.explore_to_rest - self.social_explore_to_rest)
            elif said == UNSUCCESSFUL:
                self.explore_to_rest = clamp(self.explore_to_rest + self.social_explore_to_rest)
                self.rest_to_explore = clamp(self.rest_to_explore - self.social_rest_to_explore)

    def explore(self) -> None:
        go_home = False
        if self.has_food:
            self.explore_to_rest = clamp(self.explore_to_rest - self.food_explore_to_rest)
            self.rest_to_explore = clamp(self.rest_to_explore + self.food_rest_to_explore)
            self.last_exploration = SUCCESSFUL
            go_home = True
        elif self.time_exploring_unsuccessfully > self.minimum_unsuccessful_explore_time:
            if self.random.next_double() < self.explore_to_rest:
                self.last_exploration = UNSUCCESSFUL
                go_home = True
            else:
                self.explore_to_rest = clamp(self.explore_to_rest + self.food_explore_to_rest)
                self.rest_to_explore = clamp(self.rest_to_explore - self.food_rest_to_explore)
        if go_home:
            self.time_exploring_unsuccessfully = 0
            self.time_searching = 0
            self.robot.set_leds("blue")
            self.state = RETURN_TO_NEST
            return
        self.time_exploring_unsuccessfully += 1
        self.update_in_nest()
        dx, dy, collision = self.diffusion()
        if collision:
            self.explore_to_rest = clamp(self.explore_to_rest + self.collision_explore_to_rest)
            self.rest_to_explore = clamp(self.rest_to_explore - self.collision_explore_to_rest)
        if self.in_nest:
            lx, ly = self.to_light()
            self.steer.drive(self.robot, self.max_speed * dx - self.max_speed * 0.25 * lx,
                             self.max_speed * dy - self.max_speed * 0.25 * ly)
        else:
            self.steer.drive(self.robot, self.max_speed * dx, self.max_speed * dy)

    def return_to_nest(self) -> None:
        self.update_in_nest()
        if self.in_nest:
            if self.time_searching > self.minimum_search_time:
                self.robot.set_wheel_speeds(0, 0)
                self.say(self.last_exploration)
                self.robot.set_leds("red")
                self.state = RESTING
                self.time_searching = 0
                self.last_exploration = NONE
                return
            self.time_searching += 1
        else:
            self.time_searching = 0
        dx, dy, _ = self.diffusion()
        lx, ly = self.to_light()
        self.steer.drive(self.robot, self.max_speed * dx + self.max_speed * lx,
                         self.max_speed * dy + self.max_speed * ly)

    def update_in_nest(self) -> None:
        g = self.robot.sensor("ground")
        self.in_nest = 0.25 < g[2] < 0.75 and 0.25 < g[3] < 0.75

    def diffusion(self) -> tuple[float, float, bool]:
        x, y = ring_sum(self.robot.sensor("proximity"))
        a = angle(y, x)
        n = length(x, y)
        if self.go_straight_min <= a <= self.go_straight_max and n < self.delta:
            return 1.0, 0.0, False
        return (-x / n if n > 0 else 0.0), (-y / n if n > 0 else 0.0), True

    def to_light(self) -> tuple[float, float]:
        x, y = ring_sum(self.robot.sensor("light"))
        n = length(x, y)
        return (x / n, y / n) if n > 0 else (0.0, 0.0)


def control(robot: Robot) -> None:
    Forager(robot).run()
