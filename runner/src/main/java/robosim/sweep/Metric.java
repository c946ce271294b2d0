package robosim.sweep;

import java.io.IOException;
import robosim.protocol.RecordingReader;

/**
 * A metric of one's own: a public class with a public no-argument constructor, named in a sweep file
 * ({@code <metric class="my.Metric"/>}) and found on the class path ({@code ROBOSIM_CLASSPATH}). It computes one
 * number of a run from the run's recording, so a recording alone gives it again
 * ({@code scripts/record-tool.sh metrics FILE --metric CLASS}).
 */
public interface Metric {
    /** The column's name in the tables: 1 to 64 letters, digits, {@code _ . -}. */
    String name();

    /** The run's value (a finite number), read from its recording; an exception fails the run's row. */
    double value(RecordingReader recording) throws IOException;
}
