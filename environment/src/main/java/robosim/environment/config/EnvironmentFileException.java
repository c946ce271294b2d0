package robosim.environment.config;

/**
 * An environment file that cannot be used; the message is one line per fault, each naming the file (and, for a
 * fault in the file, the line and column where the element at fault starts), the element and the fault.
 */
public final class EnvironmentFileException extends Exception {
    private static final long serialVersionUID = 1L;

    public EnvironmentFileException(String message) {
        super(message);
    }
}
