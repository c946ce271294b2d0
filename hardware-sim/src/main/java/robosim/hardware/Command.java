package robosim.hardware;

import robosim.protocol.StepResponse;

/**
 * A blocking robot call, cut into time-step pieces by the Hardware Simulator thread. {@link #plan}
 * gives this step's piece; {@link #apply} takes the Environment's answer and says whether the call
 * is done. Touched only by the Hardware Simulator thread while the control thread waits on it.
 */
abstract class Command {
    private static final double EPS = 1e-9;

    double plannedMoveMm;
    double plannedTurnDeg;
    boolean done;
    double result;

    abstract void plan(double stepSeconds);

    /** Returns true when the call is complete. */
    abstract boolean apply(StepResponse response, boolean messageArrived);

    /** {@code move(mm)} at {@code mmPerS}: at most mmPerS * step per step. */
    static Command move(double mm, double mmPerS) {
        return new Command() {
            private double remaining = mm;

            @Override
            void plan(double stepSeconds) {
                plannedMoveMm = Math.copySign(Math.min(Math.abs(remaining), mmPerS * stepSeconds), remaining);
                plannedTurnDeg = 0;
            }

            @Override
            boolean apply(StepResponse r, boolean messageArrived) {
                result += r.movedMm();
                remaining -= r.movedMm();
                boolean blocked = Math.abs(r.movedMm()) < Math.abs(plannedMoveMm) - EPS;
                return blocked || Math.abs(remaining) <= EPS;
            }
        };
    }

    /** {@code turn(deg)} at {@code degPerS}. */
    static Command turn(double deg, double degPerS) {
        return new Command() {
            private double remaining = deg;

            @Override
            void plan(double stepSeconds) {
                plannedMoveMm = 0;
                plannedTurnDeg = Math.copySign(Math.min(Math.abs(remaining), degPerS * stepSeconds), remaining);
            }

            @Override
            boolean apply(StepResponse r, boolean messageArrived) {
                result += r.turnedDeg();
                remaining -= r.turnedDeg();
                boolean blocked = Math.abs(r.turnedDeg()) < Math.abs(plannedTurnDeg) - EPS;
                return blocked || Math.abs(remaining) <= EPS;
            }
        };
    }

    /** Stand still for {@code steps} steps, or fewer if {@code untilMessage} and a message arrives. */
    static Command idle(long steps, boolean untilMessage) {
        return new Command() {
            private long left = Math.max(1, steps);

            @Override
            void plan(double stepSeconds) {
                plannedMoveMm = 0;
                plannedTurnDeg = 0;
            }

            @Override
            boolean apply(StepResponse r, boolean messageArrived) {
                return --left <= 0 || (untilMessage && messageArrived);
            }
        };
    }
}
