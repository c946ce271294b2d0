package robosim.api;

/** A text message from another robot. */
public record Message(String from, String text) {
}
