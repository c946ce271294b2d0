package robosim.sweep;

import java.io.IOException;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;

/** A metric of one's own for the tests: where the robots end, the mean of their x, m. */
public final class MeanFinalX implements Metric {
    @Override
    public String name() {
        return "mean_final_x_m";
    }

    @Override
    public double value(RecordingReader recording) throws IOException {
        PoseUpdate last = recording.step(recording.steps() - 1).update();
        double sum = 0;
        for (int r = 0; r < last.count(); r++) {
            sum += last.xMm(r);
        }
        return sum / last.count() / 1000;
    }
}
