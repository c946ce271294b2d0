package robosim.sweep;

/** A sweep that cannot run as asked: one line naming the file or directory, the value and what is wrong. */
public final class SweepException extends Exception {
    public SweepException(String message) {
        super(message);
    }
}
