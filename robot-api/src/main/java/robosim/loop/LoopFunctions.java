package robosim.loop;

/**
 * An experiment's own code, run inside the world while it steps (ARGoS's {@code CLoopFunctions}, Webots' supervisor):
 * one class with a public no-argument constructor, named by the world file ({@code <loopFunctions class="..."/>}),
 * made anew for every run. The simulation loop calls it, between the phases of a step and never from another thread:
 * {@link #init} once before step 0, {@link #preStep} before each step's moves, {@link #postStep} after them (the world
 * as the step released it), {@link #finished} after each {@link #postStep}, {@link #destroy} once at the end. What it
 * throws ends the run with one line naming it and the step (exit code 4, as a robot's control code that throws).
 */
public interface LoopFunctions {
    /** Once, before step 0: the world as the file placed it. */
    default void init(Experiment world) throws Exception {
    }

    /**
     * The experiment starts again from its beginning (a learning episode's reset): its own state back to what
     * {@link #init} made. By default {@link #init} again.
     */
    default void reset(Experiment world) throws Exception {
        init(world);
    }

    /** Before each step's moves: the world as the last step left it. */
    default void preStep(Experiment world) throws Exception {
    }

    /** After each step's moves and sensing: the world as the step released it. */
    default void postStep(Experiment world) throws Exception {
    }

    /** After each {@link #postStep}: true ends the run there, as planned. */
    default boolean finished(Experiment world) throws Exception {
        return false;
    }

    /** Once, when the run ends however it ends (files closed here). */
    default void destroy(Experiment world) throws Exception {
    }
}
