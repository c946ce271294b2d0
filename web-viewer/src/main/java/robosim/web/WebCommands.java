package robosim.web;

/**
 * What a page may ask of the Environment or replay it watches, one request line at a time
 * ({@code status}, {@code pause}, {@code resume}, {@code step N}, {@code seek K}, {@code speed X}: the
 * control port's requests, served in-process); the reply is the control port's JSON line.
 */
@FunctionalInterface
public interface WebCommands {
    String handle(String verb, String arg) throws Exception;
}
