package robosim.testkit;

/** A message a robot received: the step whose response carried it, who sent it, its text. */
public record Received(long step, String from, String text) {
}
