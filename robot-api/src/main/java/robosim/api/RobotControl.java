package robosim.api;

/**
 * Robot control code: one class with a public no-argument constructor, named when a robot is
 * started. {@link #run} is called once on the control code's own thread; returning stops the
 * robot, and an {@link InterruptedException} means the robot is being shut down.
 */
public interface RobotControl {
    void run(Robot robot) throws Exception;
}
