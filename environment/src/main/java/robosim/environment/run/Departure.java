package robosim.environment.run;

/** A robot that left the run at {@code step}, and why (network text already made safe to print). */
public record Departure(String robot, long step, String why) {
}
