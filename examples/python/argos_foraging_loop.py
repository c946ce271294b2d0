"""ARGoS's foraging_loop_functions in Python, the twin of Java's ``robosim.examples.ForagingLoopFunctions``
(examples/argos/foraging.xml with ``--param loop=python:../python/argos_foraging_loop.py``): ``items`` food items,
black discs painted on the floor at random in the foraging area; before each step a robot without food standing on
an item outside the nest picks it up (told ``food``), a robot with food in the nest drops it (a new item appears;
told ``dropped``; ``energy_per_item`` earned); each walking robot spends ``energy_per_walking_robot``. Each step's
line goes to ``output`` in the run's output directory; ``collected_food`` and ``energy`` are reported. The same
arithmetic in the same order as the Java class's: the two give the same pose log and the same file."""

from __future__ import annotations

import re
from typing import TextIO

from robosim.loop import Experiment, LoopFunctions

MAX_ITEMS = 5_000
BLACK, GREEN, BLUE = 0x000000, 0x00FF00, 0x0000FF


class ForagingLoopFunctions(LoopFunctions):
    def __init__(self) -> None:
        self.output: TextIO | None = None

    def init(self, world: Experiment) -> None:
        items = int(world.parameter("items", 15))
        if not 0 <= items <= MAX_ITEMS:
            raise ValueError(f"items is 0 to {MAX_ITEMS}, got {items}")
        self.radius_mm = world.parameter("radius", 0.1) * 1000
        self.nest_x_mm = world.parameter("nest_x", 1.5) * 1000
        self.area = [float(v.strip()) * 1000 for v in world.parameter("area", "1.6,0.8,4.2,4.2").split(",")]
        if len(self.area) != 4 or not self.area[0] < self.area[2] or not self.area[1] < self.area[3]:
            raise ValueError(f"area is MINX,MINY,MAXX,MAXY in metres, got {world.parameter('area', '')}")
        self.energy_per_item = int(world.parameter("energy_per_item", 1000))
        self.energy_per_walking_robot = int(world.parameter("energy_per_walking_robot", 1))
        self.collected = 0
        self.energy = 0
        self.food: list[tuple[float, float] | None] = [None] * items
        for i in range(items):
            self.place(world, i)
        self.carried = [-1] * world.robots
        self.paint(world)
        if self.output is not None:
            self.output.close()
        name = world.parameter("output", "foraging.txt")
        if not re.fullmatch(r"[A-Za-z0-9_.-]{1,64}", name) or name.startswith("."):
            raise ValueError(f"output is a file name (letters, digits, _ . -), got {name}")
        self.output = open(world.output_directory / name, "w", encoding="utf-8")  # noqa: SIM115 (closed in destroy)
        self.output.write("# clock\twalking\tresting\tcollected_food\tenergy\n")

    def place(self, world: Experiment, item: int) -> None:
        x = self.area[0] + world.random.next_double() * (self.area[2] - self.area[0])
        y = self.area[1] + world.random.next_double() * (self.area[3] - self.area[1])
        self.food[item] = (x, y)

    def paint(self, world: Experiment) -> None:
        world.erase_paint()
        for item in self.food:
            if item is not None:
                world.paint_disc(item[0], item[1], self.radius_mm, BLACK)

    def pre_step(self, world: Experiment) -> None:
        walking = resting = 0
        changed = False
        if len(self.carried) < world.robots:  # (robots that joined)
            self.carried.extend([-1] * (world.robots - len(self.carried)))
        for r in range(world.robots):
            if not world.present(r):
                if self.carried[r] >= 0:  # (it left with an item: the item comes back to the floor)
                    self.place(world, self.carried[r])
                    self.carried[r] = -1
                    changed = True
                continue
            leds = world.leds(r)
            if leds and leds[0] in (GREEN, BLUE):
                walking += 1
            else:
                resting += 1
            x, y = world.robot_x_mm(r), world.robot_y_mm(r)
            if self.carried[r] >= 0:
                if x < self.nest_x_mm:
                    self.place(world, self.carried[r])
                    self.carried[r] = -1
                    self.energy += self.energy_per_item
                    self.collected += 1
                    world.tell(r, "dropped")
                    changed = True
            elif x > self.nest_x_mm:
                for i, item in enumerate(self.food):
                    if item is None:
                        continue
                    dx, dy = x - item[0], y - item[1]
                    if dx * dx + dy * dy < self.radius_mm * self.radius_mm:
                        self.food[i] = None
                        self.carried[r] = i
                        world.tell(r, "food")
                        changed = True
                        break
        if changed:
            self.paint(world)
        self.energy -= walking * self.energy_per_walking_robot
        assert self.output is not None
        self.output.write(f"{world.step}\t{walking}\t{resting}\t{self.collected}\t{self.energy}\n")
        world.report("collected_food", self.collected)
        world.report("energy", self.energy)

    def destroy(self, world: Experiment) -> None:
        if self.output is not None:
            self.output.close()
            self.output = None


loop_functions = ForagingLoopFunctions
