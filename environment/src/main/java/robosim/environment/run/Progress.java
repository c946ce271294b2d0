package robosim.environment.run;

/**
 * Where a run stands: its phase and its step counts. The {@link Run} alone moves it on; its parts (the
 * {@link Roster}, the {@link Admission}, the {@link StatusBoard}) read it. Loop thread only.
 *
 * <p>The phases and their transitions:
 * <pre>
 * WAITING    -&gt; STARTING     every robot the file names and a Geometry process (unless in-process) are there
 * STARTING   -&gt; COLLECTING   step 0 went out
 * COLLECTING -&gt; RESOLVING    every running robot's request is in: the core prepares the step
 * RESOLVING  -&gt; RELEASING    the step is computed (Geometry's answer, or in-process at once)
 * RELEASING  -&gt; COLLECTING   its responses went out with the next step's number
 * any        -&gt; ENDED        once, with the reason
 * </pre>
 */
public final class Progress {
    /** Why what needs the run is refused once it is over. */
    public static final String OVER = "the simulation is over";

    enum Phase { WAITING, STARTING, COLLECTING, RESOLVING, RELEASING, ENDED }

    private Phase phase = Phase.WAITING;
    /** Steps computed so far: the step being collected or resolved is this one. */
    private long step;
    /** Steps whose responses have gone out. */
    private long released;

    Phase phase() {
        return phase;
    }

    /** The step being collected or resolved; while one is released, the one after it. */
    long step() {
        return step;
    }

    /** Steps whose responses have gone out. */
    long released() {
        return released;
    }

    /** True while a step is resolved or released: robots come and go at its end. */
    boolean midStep() {
        return phase == Phase.RESOLVING || phase == Phase.RELEASING;
    }

    /** True from the start until the end: the world exists, and a pause or step N acts on it. */
    boolean running() {
        return phase != Phase.WAITING && phase != Phase.ENDED;
    }

    boolean over() {
        return phase == Phase.ENDED;
    }

    /** The step what happens now belongs to: the one being collected or resolved, or the one being released. */
    long current() {
        return phase == Phase.RELEASING ? step - 1 : step;
    }

    void starting() {
        move(Phase.WAITING, Phase.STARTING);
    }

    void begun() {
        move(Phase.STARTING, Phase.COLLECTING);
    }

    void resolving() {
        move(Phase.COLLECTING, Phase.RESOLVING);
    }

    /** The step being resolved is computed: it is released next. */
    void computed() {
        move(Phase.RESOLVING, Phase.RELEASING);
        step++;
    }

    /** The computed step's responses went out: the next is collected. */
    void release() {
        released = step;
        move(Phase.RELEASING, Phase.COLLECTING);
    }

    /** The last step's responses went out with the end. */
    void releaseLast() {
        released = step;
    }

    void end() {
        phase = Phase.ENDED;
    }

    private void move(Phase from, Phase to) {
        if (phase != from) {
            throw new IllegalStateException("the run cannot go from " + phase + " to " + to);
        }
        phase = to;
    }
}
