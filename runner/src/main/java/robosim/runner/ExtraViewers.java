package robosim.runner;

import java.io.IOException;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.Connector;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * Viewers connected only to measure what viewers cost the robots: live ones that ask for updates
 * like a Viewer2D at {@code updatesPerSecond} frames a second (0: every step) and read them in this
 * process, and frozen ones that say hello and then never read a byte.
 */
final class ExtraViewers implements AutoCloseable {
    private final List<ViewerClient> live = new ArrayList<>();
    private final List<Socket> frozen = new ArrayList<>();

    static ExtraViewers connect(int port, int liveCount, int updatesPerSecond, int frozenCount)
            throws IOException, InterruptedException {
        ExtraViewers v = new ExtraViewers();
        for (int i = 0; i < liveCount; i++) {
            ViewerClient c = ViewerClient.connect("127.0.0.1", port, new ViewerHello(false, updatesPerSecond), 10_000);
            c.start(new ViewerClient.Listener() {
                @Override
                public void snapshot(WorldSnapshot snapshot) {
                }

                @Override
                public void update(PoseUpdate update) {
                }
            });
            v.live.add(c);
        }
        for (int i = 0; i < frozenCount; i++) {
            v.frozen.add(frozen(port));
        }
        return v;
    }

    /** A viewer that says hello and never reads: a tiny receive buffer, so it fills at once. */
    static Socket frozen(int port) throws IOException, InterruptedException {
        Socket s = Connector.connect("127.0.0.1", port, 10_000);
        if (s == null) {
            throw new IOException("cannot connect to the viewer port " + port);
        }
        s.setReceiveBufferSize(4096);
        robosim.protocol.SimulationKeys secret = robosim.protocol.SimulationKeys.fromEnvironment();
        robosim.protocol.ObjectConnection c = robosim.protocol.ObjectConnection.client(s, 256, secret);
        c.write(new ViewerHello(false));
        c.flush();
        if (secret != null) { // prove it (and take the snapshot), then never read again
            c.answerChallenge(secret, "viewer");
        }
        return s;
    }

    @Override
    public void close() {
        live.forEach(ViewerClient::close);
        for (Socket s : frozen) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
    }
}
