"""The README's first Python robot: a square of 2 m sides, telling robot2 each corner."""

from robosim import Robot


def control(robot: Robot) -> None:
    while True:
        robot.move(2000)
        robot.turn(90)
        sonar = robot.sonar_ranges()
        pose = robot.pose()
        robot.send("robot2", f"corner at {pose.x_mm:.0f},{pose.y_mm:.0f}; nearest {min(sonar):.0f} mm")
