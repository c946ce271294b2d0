package robosim.viewer;

import java.io.IOException;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;

/**
 * Opens a robot window: its own connection to the viewer port that watches one robot (a live viewer at
 * the window's frame rate), followed across runs by a {@link RunFollower}, and the {@link RobotWindow}
 * fed by it. Closing the window closes the connection.
 */
final class RobotWatch {
    private RobotWatch() {
    }

    /**
     * Connects (on the calling thread; within {@code connectTimeoutMs}) and opens the window;
     * {@code only}: it is the process's one window.
     */
    static void open(String host, int port, String robot, int fps, long connectTimeoutMs, long nextRunWaitMs,
            boolean only) throws IOException, InterruptedException {
        ViewerHello hello = new ViewerHello(false, fps, robot);
        ViewerClient client = ViewerClient.connect(host, port, hello, connectTimeoutMs);
        RobotFeed feed = new RobotFeed(robot, 1_000_000_000L / fps);
        RunFollower follower = new RunFollower(host, port, hello, feed, Viewer2DMain.FIRST_RETRY_MS,
                Viewer2DMain.MAX_RETRY_MS, nextRunWaitMs);
        follower.start(client);
        RobotWindow.open(robot + " - " + host + ":" + port, feed, fps, only, follower::close);
    }

    /** From a click in the world window (Swing thread): connects on its own thread, {@code robot-window-open}. */
    static void openLater(String host, int port, String robot, int fps, long nextRunWaitMs) {
        Thread t = new Thread(() -> {
            try {
                open(host, port, robot, fps, 10_000, nextRunWaitMs, false);
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
