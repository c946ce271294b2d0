package robosim.environment.net;

import java.util.List;

/** How a run went; {@code departures} says, for each robot that left mid-run, when and why. */
public record RunSummary(long steps, int robots, double wallSeconds, String reason, boolean completed,
        long messagesDelivered, long messagesOutOfRange, long messagesRefused, int robotsLeft,
        int geometryLosses, int geometryAttaches, List<Departure> departures) {
}
