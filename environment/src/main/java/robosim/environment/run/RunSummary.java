package robosim.environment.run;

import java.util.List;

/**
 * How a run went; {@code steps}: steps completed (responses out, as the control port's); {@code departures} says, for
 * each robot that left mid-run, when and why; {@code experimentFailed}: the world's loop functions threw (the reason
 * says where).
 */
public record RunSummary(long steps, int robots, double wallSeconds, String reason, boolean completed,
        long messagesDelivered, long messagesOutOfRange, long messagesRefused, int robotsRemoved,
        int geometryLosses, int geometryAttaches, List<Departure> departures, boolean experimentFailed) {
    /** The Environment's last line: {@code summary steps=... robots=... wall_s=... steps_per_s=...}. */
    public String line() {
        double wall = Math.max(wallSeconds, 1e-9);
        return String.format(java.util.Locale.ROOT,
                "summary steps=%d robots=%d wall_s=%.3f steps_per_s=%.1f robot_steps_per_s=%.1f messages=%d"
                        + " messages_out_of_range=%d messages_refused=%d robots_removed=%d geometry_losses=%d"
                        + " geometry_attaches=%d",
                steps, robots, wallSeconds, steps / wall, steps * robots / wall, messagesDelivered, messagesOutOfRange,
                messagesRefused, robotsRemoved, geometryLosses, geometryAttaches);
    }
}
