package robosim.environment.config;

/** An environment file that cannot be used; the message is one line naming the file, the element and the fault. */
public final class EnvironmentFileException extends Exception {
    private static final long serialVersionUID = 1L;

    public EnvironmentFileException(String message) {
        super(message);
    }
}
