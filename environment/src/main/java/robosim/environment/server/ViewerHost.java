package robosim.environment.server;

import java.util.concurrent.CompletableFuture;
import robosim.protocol.WorldSnapshot;

/**
 * Whoever publishes to viewers (the live Environment's loop, a replay's clock), as a {@link ViewerClientWorker}
 * sees it: it takes a viewer in and hands it the world it starts from, hears that the viewer has gone or has room
 * again, and says which robots a viewer may watch. Any thread; nothing here waits for the publisher.
 */
public interface ViewerHost {
    /** What the viewer watches robots of, for a refusal: "this simulation". */
    String world();

    /** The index (world order) of robot {@code name} now, or -1 if there is none of that name. */
    int robot(String name);

    /** Takes {@code viewer} in; the world it starts from, after which its queue is fed without a gap. */
    CompletableFuture<WorldSnapshot> join(ViewerSink viewer);

    /** {@code viewer}'s worker has ended, for {@code why}; {@code cutOff}: the connection watch cut it off. */
    void left(ViewerSink viewer, String why, boolean cutOff);

    /** A recording viewer's queue has room again: a step held for it may go out. */
    void roomFreed(ViewerSink viewer);
}
