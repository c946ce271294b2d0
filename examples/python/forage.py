"""Foraging with a foot-bot, the same robot as Java's robosim.examples.Forage (test-envs/foraging.xml its world): it
drives on its wheels, steering away from what its proximity ring sees on either side, up to what it sees straight
ahead, where it tries its gripper (a wall, a robot, or a can already in the nest: it backs off and turns away). A can
it takes it carries towards the light over the nest, steering by its light ring, until its ground sensors all read
the nest's grey; there it lets go, reports ``delivered``, backs off and turns away. Its LEDs say what it is doing:
green searching, red carrying. Without chance, and with nothing but sums and comparisons of its
readings: the Java and the Python robot give byte-identical pose logs (runner's PythonControlIT)."""

from robosim import Robot

SPEED = 150.0  # mm/s
NEAR = 0.3  # a proximity reading above this is something close (0 nothing in range, 1 contact)
AHEAD = 0.99  # a front reading above this is within the gripper's 10 mm: time to try it
NEST = 0.75  # a ground reading below this is the nest's grey (the floor is white, 1)
BACK_STEPS = 5
TURN_STEPS = 8


def nest(ground: list[float]) -> bool:
    """True when every ground sensor reads the nest's grey."""
    return all(g < NEST for g in ground)


def turn_away(robot: Robot, near: list[float]) -> None:
    """Backs off, then turns away from the side more crowded by ``near``."""
    robot.set_wheel_speeds(-SPEED, -SPEED)
    for _ in range(BACK_STEPS):
        robot.step()
    left = near[0] + near[1] + near[2]
    right = near[23] + near[22] + near[21]
    robot.set_wheel_speeds(SPEED if left > right else -SPEED, -SPEED if left > right else SPEED)
    for _ in range(TURN_STEPS):
        robot.step()


def control(robot: Robot) -> None:
    delivered = 0
    robot.set_leds("green")
    robot.step()  # readings come with a step: none before the first
    while True:
        near = robot.sensor("proximity")
        home = nest(robot.sensor("ground"))
        carrying = robot.gripped() != ""
        if not carrying and max(near[0], near[23]) > AHEAD:
            if home or robot.grip() == "":
                turn_away(robot, near)
            else:
                robot.set_leds("red")
            continue
        if carrying and home:
            robot.set_wheel_speeds(0, 0)
            robot.release()
            delivered += 1
            robot.report("delivered", delivered)
            robot.set_leds("green")
            turn_away(robot, near)
            continue
        if not carrying and max(near[0], near[23]) > NEAR:
            robot.set_wheel_speeds(SPEED, SPEED)  # something straight ahead: up to it, to try the gripper
            robot.step()
            continue
        # what is close on either side; carrying, the can in its gripper fills the front: the sides only
        left = 0.0
        right = 0.0
        for k in range(3 if carrying else 1, 6):
            left += near[k]
            right += near[23 - k]
        if max(left, right) > NEAR:
            robot.set_wheel_speeds(SPEED if left > right else -SPEED, -SPEED if left > right else SPEED)
        elif carrying:
            light = robot.sensor("light")
            to_left = 0.0
            to_right = 0.0
            for k in range(12):
                to_left += light[k]
                to_right += light[12 + k]
            total = to_left + to_right
            d = (to_left - to_right) / total if total > 0 else 1.0  # no light in sight: turn till it is
            robot.set_wheel_speeds(SPEED * (1 - d), SPEED * (1 + d))
        else:
            robot.set_wheel_speeds(SPEED, SPEED)
        robot.step()
