package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * ARGoS's epuck_obstacleavoidance (examples/argos/epuck_obstacleavoidance.xml): of the four front proximity sensors
 * (17 and 50 degrees to the left, 17 and 50 to the right, looked at in ARGoS's order: 0, 1, 7, 6) the highest reading;
 * anything there, it turns away on one wheel (the obstacle on the left: the left wheel drives), else straight on at
 * {@code velocity} (ARGoS's 5 cm/s).
 */
public final class EPuckObstacleAvoidance implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        double v = robot.parameter("velocity", 50.0);
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] p = robot.sensor("proximity");
            int most = 0;
            for (int k : new int[] {1, 7, 6}) {
                if (p[most] < p[k]) {
                    most = k;
                }
            }
            if (p[most] > 0) {
                robot.setWheelSpeeds(most <= 1 ? v : 0, most <= 1 ? 0 : v);
            } else {
                robot.setWheelSpeeds(v, v);
            }
            robot.step();
        }
    }
}
