package robosim.runner;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import robosim.protocol.PoseUpdate;
import robosim.protocol.StepNumbers;
import robosim.protocol.WorldSnapshot;
import robosim.sweep.Csv;

/**
 * Writes {@code step,robot,x_m,y_m,heading_deg,state}, one row per robot per step, from a recording viewer
 * ({@code step}: steps completed, the number a person is shown, so the row of step 900 is the world the replay's
 * {@code seek 900} shows, after 900 steps; protocol/README.md, "Step numbers");
 * {@code state} is {@code running}, {@code held} (lost, standing for its return: {@code --on-robot-loss HOLD}
 * or {@code WAIT}) or {@code gone}, so a robot's holds and returns show with their steps.
 */
public final class PoseLog implements AutoCloseable {
    private final BufferedWriter out;
    private List<String> names = List.of();
    /** Steps written (the {@code viewer-client} thread writes; read after the end). */
    private volatile long steps;

    /** Writes to {@code file} as {@code options} say (none: create or replace it). */
    public PoseLog(Path file, java.nio.file.OpenOption... options) throws IOException {
        out = Files.newBufferedWriter(file, StandardCharsets.UTF_8, options);
        out.write(HEADER);
    }

    void snapshot(WorldSnapshot s) {
        names = s.robotNames();
    }

    /** The robots' names, in the order of the updates' poses (a world without a snapshot: the simulation host's). */
    public void names(List<String> robots) {
        names = List.copyOf(robots);
    }

    /** Writes the update's rows. */
    public void update(PoseUpdate u) {
        try {
            write(u, names, out);
            steps++;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The header of every pose log. */
    static final String HEADER = Csv.line(List.of("step", "robot", "x_m", "y_m", "heading_deg", "state"));

    /** One step's rows: each robot's pose, in snapshot order ({@code names}). */
    static void write(PoseUpdate u, List<String> names, java.io.Writer out) throws IOException {
        String step = Long.toString(StepNumbers.shown(u.step()));
        for (int i = 0; i < u.count(); i++) {
            String name = names.get(i);
            String state = u.departed().contains(name) ? "gone" : u.held().contains(name) ? "held" : "running";
            out.write(Csv.line(List.of(step, name, Double.toString(u.xMm(i) / 1000.0),
                    Double.toString(u.yMm(i) / 1000.0), Double.toString(u.headingDeg(i)), state)));
        }
    }

    long steps() {
        return steps;
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
