package robosim.environment.run;

import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/**
 * Told, on the loop thread, of every step the run releases, and of the run's beginning, state and end: the run's
 * viewers ({@link RunViewers}) and its recording ({@link RunRecorder}). Never blocks the loop (one that cannot take
 * a step says so with {@link #hasRoom}, and posts when it has room again).
 */
public interface ReleaseListener {
    /** What a listener may read of the step just released, on the loop thread, during the call. */
    interface Step {
        /** True if robot {@code i} (world order) took part in the step. */
        boolean tookPart(int i);

        /** What robot {@code i} asked in the step (it took part). */
        StepRequest request(int i);

        /** What robot {@code i} was answered (it took part). */
        StepResponse response(int i);
    }

    /** The run begins from {@code start} (before step 0 is computed). */
    default void begun(WorldSnapshot start) {
    }

    /** A step was released: the world after it, and what its robots asked and were answered. */
    void released(ReleasedWorld world, Step step);

    /** The run runs, holds or waits now. */
    default void state(RunState state) {
    }

    /** The run is over. */
    void ended(SimulationEnd end);

    /** False while it cannot take one more step now (it posts when it has room again). */
    default boolean hasRoom() {
        return true;
    }
}
