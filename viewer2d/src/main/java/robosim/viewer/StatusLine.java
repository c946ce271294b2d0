package robosim.viewer;

import java.util.Locale;
import robosim.protocol.StepNumbers;

/**
 * The viewer's status line, from a {@link Scene}: the step, the robot count, the run's state (with
 * the steps per second only while it runs and once measured), why it stopped, and what the viewer
 * is doing meanwhile. Text from the network (reasons) has its control characters replaced and is cut
 * to {@link #MAX_REASON} characters.
 */
public final class StatusLine {
    static final int MAX_REASON = 160;
    static final String KEYS = "[f fit, wheel/+/- zoom, drag/arrows pan, t trails, s sonar, n names]";

    private StatusLine() {
    }

    /** The state part alone, e.g. {@code RUNNING  10 steps/s}, {@code PAUSED}, {@code STOPPED: why}. */
    public static String state(Scene s) {
        ViewedRun r = s.status();
        String text = switch (r.kind()) {
            case WAITING_FOR_ROBOTS -> "waiting for robots";
            case RUNNING -> Double.isNaN(s.stepsPerSecond()) ? "RUNNING"
                    : String.format(Locale.ROOT, "RUNNING  %.0f steps/s", s.stepsPerSecond());
            case PAUSED -> "PAUSED";
            case STOPPED -> "STOPPED: " + clean(r.reason());
            case LOST -> "connection lost: " + clean(r.reason());
        };
        return r.next().isEmpty() ? text : text + " - " + r.next();
    }

    /** The step a window shows for {@code s}: steps completed ({@link StepNumbers}; 0 before the first). */
    public static long step(Scene s) {
        return StepNumbers.shown(s.step());
    }

    /** The whole line under the world. */
    public static String text(Scene s) {
        return String.format(Locale.ROOT, "step %d   %d robots   %s      %s", step(s), s.robotCount(), state(s), KEYS);
    }

    private static String clean(String reason) {
        return clean(reason, MAX_REASON);
    }

    /** Text from the network for a window: control characters as '?', at most {@code max} characters ("..." after). */
    static String clean(String s, int max) {
        StringBuilder out = new StringBuilder(Math.min(s.length(), max + 3));
        s.codePoints().limit(max).forEach(c -> out.appendCodePoint(Character.isISOControl(c) ? '?' : c));
        return s.codePointCount(0, s.length()) > max ? out + "..." : out.toString();
    }
}
