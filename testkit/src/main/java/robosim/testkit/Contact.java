package robosim.testkit;

/** A robot touched something during {@code step}: a wall, an obstacle or a robot, by name, as its bumper says. */
public record Contact(long step, String with) {
}
