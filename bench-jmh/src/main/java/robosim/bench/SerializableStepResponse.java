package robosim.bench;

import java.io.Serializable;
import java.util.ArrayList;

/** The same fields as {@link robosim.protocol.StepResponse}, by default Java serialization. */
public final class SerializableStepResponse implements Serializable {
    private static final long serialVersionUID = 1L;

    long step;
    double movedMm;
    double turnedDeg;
    String contact = "";
    double xMm;
    double yMm;
    double headingDeg;
    double[] sonarMm;
    ArrayList<String> inbox = new ArrayList<>();
    ArrayList<String> notices = new ArrayList<>();
    ArrayList<double[]> readings = new ArrayList<>();
    String tagged = "";

    SerializableStepResponse(long step, double[] sonarMm) {
        this.step = step;
        this.movedMm = 250;
        this.xMm = 1000;
        this.yMm = 2000;
        this.sonarMm = sonarMm;
    }
}
