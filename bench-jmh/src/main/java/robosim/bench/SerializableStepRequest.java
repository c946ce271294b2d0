package robosim.bench;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

/**
 * The same fields as {@link robosim.protocol.StepRequest}, written by default Java serialization:
 * the baseline the original RoboSim used. For measurement only.
 */
public final class SerializableStepRequest implements Serializable {
    private static final long serialVersionUID = 1L;

    long step;
    double moveMm;
    double turnDeg;
    boolean sonar;
    ArrayList<String> messages = new ArrayList<>();
    ArrayList<String> sensors = new ArrayList<>();
    boolean tag;

    SerializableStepRequest(long step, double moveMm, List<String> sensors) {
        this.step = step;
        this.moveMm = moveMm;
        this.sonar = true;
        this.sensors = new ArrayList<>(sensors);
    }
}
