package robosim.devices;

import com.google.auto.service.AutoService;

/**
 * {@code ArRobot}: Pioneer-like, radius 250 mm, 237 mm tall, 9 kg, wheels 330 mm apart, 8 front sonars at 90, 50, 30,
 * 10, -10, -30, -50, -90 degrees.
 */
@AutoService(RobotType.class)
public final class ArRobot extends RobotType {
    public ArRobot() {
        super("ArRobot", "Pioneer-like: a ring of 8 sonars across the front (15 degree cones, 5 m)",
                new Body(250, 237, 9, 330, 1000, 300), ring(250, 15, 5000, 90, 50, 30, 10, -10, -30, -50, -90));
    }
}
