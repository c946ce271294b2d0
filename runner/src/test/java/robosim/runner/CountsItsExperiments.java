package robosim.runner;

import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/**
 * Loop functions with static state: the n-th run of this class in a JVM moves robot 0 n times 100 mm along +y at its
 * init. In a JVM of its own every run is the first; a warm JVM's runs must be too (their classes are loaded afresh).
 */
public final class CountsItsExperiments implements LoopFunctions {
    private static int runs;

    @Override
    public void init(Experiment world) {
        int n = ++runs;
        if (!world.moveRobot(0, world.robotXMm(0), world.robotYMm(0) + 100 * n, world.robotHeadingDeg(0))) {
            throw new IllegalStateException("robot 0 could not be moved " + 100 * n + " mm");
        }
    }
}
