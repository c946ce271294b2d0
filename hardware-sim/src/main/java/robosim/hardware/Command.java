package robosim.hardware;

import robosim.devices.Drive;
import robosim.protocol.StepRequest;
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
    boolean plannedTag;
    StepRequest.Gripper plannedGripper = StepRequest.Gripper.STAY;
    boolean done;
    double result;
    /** What a tag hit ("" for nothing). */
    String text = "";

    abstract void plan(double stepSeconds);

    /** Returns true when the call is complete. */
    abstract boolean apply(StepResponse response, boolean messageArrived);

    /** {@code move(mm)} at {@code mmPerS}: at most mmPerS * step per step. */
    static Command move(double mm, double mmPerS) {
        return new Motion(mm, mmPerS, false);
    }

    /** {@code turn(deg)} at {@code degPerS}. */
    static Command turn(double deg, double degPerS) {
        return new Motion(deg, degPerS, true);
    }

    /** A move or a turn: pieces of at most rate * step until done or blocked. */
    private static final class Motion extends Command {
        private final double rate;
        private final boolean turn;
        private double remaining;

        Motion(double amount, double rate, boolean turn) {
            this.remaining = amount;
            this.rate = rate;
            this.turn = turn;
        }

        @Override
        void plan(double stepSeconds) {
            double piece = Drive.piece(remaining, rate, stepSeconds);
            plannedMoveMm = turn ? 0 : piece;
            plannedTurnDeg = turn ? piece : 0;
        }

        @Override
        boolean apply(StepResponse r, boolean messageArrived) {
            double planned = turn ? plannedTurnDeg : plannedMoveMm;
            double done = turn ? r.turnedDeg() : r.movedMm();
            result += done;
            remaining -= done;
            boolean blocked = Math.abs(done) < Math.abs(planned) - EPS;
            return blocked || Math.abs(remaining) <= EPS;
        }
    }

    /** One step in which the gripper takes what is in reach ({@code GRIP}) or lets go ({@code RELEASE}). */
    static Command gripper(StepRequest.Gripper what) {
        return new Command() {
            @Override
            void plan(double stepSeconds) {
                plannedMoveMm = 0;
                plannedTurnDeg = 0;
                plannedGripper = what;
            }

            @Override
            boolean apply(StepResponse r, boolean messageArrived) {
                text = r.gripped();
                return true;
            }
        };
    }

    /** One step that tags what is in front. */
    static Command tag() {
        return new Command() {
            @Override
            void plan(double stepSeconds) {
                plannedMoveMm = 0;
                plannedTurnDeg = 0;
                plannedTag = true;
            }

            @Override
            boolean apply(StepResponse r, boolean messageArrived) {
                text = r.tagged();
                return true;
            }
        };
    }

    /**
     * Let {@code steps} steps pass (or fewer if {@code untilMessage} and a message arrives), driving on the wheels at
     * {@code wheels} (left and right, mm/s, {@code wheelBaseMm} apart: {@link Drive#wheels}; 0 and 0 stand still).
     */
    static Command idle(long steps, boolean untilMessage, double[] wheels, double wheelBaseMm) {
        return new Command() {
            private long left = Math.max(1, steps);

            @Override
            void plan(double stepSeconds) {
                if (wheels[0] == 0 && wheels[1] == 0) {
                    plannedMoveMm = 0;
                    plannedTurnDeg = 0;
                    return;
                }
                double[] piece = Drive.wheels(wheels[0], wheels[1], wheelBaseMm, stepSeconds);
                plannedTurnDeg = piece[0];
                plannedMoveMm = piece[1];
            }

            @Override
            boolean apply(StepResponse r, boolean messageArrived) {
                return --left <= 0 || (untilMessage && messageArrived);
            }
        };
    }
}
