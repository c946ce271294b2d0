package robosim.sweep;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** {@code sweep.sh}'s main run in the test's JVM, for the sweep tests: its exit code and what it said on stderr. */
record SweepCommand(int code, String err) {
    /** Runs the main with {@code args} (one at a time: stderr is this JVM's). */
    static synchronized SweepCommand sweep(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream was = System.err;
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            return new SweepCommand(SweepMain.commandLine().execute(args), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setErr(was);
        }
    }

    /** {@code dir}/spec.xml: a sweep of {@code world}, 300 steps, seeds 1 and 2, and {@code body}. */
    static Path spec(Path dir, String world, String body) throws Exception {
        Path f = dir.resolve("spec.xml");
        Files.writeString(f, "<sweep world=\"" + world + "\" steps=\"300\"><seeds from=\"1\" to=\"2\"/>" + body
                + "</sweep>");
        return f;
    }

    /** The fields of one CSV line. */
    static List<String> fields(String line) throws java.io.IOException {
        return Csv.rows(line).get(0);
    }

    /** The lines of a runs.csv without their last column, {@code wall_s}. */
    static List<String> withoutWallTime(List<String> csv) throws java.io.IOException {
        List<String> out = new ArrayList<>();
        for (String line : csv) {
            List<String> f = SweepCommand.fields(line);
            out.add(String.join(",", f.subList(0, f.size() - 1)));
        }
        return out;
    }
}
