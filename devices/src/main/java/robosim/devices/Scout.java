package robosim.devices;

import com.google.auto.service.AutoService;

/**
 * {@code Scout}: Nomadic Scout-like, radius 190 mm, 350 mm tall, 23 kg, wheels 340 mm apart, 16 sonars all round, one
 * every 22.5 degrees.
 */
@AutoService(RobotType.class)
public final class Scout extends RobotType {
    public Scout() {
        super("Scout", "Nomadic Scout-like: 16 sonars all round (22.5 degree cones, 5 m)", new Body(190, 350, 23, 340, 1000, 300),
                ring(190, 22.5, 5000, 0, 22.5, 45, 67.5, 90, 112.5, 135, 157.5, 180, 202.5, 225, 247.5, 270, 292.5,
                        315, 337.5));
    }
}
