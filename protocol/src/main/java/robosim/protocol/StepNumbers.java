package robosim.protocol;

/**
 * The one step number a person is shown (protocol/README.md, "Step numbers"): steps completed, the number of
 * steps whose responses have gone out. The wire counts steps from 0 ({@link PoseUpdate#step}, {@link RobotView#step},
 * {@link SimulationEnd#lastStep}; -1 before the first), so the world after wire step k is shown as step k + 1, the
 * (k + 1)th step; {@link RunState#step} is a count already. Every display, control reply, log line and summary
 * converts here, at its edge; no message changes.
 */
public final class StepNumbers {
    private StepNumbers() {
    }

    /** The number shown for the world after wire step {@code step} (-1 before the first: 0). */
    public static long shown(long step) {
        return step + 1;
    }

    /** The wire step whose world is shown as {@code shown} (0: -1, before the first). */
    public static long wire(long shown) {
        return shown - 1;
    }
}
