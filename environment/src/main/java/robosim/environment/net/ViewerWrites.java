package robosim.environment.net;

import java.io.Externalizable;
import java.io.IOException;
import robosim.protocol.ObjectConnection;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * A viewer's writing side, on its own thread (the Environment's viewer workers, a replay's viewers): the
 * snapshot, then what its {@link ViewerQueue} holds until the end, each write on the connection's
 * {@link ConnectionClock}, so the {@link ConnectionWatch} cuts off a viewer stuck in one.
 */
public final class ViewerWrites {
    private final ObjectConnection connection;
    private final ConnectionClock clock;

    public ViewerWrites(ObjectConnection connection, ConnectionClock clock) {
        this.connection = connection;
        this.clock = clock;
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
        clock.writing();
        try {
            connection.write(message);
            connection.flush();
        } finally {
            clock.written();
        }
    }
}
