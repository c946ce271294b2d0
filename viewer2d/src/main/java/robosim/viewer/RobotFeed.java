package robosim.viewer;

import java.util.ArrayDeque;
import java.util.List;
import java.util.Locale;
import robosim.protocol.CommEvent;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepNumbers;
import robosim.protocol.WorldSnapshot;

/**
 * What a robot window shows, from a connection that watches one robot: the world's {@link Scene} (through
 * a {@link SceneFeed}: its pose, sonar, the run's state), the robot's newest {@link RobotView}, and a log of
 * its messages and notices, the newest {@link #LOG_LINES} lines. Written by the network thread (one at a
 * time, as {@link SceneFeed}); the Swing thread takes {@link #latest} and {@link #log}, both immutable.
 */
public final class RobotFeed implements RunFollower.Listener {
    public static final int LOG_LINES = 500;
    /** A log line shows at most this many characters of a message (network text, cleaned). */
    static final int MAX_TEXT = 200;

    private final String name;
    private final SceneFeed scenes;
    private final ArrayDeque<String> log = new ArrayDeque<>();
    private volatile RobotView view;
    private volatile long logged;

    /** Watches the robot called {@code name}. */
    public RobotFeed(String name) {
        this.name = name;
        this.scenes = new SceneFeed(System::nanoTime);
    }

    public String name() {
        return name;
    }

    /** The newest scene of the world (null before the snapshot). */
    public Scene latest() {
        return scenes.latest();
    }

    /** The robot's newest view (null before its first step). */
    public RobotView view() {
        return view;
    }

    /** Lines logged so far, ever (it changes whenever the log does). */
    public long logged() {
        return logged;
    }

    /** The log, oldest first. */
    public synchronized List<String> log() {
        return List.copyOf(log);
    }

    @Override
    public void snapshot(WorldSnapshot snapshot) {
        view = null;
        scenes.snapshot(snapshot);
        note("-- watching " + clean(name) + " in a run of " + snapshot.robotNames().size() + " robots");
    }

    @Override
    public void update(PoseUpdate update) {
        scenes.update(update);
    }

    @Override
    public void robotView(RobotView v) {
        long step = StepNumbers.shown(v.step());
        String at = v.sinceStep() == v.step() ? "step " + step : "steps " + StepNumbers.shown(v.sinceStep()) + "-" + step;
        if (v.leftOut() > 0) {
            note(at + ": " + v.leftOut() + " earlier messages and notices left out (this window skipped steps)");
        }
        for (CommEvent m : v.sent()) {
            note(at + "  out  to " + clean(m.to()) + ": " + clean(m.payload()));
        }
        for (CommEvent m : v.delivered()) {
            note(at + "  in   from " + clean(m.from()) + ": " + clean(m.payload()));
        }
        for (String n : v.notices()) {
            note(at + "  notice: " + clean(n));
        }
        view = v;
    }

    @Override
    public void runState(RunState state) {
        scenes.runState(state);
    }

    @Override
    public void end(SimulationEnd end) {
        scenes.end(end);
        noteOnce("-- the simulation ended at step " + StepNumbers.shown(end.lastStep()) + ": " + clean(end.reason()));
    }

    @Override
    public void lost(java.io.IOException cause) {
        scenes.lost(cause);
        noteOnce("-- connection lost: " + clean(String.valueOf(cause.getMessage())));
    }

    @Override
    public void between(String doing) {
        scenes.between(doing);
    }

    /** The newest line of the log ("" for none): what the window says before it has a world to show. */
    public synchronized String lastLine() {
        return log.isEmpty() ? "" : log.getLast();
    }

    /** A line, unless it is the last one already (a refusal repeated at every attempt to follow the next run). */
    private synchronized void noteOnce(String line) {
        if (!line.equals(log.peekLast())) {
            note(line);
        }
    }

    private synchronized void note(String line) {
        if (log.size() == LOG_LINES) {
            log.removeFirst();
        }
        log.addLast(line);
        logged++;
    }

    /** Network text for a line: control characters replaced, cut to {@link #MAX_TEXT} characters. */
    static String clean(String s) {
        return StatusLine.clean(s, MAX_TEXT);
    }

    /** A reading's values in short: all of a few, else how many and their range. */
    static String values(double[] v) {
        if (v.length <= 6) {
            StringBuilder b = new StringBuilder();
            for (double d : v) {
                b.append(b.length() == 0 ? "" : " ").append(String.format(Locale.ROOT, "%.1f", d));
            }
            return b.toString();
        }
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (double d : v) {
            min = Math.min(min, d);
            max = Math.max(max, d);
        }
        return String.format(Locale.ROOT, "%d values, %.0f to %.0f", v.length, min, max);
    }
}
