package robosim.environment.core;

import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ProtocolException;

/**
 * Checks Geometry's answer to one step before any of it is used: the step and robot count asked,
 * finite distances no longer than asked (Geometry only ever shortens a motion), contacts that name a
 * robot, obstacle, object or the arena that exists, exactly the sonar ranges and proximity rays asked for, each finite
 * and not negative, every object's pose finite and inside the arena (a fixed one's unchanged), and a catch only for a
 * robot that asked to grip, of a gripable object that exists and that no one holds or took this step; a slide only of
 * a robot that slides, finite, no longer than what was left of its move. An answer from
 * another process is hostile until proven otherwise.
 */
final class GeometryAnswerCheck {
    private static final double SLACK = 1e-6;

    private GeometryAnswerCheck() {
    }

    /**
     * @param sonars robot i's sonar count
     * @param rays robot i's proximity ray count
     * @throws ProtocolException naming what is wrong
     */
    static void check(GeometryStepRequest asked, GeometryStepResponse answer, int[] sonars, int[] rays, int obstacles,
            Arena arena, java.util.List<robosim.protocol.WorldObject> things) throws ProtocolException {
        int robots = sonars.length;
        int objects = asked.objectCount();
        if (answer.step() != asked.step() || answer.count() != robots || answer.objectCount() != objects) {
            throw new ProtocolException("geometry answered step " + answer.step() + " for " + answer.count()
                    + " robots and " + answer.objectCount() + " objects, expected step " + asked.step() + " for "
                    + robots + " and " + objects);
        }
        int ranges = 0;
        int rayTotal = 0;
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
                case GeometryStepResponse.CONTACT_OBJECT -> index >= 0 && index < objects
                        && asked.carrier(index) != GeometryStepRequest.GONE;
                default -> false;
            };
            if (!contactOk) {
                throw new ProtocolException("geometry gave robot " + i + " contact kind " + answer.contactKind(i)
                        + " with index " + index + ", which does not exist");
            }
            if (asked.wantsSonar(i)) {
                ranges += sonars[i];
            }
            if (asked.wantsRays(i)) {
                rayTotal += rays[i];
            }
        }
        if (answer.rangeCount() != ranges || answer.rayCount() != rayTotal) {
            throw new ProtocolException("geometry returned " + answer.rangeCount() + " sonar ranges and "
                    + answer.rayCount() + " rays, expected " + ranges + " and " + rayTotal);
        }
        for (int r = 0; r < ranges; r++) {
            double mm = answer.rangeMm(r);
            if (!(mm >= 0) || Double.isInfinite(mm)) {
                throw new ProtocolException("geometry returned sonar range " + mm + " mm");
            }
        }
        for (int r = 0; r < rayTotal; r++) {
            double mm = answer.rayMm(r);
            if (!(mm >= 0) || Double.isInfinite(mm)) {
                throw new ProtocolException("geometry returned ray range " + mm + " mm");
            }
        }
        for (int o = 0; o < objects; o++) {
            double x = answer.objectXMm(o);
            double y = answer.objectYMm(o);
            if (!(x >= arena.minXMm() && x <= arena.maxXMm() && y >= arena.minYMm() && y <= arena.maxYMm())
                    || !Double.isFinite(answer.objectHeadingDeg(o))) {
                throw new ProtocolException("geometry put object " + o + " at (" + x + ", " + y + ") heading "
                        + answer.objectHeadingDeg(o) + ", outside the arena or not a pose");
            }
            if ((!things.get(o).movable() || asked.carrier(o) == GeometryStepRequest.GONE)
                    && (x != asked.objectXMm(o) || y != asked.objectYMm(o)
                    || answer.objectHeadingDeg(o) != asked.objectHeadingDeg(o))) {
                throw new ProtocolException("geometry moved object " + o + ", which is fixed or out of the world");
            }
        }
        int before = -1;
        for (int k = 0; k < answer.slideCount(); k++) {
            int robot = answer.slideRobot(k);
            if (robot <= before || robot >= robots || !asked.slides(robot)) {
                throw new ProtocolException("geometry slid robot " + robot + ", which does not slide");
            }
            double slid = Math.hypot(answer.slideXMm(k), answer.slideYMm(k));
            if (!(slid <= Math.abs(asked.moveMm(robot)) - Math.abs(answer.movedMm(robot)) + SLACK)) {
                throw new ProtocolException("geometry slid robot " + robot + " by " + slid + " mm, more than the "
                        + (Math.abs(asked.moveMm(robot)) - Math.abs(answer.movedMm(robot))) + " mm left of its move");
            }
            before = robot;
        }
        boolean[] taken = new boolean[objects];
        int last = -1;
        for (int k = 0; k < answer.gripCount(); k++) {
            int robot = answer.gripRobot(k);
            int object = answer.gripObject(k);
            if (robot <= last || robot >= robots || !asked.wantsGrip(robot) || object < -1 || object >= objects
                    || (object >= 0 && (asked.carrier(object) != -1 || !things.get(object).gripable() || taken[object]))) {
                throw new ProtocolException("geometry gave robot " + robot + " object " + object
                        + " to grip, which it did not ask for or cannot have");
            }
            last = robot;
            if (object >= 0) {
                taken[object] = true;
            }
        }
    }
}
