package robosim.runner;

import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/** Loop functions that draw, at their init, a 3 m square in magenta (a colour nothing else in a viewer has). */
public final class DrawsASquare implements LoopFunctions {
    /** The square's colour. */
    public static final int MAGENTA = 0xFF00FF;

    @Override
    public void init(Experiment world) {
        double[][] corners = {{1000, 1000}, {4000, 1000}, {4000, 4000}, {1000, 4000}, {1000, 1000}};
        for (double[] c : corners) {
            world.trace("square", c[0], c[1], MAGENTA);
        }
    }
}
