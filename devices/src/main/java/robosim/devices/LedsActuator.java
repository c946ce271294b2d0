package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.RobotProperties;

/**
 * {@code leds}: the robot's LEDs (its type's, where its {@code LedSpec}s put them), each a colour ({@code 0xRRGGBB};
 * black, 0, is off), all off at the start. Cameras see the lit ones; viewers draw them.
 */
@AutoService(RobotActuator.class)
public final class LedsActuator extends RobotActuator {
    private int[] colours = new int[0];

    public LedsActuator() {
        super(new ActuatorInfo("leds", "the robot's LEDs, each a colour", List.of(),
                "one colour an LED, 0xRRGGBB (0, black, is off), in the type's order"));
    }

    @Override
    protected void mount(RobotProperties robot) {
        colours = new int[robot == null ? 0 : robot.leds().size()];
    }

    @Override
    public ActuatorValues values() {
        return new ActuatorValues(colours.length, 0, 0xFFFFFF, true);
    }

    @Override
    protected void apply(double[] values) {
        for (int k = 0; k < colours.length; k++) {
            colours[k] = (int) values[k];
        }
    }

    /** Each LED's colour now. Do not change. */
    public int[] colours() {
        return colours;
    }
}
