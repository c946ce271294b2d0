package org.example.myrobot;

import java.util.Locale;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Explores the world with its sonar, on any robot type (it reads where the sonars point from the
 * robot). It does one thing per time step: drive ahead one step's worth; or, when something is
 * within {@link #CLEARANCE_MM} ahead, turn one step's worth towards the more open side until the way
 * is clear; or, after touching something, back off for {@link #BACK_OFF_MM} and turn away by
 * {@link #ESCAPE_DEG} (so it does not graze the same thing again on the same line). Because every call it
 * makes takes exactly one step, it looks at its sonar every step and knows the robot time. It prints
 * a report every {@link #REPORT_EVERY_MS} of robot time and a last one when the simulation ends.
 */
public final class Explorer implements RobotControl {
    /** How close something ahead may come before the robot turns away, mm (a sonar reading). */
    static final double CLEARANCE_MM = 700;
    /** A sonar pointing within this many degrees of the heading looks ahead. */
    static final double AHEAD_DEG = 35;
    /** A sonar pointing between AHEAD_DEG and this many degrees to one side looks at that side. */
    static final double SIDE_DEG = 100;
    /** How far to back off after touching something, mm. */
    static final double BACK_OFF_MM = 200;
    /** How far to turn away after backing off, degrees (rounded up to whole steps' worth). */
    static final double ESCAPE_DEG = 60;
    /** Robot time between two reports, ms. */
    static final long REPORT_EVERY_MS = 60_000;

    private long steps;
    private double travelledMm;
    private int turnsAway;
    private int contacts;

    @Override
    public void run(Robot robot) throws InterruptedException {
        double[] angles = robot.sonarAnglesDeg();
        for (int s = 0; s < angles.length; s++) {
            angles[s] = towardsLeft(angles[s]);
        }
        double legMm = robot.velocity() * robot.stepMs() / 1000;
        double swingDeg = robot.rotVelocity() * robot.stepMs() / 1000;
        long backOffSteps = (long) Math.ceil(BACK_OFF_MM / legMm);
        long escapeSteps = (long) Math.ceil(ESCAPE_DEG / swingDeg);
        System.out.printf(Locale.ROOT, "%s: exploring with %d sonars, step %d ms: %.0f mm or %.1f deg a step%n",
                robot.name(), angles.length, robot.stepMs(), legMm, swingDeg);
        try {
            robot.sleep(0); // one step: the first sonar readings
            steps++;
            long backing = 0;
            long escaping = 0;
            int turning = 0; // +1 left, -1 right, 0 not turning away
            while (true) {
                double[] ranges = robot.sonarRanges();
                if (backing > 0) {
                    travelledMm += Math.abs(robot.move(-legMm));
                    if (--backing == 0) {
                        turning = moreOpenSide(robot.sonarRanges(), angles);
                        escaping = escapeSteps;
                        turnsAway++;
                    }
                } else if (escaping > 0) {
                    robot.turn(turning * swingDeg);
                    escaping--;
                } else if (nearest(ranges, angles, -AHEAD_DEG, AHEAD_DEG) < CLEARANCE_MM) {
                    if (turning == 0) {
                        turning = moreOpenSide(ranges, angles);
                        turnsAway++;
                    }
                    robot.turn(turning * swingDeg);
                } else {
                    turning = 0;
                    travelledMm += robot.move(legMm);
                    if (!robot.lastContact().isEmpty()) {
                        contacts++;
                        backing = backOffSteps;
                    }
                }
                steps++;
                if (steps * robot.stepMs() % REPORT_EVERY_MS < robot.stepMs()) {
                    report(robot, "");
                }
            }
        } finally {
            report(robot, " (the end)");
        }
    }

    private void report(Robot robot, String when) {
        System.out.printf(Locale.ROOT,
                "%s: t=%.1f s at (%.2f, %.2f) m heading %.0f deg; travelled %.1f m, turned away %d times, "
                        + "%d contacts%s%n",
                robot.name(), steps * robot.stepMs() / 1000.0, robot.xMm() / 1000, robot.yMm() / 1000,
                robot.headingDeg(), travelledMm / 1000, turnsAway, contacts, when);
    }

    /** +1 if the sonars on the left see more room than those on the right, else -1. */
    static int moreOpenSide(double[] ranges, double[] anglesDeg) {
        double left = nearest(ranges, anglesDeg, AHEAD_DEG, SIDE_DEG);
        double right = nearest(ranges, anglesDeg, -SIDE_DEG, -AHEAD_DEG);
        return left >= right ? 1 : -1;
    }

    /**
     * The nearest reading of the sonars pointing between {@code fromDeg} and {@code toDeg} (left of
     * the heading positive); infinity if none points there (an ArRobot has no sonar behind).
     */
    static double nearest(double[] ranges, double[] anglesDeg, double fromDeg, double toDeg) {
        double nearest = Double.POSITIVE_INFINITY;
        for (int s = 0; s < ranges.length; s++) {
            if (anglesDeg[s] >= fromDeg && anglesDeg[s] <= toDeg) {
                nearest = Math.min(nearest, ranges[s]);
            }
        }
        return nearest;
    }

    /** An angle in (-180, 180]: positive to the left of the heading, negative to the right. */
    static double towardsLeft(double deg) {
        double a = deg % 360;
        if (a > 180) {
            a -= 360;
        } else if (a <= -180) {
            a += 360;
        }
        return a;
    }
}
