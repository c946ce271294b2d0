package robosim.environment.config;

import java.util.HashSet;
import java.util.Set;

/**
 * An element of an environment file as read ({@link EnvironmentFile} and its parts): where its start tag begins, set
 * by {@link PositionedXmlModule} as it is read, and which of its attributes held a value not of their type (each
 * already a fault of its own, so no check reports it again as missing). Neither is an attribute of the file.
 */
abstract class FileElement {
    /** Where its start tag begins; null if the parser could not say. */
    FilePosition at;
    private final Set<String> badValues = new HashSet<>();

    /** {@code attribute}'s value was not of its type: it was read as absent, its fault recorded. */
    void badValue(String attribute) {
        badValues.add(attribute);
    }

    /** Whether {@code attribute} is absent because its value was not of its type (a fault already recorded). */
    boolean hadBadValue(String attribute) {
        return badValues.contains(attribute);
    }
}
