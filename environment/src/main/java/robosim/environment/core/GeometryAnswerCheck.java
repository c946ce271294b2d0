package robosim.environment.core;

import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ProtocolException;

/**
 * Checks Geometry's answer to one step before any of it is used: the step and robot count asked,
 * finite distances no longer than asked (Geometry only ever shortens a motion), contacts that name a
 * robot, obstacle or the arena that exists, and exactly the sonar ranges asked for, each finite and
 * not negative. An answer from another process is hostile until proven otherwise.
 */
final class GeometryAnswerCheck {
    private static final double SLACK = 1e-6;

    private GeometryAnswerCheck() {
    }

    /**
     * @param sonars robot i's sonar count
     * @throws ProtocolException naming what is wrong
     */
    static void check(GeometryStepRequest asked, GeometryStepResponse answer, int[] sonars, int obstacles)
            throws ProtocolException {
        int robots = sonars.length;
        if (answer.step() != asked.step() || answer.count() != robots) {
            throw new ProtocolException("geometry answered step " + answer.step() + " for " + answer.count()
                    + " robots, expected step " + asked.step() + " for " + robots);
        }
        int ranges = 0;
        for (int i = 0; i < robots; i++) {
            double moved = answer.movedMm(i);
            double turned = answer.turnedDeg(i);
            if (!Double.isFinite(moved) || Math.abs(moved) > Math.abs(asked.moveMm(i)) + SLACK
                    || !Double.isFinite(turned) || Math.abs(turned) > Math.abs(asked.turnDeg(i)) + SLACK) {
                throw new ProtocolException("geometry moved robot " + i + " by " + moved + " mm and " + turned
                        + " deg, asked " + asked.moveMm(i) + " mm and " + asked.turnDeg(i) + " deg");
            }
            int index = answer.contactIndex(i);
            boolean contactOk = switch (answer.contactKind(i)) {
                case GeometryStepResponse.CONTACT_NONE, GeometryStepResponse.CONTACT_ARENA -> true;
                case GeometryStepResponse.CONTACT_ROBOT -> index >= 0 && index < robots && index != i;
                case GeometryStepResponse.CONTACT_OBSTACLE -> index >= 0 && index < obstacles;
                default -> false;
            };
            if (!contactOk) {
                throw new ProtocolException("geometry gave robot " + i + " contact kind " + answer.contactKind(i)
                        + " with index " + index + ", which does not exist");
            }
            if (asked.wantsSonar(i)) {
                ranges += sonars[i];
            }
        }
        if (answer.rangeCount() != ranges) {
            throw new ProtocolException("geometry returned " + answer.rangeCount() + " sonar ranges, expected "
                    + ranges);
        }
        for (int r = 0; r < ranges; r++) {
            double mm = answer.rangeMm(r);
            if (!(mm >= 0) || Double.isInfinite(mm)) {
                throw new ProtocolException("geometry returned sonar range " + mm + " mm");
            }
        }
    }
}
