package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.LedSpec;

/**
 * {@code kilobot}: the Kilobot, as ARGoS models it (ilpincy/argos3-kilobot: radius 16.5 mm, height 34.4 mm, 10 g, legs
 * 25 mm apart; its body taken as centred between its legs); its speed the Kilobot's 1 cm/s (Rubenstein et al., 2012:
 * 1 cm/s and about 45 degrees a second), its turn what its legs at that speed give, 45.8 degrees a second. It carries an ambient light sensor, infrared messages of 9 bytes to the robots within
 * 10 cm that sense their distance but not their bearing (its range-and-bearing device of the {@code kilobot} model),
 * and one RGB LED on top (any colour here; the Kilobot's has 4 levels a channel).
 */
@AutoService(RobotType.class)
public final class Kilobot extends RobotType {
    public Kilobot() {
        super("kilobot", "the Kilobot: an ambient light sensor, messages within 10 cm with their distance, one RGB LED",
                new Body(16.5, 34.4, 0.01, 25, 10, Math.toDegrees(2 * 10 / 25.0)), List.of(), List.of(), List.of(new LedSpec(0, 0, 34.4)), null,
                List.of(DeviceSpec.sensor("light", "model", "kilobot"), DeviceSpec.sensor("rab", "model", "kilobot"),
                        DeviceSpec.actuator("rab", "model", "kilobot"), DeviceSpec.actuator("leds")));
    }

    /** Its wheels drive it along what blocks it, as ARGoS's dynamics2d does. */
    @Override
    public boolean slides() {
        return true;
    }
}
