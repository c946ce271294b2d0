package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.protocol.ObjectConnection;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * The follower over real sockets: after the end it says it waits for the next run, retries while the
 * port refuses, and with a limit gives up and says so. (Following a real next run: runner's
 * ViewerFollowTest.)
 */
class RunFollowerTest {
    /** Records what the follower passes on, to wait on. */
    private static final class Events implements RunFollower.Listener {
        final BlockingQueue<String> seen = new LinkedBlockingQueue<>();

        @Override
        public void snapshot(WorldSnapshot snapshot) {
            seen.add("snapshot");
        }

        @Override
        public void update(PoseUpdate update) {
            seen.add("update");
        }

        @Override
        public void end(SimulationEnd end) {
            seen.add("end: " + end.reason());
        }

        @Override
        public void lost(IOException cause) {
            seen.add("lost");
        }

        @Override
        public void between(String doing) {
            seen.add(doing);
        }

        String next() throws InterruptedException {
            String e = seen.poll(60, TimeUnit.SECONDS);
            assertNotNull(e, "nothing within a minute");
            return e;
        }
    }

    @Test
    void afterTheEndItWaitsForTheNextRunAndGivesUpAfterItsLimit() throws Exception {
        Events events = new Events();
        ViewerHello hello = new ViewerHello(false, 30);
        int port;
        ViewerClient client;
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = server.getLocalPort();
            // an Environment whose simulation is over: the end, then its viewer port closes (both ends of
            // an object connection read the other's stream header first, so the server side has a thread)
            CompletableFuture<Void> environment = CompletableFuture.runAsync(() -> {
                try (Socket s = server.accept()) {
                    ObjectConnection c = new ObjectConnection(s, 16);
                    c.write(new SimulationEnd(41, "stopped from the control port"));
                    c.flush();
                    c.close();
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }, r -> new Thread(r, "test-environment").start());
            client = ViewerClient.connect("127.0.0.1", port, hello, 10_000);
            environment.get(60, TimeUnit.SECONDS);
        }
        long t0 = System.nanoTime();
        RunFollower follower = new RunFollower("127.0.0.1", port, hello, events, 10, 100, 1000);
        follower.start(client);
        try {
            assertEquals("end: stopped from the control port", events.next());
            assertEquals("waiting for the next run on 127.0.0.1:" + port, events.next());
            assertEquals("no next run on 127.0.0.1:" + port + " within 1 s; gave up", events.next());
            assertTrue(System.nanoTime() - t0 >= TimeUnit.SECONDS.toNanos(1), "it waited its limit first");
        } finally {
            follower.close();
        }
    }

    @Test
    void retryIntervalsAreChecked() {
        RunFollower.Listener none = new Events();
        ViewerHello hello = new ViewerHello(false, 30);
        assertThrows(IllegalArgumentException.class, () -> new RunFollower("h", 1, hello, none, 0, 10, 0));
        assertThrows(IllegalArgumentException.class, () -> new RunFollower("h", 1, hello, none, 50, 10, 0));
        assertThrows(IllegalArgumentException.class, () -> new RunFollower("h", 1, hello, none, 10, 50, -1));
    }
}
