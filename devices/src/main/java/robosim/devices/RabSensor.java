package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;

/**
 * {@code rab}: the range-and-bearing messages a robot received this step: for each, nearest first, the sender's
 * distance (mm, between the devices), its bearing as this robot sees it (degrees from the heading, counter-clockwise,
 * in (-180, 180]; 0 on a model that senses none) and the bytes it sent, as the step it sent them left the world (the
 * Environment's medium: within the sender's range, its device of this model, and, where the model asks, in a line
 * clear of anything taller than it). Gaussian noise on the distance.
 */
@AutoService(RobotSensor.class)
public final class RabSensor extends RobotSensor {
    private static final Attribute MAX = Attribute.number("maxMessages", 16, "", "the most messages a step reads "
            + "(the nearest)").atLeast(1).atMost(256);
    private static final Attribute NOISE = Attribute.noise("mm");

    private RabModel model = RabModel.FOOT_BOT;
    private int most;
    private double noise;

    public RabSensor() {
        super(new SensorInfo("rab", "the range-and-bearing messages received this step", List.of(RabModel.ATTRIBUTE,
                MAX, NOISE), "per message, nearest first: its distance (mm), its bearing (deg) and its bytes (foot-bot "
                + "10, e-puck 2, kilobot 9), each 0 to 255", "", false, SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes a) {
        model = RabModel.of(RabModel.ATTRIBUTE.choose(a));
        most = (int) MAX.read(a);
        noise = NOISE.read(a);
        if (most * (2 + model.bytes()) > robosim.protocol.Limits.MAX_SENSOR_VALUES) {
            throw new IllegalArgumentException("maxMessages " + most + " of " + model.bytes() + " bytes gives more than "
                    + robosim.protocol.Limits.MAX_SENSOR_VALUES + " values");
        }
    }

    /** The most messages it reads a step (the nearest): the medium works out no more for it. */
    public int maxMessages() {
        return most;
    }

    /** Its model (the medium's concern: where it sits, whether it senses bearing, the message size it takes). */
    public RabModel model() {
        return model;
    }

    @Override
    public SensorValues values() {
        double[] low = new double[2 + model.bytes()];
        double[] high = new double[low.length];
        low[1] = -180;
        high[0] = model.rangeMm();
        high[1] = 180;
        for (int k = 2; k < high.length; k++) {
            high[k] = 255;
        }
        return SensorValues.groups(most, low, high, "");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        List<RabMessage> heard = c.rabReceived();
        int n = Math.min(most, heard.size());
        int width = 2 + model.bytes();
        double[] out = new double[n * width];
        for (int m = 0; m < n; m++) {
            RabMessage msg = heard.get(m);
            out[m * width] = noisy(msg.rangeMm(), noise, c, 0, model.rangeMm());
            out[m * width + 1] = msg.bearingDeg();
            for (int k = 0; k < model.bytes(); k++) {
                out[m * width + 2 + k] = msg.data(k);
            }
        }
        return out;
    }
}
