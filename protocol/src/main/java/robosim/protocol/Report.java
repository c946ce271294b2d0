package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * A value the control code reported for its run ({@code Robot.report(name, value)}), carried in the step's
 * {@link StepRequest} and recorded in the robot's {@link RobotView}: a name of 1 to {@link #MAX_NAME_CHARS}
 * letters, digits, {@code _ . -}, and a finite number. A sweep's metrics read them from the recording.
 */
public record Report(String name, double value) {
    /** The longest report name, characters. */
    public static final int MAX_NAME_CHARS = 64;
    /** The most names one robot reports in one step. */
    public static final int MAX_PER_STEP = 64;

    public Report {
        String bad = problem(name, value);
        if (bad != null) {
            throw new IllegalArgumentException(bad);
        }
    }

    /** What is wrong with this name and value, or null. */
    public static String problem(String name, double value) {
        if (name == null || name.isEmpty() || name.length() > MAX_NAME_CHARS || !name.chars().allMatch(
                c -> c < 128 && (Character.isLetterOrDigit(c) || c == '_' || c == '.' || c == '-'))) {
            return "a report name must be 1 to " + MAX_NAME_CHARS + " letters, digits, '_', '.' or '-', got "
                    + Printable.of(name, MAX_NAME_CHARS);
        }
        if (!Double.isFinite(value)) {
            return "report " + name + ": the value must be a finite number, got " + value;
        }
        return null;
    }

    /** Writes a count and each report. */
    static void write(ObjectOutput out, List<Report> reports) throws IOException {
        out.writeShort(reports.size());
        for (Report r : reports) {
            out.writeUTF(r.name);
            out.writeDouble(r.value);
        }
    }

    /** Reads what {@link #write} wrote: at most {@code max} reports, each checked. */
    static List<Report> read(ObjectInput in, int max) throws IOException {
        int n = Limits.checkCount("report count", in.readUnsignedShort(), max);
        if (n == 0) {
            return List.of();
        }
        List<Report> reports = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            String name = in.readUTF();
            double value = in.readDouble();
            String bad = problem(name, value);
            if (bad != null) {
                throw new ProtocolException(bad);
            }
            reports.add(new Report(name, value));
        }
        return List.copyOf(reports);
    }
}
