package robosim.environment.core;

/**
 * A world's loop functions threw (or could not be made): the run ends with {@link #getMessage()}, one line naming the
 * class, the call and the step, and the exit code a robot's failed control code gives.
 */
public final class ExperimentFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    ExperimentFailure(String message, Throwable cause) {
        super(message, cause);
    }
}
