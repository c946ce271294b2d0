package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;

/**
 * {@code rab}: the bytes a robot's range-and-bearing device sends, every step from the one they are set in until set
 * again (each 0 to 255; as many as its model's message holds); it sends nothing before they are first set.
 */
@AutoService(RobotActuator.class)
public final class RabActuator extends RobotActuator {
    private static final Attribute RANGE = Attribute.number("rangeMm", 0, "mm", "how far its messages carry, up to "
            + "its model's (0: its model's)").atLeast(0);

    private RabModel model = RabModel.FOOT_BOT;
    private double rangeMm;
    private int[] data;

    public RabActuator() {
        super(new ActuatorInfo("rab", "the bytes the range-and-bearing device sends each step",
                List.of(RabModel.ATTRIBUTE, RANGE), "the message, one byte a value, 0 to 255 (foot-bot 10, e-puck 2, "
                        + "kilobot 9)"));
    }

    @Override
    protected void configure(Attributes a) {
        model = RabModel.of(RabModel.ATTRIBUTE.choose(a));
        double r = RANGE.read(a);
        if (r > model.rangeMm()) { // (its receivers' readings and bounds stop at the model's range)
            throw new IllegalArgumentException("rangeMm " + Attribute.plain(r) + " is beyond a " + model.word()
                    + "'s range, " + Attribute.plain(model.rangeMm()) + " mm");
        }
        rangeMm = r > 0 ? r : model.rangeMm();
    }

    @Override
    public ActuatorValues values() {
        return new ActuatorValues(model.bytes(), 0, 255, true);
    }

    @Override
    protected void apply(double[] values) {
        int[] d = new int[values.length];
        for (int k = 0; k < d.length; k++) {
            d[k] = (int) values[k];
        }
        data = d;
    }

    public RabModel model() {
        return model;
    }

    /** How far its messages carry, mm. */
    public double rangeMm() {
        return rangeMm;
    }

    /** The bytes it sends, or null before they are first set. Do not change. */
    public int[] data() {
        return data;
    }
}
