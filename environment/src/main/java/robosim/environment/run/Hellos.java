package robosim.environment.run;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import robosim.protocol.RobotHello;

/**
 * Robots' hellos that came together, one robot's or every robot's of a shared connection, already checked against
 * the file on the thread that read them, for the {@link Admission} to answer together: each {@link Hello}'s
 * verdict, then the transport is told ({@link Answered}) on the loop thread, where it writes what it owes its
 * robots (a shared connection, its one frame of welcomes). Refused once the run is over: each verdict says so, and
 * the transport is told the loop never took them.
 */
public record Hellos(List<Hello> hellos, Answered answered) {
    /** One robot's hello: who speaks for it, what it said (as the loop takes it), its place in the file (or -1), its verdict (null: welcomed). */
    public record Hello(RobotPeer peer, RobotHello hello, int index, CompletableFuture<String> verdict) {
    }

    /** What a transport does once its hellos are answered, or will not be. */
    public interface Answered {
        /** {@code byLoop}: true on the loop thread, after every verdict; false if the loop never took them. */
        void answered(boolean byLoop);
    }

    /** One robot's hello, on its own. */
    public static Hellos of(Hello hello) {
        return new Hellos(List.of(hello), byLoop -> { });
    }

    /** The run is over (or never took them): each verdict says so, and the transport is told. */
    void refuse() {
        for (Hello h : hellos) {
            h.verdict().complete(Progress.OVER);
        }
        answered.answered(false);
    }
}
