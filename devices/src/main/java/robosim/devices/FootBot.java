package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.LedSpec;
import robosim.protocol.RobotProperties;

/**
 * {@code foot-bot}: the Swarmanoid foot-bot (the marXbot), as ARGoS models it ({@code src/plugins/robots/foot-bot} of
 * ilpincy/argos3: radius 85.036758 mm, height 146.899733 mm, 1.6 kg, wheels 140 mm apart); its top speed the marXbot's
 * 30 cm/s (Bonani et al., 2010), its turn what its wheels at that speed give. It carries 24 proximity rays of 100 mm
 * from the rim, from 7.5 degrees every 15; 24 light sensors likewise; 4 ground (motor-ground) sensors; a
 * range-and-bearing device (3 m, 10 bytes); an omnidirectional camera; 12 LEDs in a ring 90 mm out, 85 mm up, from 15
 * degrees every 30, and a beacon on top (LED 12); and a gripper at its front (reaching 10 mm, 30 degrees either side).
 */
@AutoService(RobotType.class)
public final class FootBot extends RobotType {
    static final double RADIUS_MM = 85.036758;
    static final double TOP_SPEED_MM_PER_S = 300;
    static final double WHEEL_BASE_MM = 140;

    public FootBot() {
        super("foot-bot", "the Swarmanoid foot-bot: 24 proximity, 24 light and 4 ground sensors, range-and-bearing, a "
                + "camera, 12 LEDs and a beacon, a gripper", new Body(RADIUS_MM, 146.899733, 1.6, WHEEL_BASE_MM,
                TOP_SPEED_MM_PER_S, Math.toDegrees(2 * TOP_SPEED_MM_PER_S / WHEEL_BASE_MM)), List.of(),
                rays(RADIUS_MM, 100, evenly(24, 7.5)), leds(), new RobotProperties.Gripper(10, 30),
                List.of(DeviceSpec.sensor("proximity", "model", "foot-bot"), DeviceSpec.sensor("light", "model",
                        "foot-bot"), DeviceSpec.sensor("ground", "model", "foot-bot"), DeviceSpec.sensor("rab", "model",
                        "foot-bot"), DeviceSpec.sensor("camera"), DeviceSpec.actuator("rab", "model", "foot-bot"),
                        DeviceSpec.actuator("leds")));
    }

    private static List<LedSpec> leds() {
        List<LedSpec> all = new ArrayList<>(LedSpec.ring(12, RADIUS_MM + 5, 85, 15));
        all.add(new LedSpec(0, 0, 174.249733));
        return all;
    }

    /** Its wheels drive it along what blocks it, as ARGoS's dynamics2d does. */
    @Override
    public boolean slides() {
        return true;
    }
}
