package robosim.protocol;

/**
 * The link between the Environment and a robot in the Environment's own JVM (a one-JVM run): the messages
 * of a robot's connection ({@link RobotHello}, {@link RobotWelcome}, the step number, {@link StepRequest},
 * {@link StepResponse}, {@link SimulationEnd}), handed over as objects, never serialized, in the same order
 * and with the same lock-step as over a socket. The Environment finds the robots' side with
 * {@link java.util.ServiceLoader} ({@link Starter}; the Hardware Simulator provides it), so neither side
 * depends on the other.
 *
 * <p>A request comes from one of two places. When the Environment gives a robot its step (the first one, or
 * the next with the last step's response) and the robot's control code is not running (it is blocked in a
 * call that goes on, or has returned), the robot builds the request at once and returns it. Otherwise its
 * control code builds it on its own thread as soon as it makes its next call, and hands it to
 * {@link Environment#request}. Each step number given gets exactly one request, one way or the other.
 */
public final class InMemoryLink {
    private InMemoryLink() {
    }

    /** The robot's end; the Environment's loop thread calls it. */
    public interface Robot {
        /** The hello this robot says: its name and its type's properties. */
        RobotHello hello();

        /** The Environment's answer to the hello; a refused robot is never called again. */
        void welcome(RobotWelcome welcome);

        /** Step {@code k} is this robot's first: its request now, or null when its control code will give it. */
        StepRequest step(long k);

        /**
         * The response to its last request, then step {@code next}: the next request now, or null when its
         * control code will give it.
         */
        StepRequest respond(StepResponse response, long next);

        /** The simulation is over for this robot (after its last response, or out of turn); nothing follows. */
        void end(SimulationEnd end);
    }

    /** The Environment's end of one robot's link; the robot's control thread calls it. */
    public interface Environment {
        /** The request for the step this robot was last given, built on its control thread. */
        void request(StepRequest request);
    }

    /** Starts robots in the Environment's JVM: {@code META-INF/services/robosim.protocol.InMemoryLink$Starter}. */
    public interface Starter {
        /**
         * A robot named {@code name} of {@code type} running a new instance of {@code controlClass}, whose
         * requests go to {@code environment}; its control code starts once it is welcomed and given a step.
         *
         * @throws IllegalArgumentException naming what is wrong with the type or the control class
         */
        Robot start(String name, String type, String controlClass, Environment environment);

        /**
         * After the simulation is over: waits up to {@code ms} for the control code of every robot it started
         * to end (its {@code finally} blocks, a last report), as a robot process does before it exits; says whose
         * threw and whose is still running.
         */
        ControlEnd awaitControlCode(long ms) throws InterruptedException;
    }

    /**
     * How the control code of the robots in this JVM ended.
     *
     * @param failed for each robot whose control code threw out of {@code run}, {@code NAME: what it threw}
     * @param running the names of the robots whose control code had not ended when the wait was over (a robot
     *        process would have exited under it; a JVM that runs more runs must not go on with it)
     * @param asked the parameters each robot's control code asked for ({@code Robot.parameter}), by robot
     */
    public record ControlEnd(java.util.List<String> failed, java.util.List<String> running,
            java.util.Map<String, java.util.Set<String>> asked) {
        /** Nobody's control code failed or is still running, or asked for anything. */
        public static final ControlEnd CLEAN = new ControlEnd(java.util.List.of(), java.util.List.of(),
                java.util.Map.of());

        public ControlEnd {
            failed = java.util.List.copyOf(failed);
            running = java.util.List.copyOf(running);
            asked = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(asked));
        }
    }
}
