package robosim.environment.net;

import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;
import robosim.protocol.StepRequest;

/**
 * The one check of a robot's requests, whatever carries them, on the thread that reads them (its worker, a shared
 * connection's reader, the {@code SEQUENTIAL} stepper): each must be for the step due (the first the robot was
 * given, then one after another), a step the loop has given it, with finite numbers. The loop says what it has
 * given; a request that fails the check is a {@link ProtocolException} that names the values.
 */
final class RequestOrder {
    /** " for robot NAME" in a fault of a robot of a shared connection; "" for one over a socket of its own. */
    private final String forRobot;
    /** "robot NAME " as what was asked to move; "" for one over a socket of its own. */
    private final String robot;
    /** The last step number the loop has handed this robot (-1 before the first). */
    private volatile long given = -1;
    /** The first step number the loop handed this robot: 0, or a later one for a robot that came back. */
    private volatile long first = -1;
    /** The reader's (one thread at a time; the SEQUENTIAL worker hands it to the stepper): the step due next, -1 for its first. */
    private long due = -1;

    /** {@code name}: the robot's, when several robots share its connection (the faults name it); else null. */
    RequestOrder(String name) {
        this.forRobot = name == null ? "" : " for robot " + Printable.of(name);
        this.robot = name == null ? "" : "robot " + Printable.of(name) + " ";
    }

    /** Loop thread: the robot is given its first step. */
    void begin(long firstStep) {
        first = firstStep;
        given = firstStep;
    }

    /** Loop thread: the robot is given step {@code next}. */
    void given(long next) {
        given = next;
    }

    /** The last step the robot was given (-1 before the first). */
    long given() {
        return given;
    }

    /** True once the robot has been given a step number. */
    boolean begun() {
        return given >= 0;
    }

    /** The reader: checks the robot's next request. */
    void check(StepRequest request) throws ProtocolException {
        long g = given;
        if (g < 0) {
            throw new ProtocolException("sent a request" + forRobot + " before the simulation started");
        }
        long k = due < 0 ? first : due;
        if (request.step() != k || k > g) {
            throw new ProtocolException("sent a request for step " + request.step() + forRobot + " where step "
                    + Math.min(k, g) + " was due");
        }
        if (!Double.isFinite(request.moveMm()) || !Double.isFinite(request.turnDeg())) {
            throw new ProtocolException("asked " + robot + "to move " + request.moveMm() + " mm and turn "
                    + request.turnDeg() + " deg");
        }
        due = k + 1;
    }
}
