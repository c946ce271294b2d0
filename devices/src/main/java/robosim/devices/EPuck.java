package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.LedSpec;

/**
 * {@code e-puck}: the e-puck, as ARGoS models it ({@code src/plugins/robots/e-puck} of ilpincy/argos3: radius 35 mm,
 * height 86 mm, 0.4 kg, wheels 53 mm apart); its top speed the e-puck's 12.9 cm/s (Mondada et al., 2009), its turn what
 * its wheels at that speed give. It carries 8 proximity rays of 50 mm from the rim at 17, 50, 90, 150, -150, -90, -50
 * and -17 degrees (its law reads 0 beyond 50 mm); 8 light sensors from 22.5 degrees every 45; 3 ground sensors; a
 * range-and-bearing device (0.8 m, 2 bytes); and 8 LEDs in a ring 42 mm out, 86 mm up, from 11.25 degrees every 45.
 */
@AutoService(RobotType.class)
public final class EPuck extends RobotType {
    static final double RADIUS_MM = 35;
    static final double TOP_SPEED_MM_PER_S = 129;
    static final double WHEEL_BASE_MM = 53;

    public EPuck() {
        super("e-puck", "the e-puck: 8 proximity, 8 light and 3 ground sensors, range-and-bearing, 8 LEDs",
                new Body(RADIUS_MM, 86, 0.4, WHEEL_BASE_MM, TOP_SPEED_MM_PER_S,
                        Math.toDegrees(2 * TOP_SPEED_MM_PER_S / WHEEL_BASE_MM)), List.of(),
                rays(RADIUS_MM, 50, 17, 50, 90, 150, -150, -90, -50, -17), LedSpec.ring(8, 42, 86, 11.25), null,
                List.of(DeviceSpec.sensor("proximity", "model", "e-puck"), DeviceSpec.sensor("light", "model", "e-puck"),
                        DeviceSpec.sensor("ground", "model", "e-puck"), DeviceSpec.sensor("rab", "model", "e-puck"),
                        DeviceSpec.actuator("rab", "model", "e-puck"), DeviceSpec.actuator("leds")));
    }

    /** Its wheels drive it along what blocks it, as ARGoS's dynamics2d does. */
    @Override
    public boolean slides() {
        return true;
    }
}
