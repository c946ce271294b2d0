package robosim.viewer;

import java.io.IOException;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;

/**
 * Opens a robot window: its own connection to the viewer port that watches one robot (a live viewer at
 * the window's frame rate), followed across runs by a {@link RunFollower}, and the {@link RobotWindow}
 * fed by it. Closing the window closes the connection.
 */
final class RobotWatch {
    /** The robots whose windows are open in this process: a second click brings no second window. */
    private static final Set<String> OPEN = ConcurrentHashMap.newKeySet();
    private RobotWatch() {
    }

    /**
     * Connects (on the calling thread; within {@code connectTimeoutMs}) and opens the window;
     * {@code only}: it is the process's one window.
     */
    static void open(String host, int port, String robot, int fps, long connectTimeoutMs, long nextRunWaitMs,
            boolean only) throws IOException, InterruptedException {
        if (!OPEN.add(robot)) {
            return; // (its window is open already)
        }
        ViewerHello hello = new ViewerHello(false, fps, robot);
        ViewerClient client;
        try {
            client = ViewerClient.connect(host, port, hello, connectTimeoutMs);
            if (client.refusal() != null) {
                client.close();
                throw new IOException(host + ":" + port + ": " + client.refusal().reason());
            }
        } catch (IOException | InterruptedException | RuntimeException e) {
            OPEN.remove(robot);
            throw e;
        }
        RobotFeed feed = new RobotFeed(robot);
        RunFollower follower = new RunFollower(host, port, hello, feed, Viewer2DMain.FIRST_RETRY_MS,
                Viewer2DMain.MAX_RETRY_MS, nextRunWaitMs);
        Runnable closed = () -> {
            follower.close();
            OPEN.remove(robot);
        };
        try {
            follower.start(client);
            RobotWindow.open(robot + " - " + host + ":" + port, feed, fps, only, closed);
        } catch (RuntimeException e) {
            client.close();
            closed.run();
            throw e;
        }
    }

    /** From a click in the world window (Swing thread): connects on its own thread, {@code robot-window-open}. */
    static void openLater(String host, int port, String robot, int fps, long connectTimeoutMs, long nextRunWaitMs) {
        Thread t = new Thread(() -> {
            try {
                open(host, port, robot, fps, connectTimeoutMs, nextRunWaitMs, false);
            } catch (IOException e) {
                System.err.println("viewer2d: cannot open " + RobotFeed.clean(robot) + "'s window: " + e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "robot-window-open");
        t.setDaemon(true);
        t.start();
    }
}
