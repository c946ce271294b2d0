package robosim.runner;

import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/** Loop functions that throw in the post-step of step 3 (after 3 steps completed), for the run's end and its exit code. */
public final class ThrowsInPostStep implements LoopFunctions {
    @Override
    public void postStep(Experiment world) {
        if (world.step() == 3) {
            throw new IllegalStateException("the nest is gone");
        }
    }
}
