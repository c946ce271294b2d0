package robosim.environment.net;

import java.io.Externalizable;
import java.io.IOException;
import robosim.protocol.ObjectConnection;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * A viewer's writing side, on its own thread (the Environment's viewer workers, a replay's viewers): the
 * snapshot, then what its {@link ViewerQueue} holds until the end, each write timed so that whoever
 * publishes can drop a viewer stuck in one ({@link #writingFor}).
 */
public final class ViewerWrites {
    private final ObjectConnection connection;
    private volatile long writingSince;

    public ViewerWrites(ObjectConnection connection) {
        this.connection = connection;
    }

    /** Sends {@code first}, then what {@code queue} holds, up to and with the end; {@code roomFreed} when it makes room. */
    public void serve(WorldSnapshot first, ViewerQueue queue, Runnable roomFreed) throws IOException, InterruptedException {
        send(first);
        while (true) {
            Object next = queue.take();
            if (queue.claimRoomSignal()) {
                roomFreed.run();
            }
            send((Externalizable) next);
            if (next instanceof SimulationEnd) {
                return;
            }
        }
    }

    public void send(Externalizable message) throws IOException {
        writingSince = System.nanoTime();
        try {
            connection.write(message);
            connection.flush();
        } finally {
            writingSince = 0;
        }
    }

    /** How long the current write has taken so far, ns; 0 when none is under way. */
    public long writingFor(long now) {
        long since = writingSince;
        return since == 0 ? 0 : now - since;
    }
}
