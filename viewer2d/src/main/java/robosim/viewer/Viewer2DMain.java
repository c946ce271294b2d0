package robosim.viewer;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.protocol.ConnectOptions;
import robosim.protocol.Protocol;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;

/** {@code scripts/viewer2d.sh HOST 3000}: a window onto a running Environment. */
@Command(name = "viewer2d.sh", mixinStandardHelpOptions = true,
        description = "Connects to an Environment's viewer port and draws the arena, obstacles and robots "
                + "(1 unit = 1 m). Any number of viewers may watch at once.")
public final class Viewer2DMain implements Callable<Integer> {
    @Parameters(index = "0", defaultValue = "localhost", description = "Environment host (default: ${DEFAULT-VALUE}).")
    String host;

    @Parameters(index = "1", defaultValue = "" + Protocol.DEFAULT_VIEWER_PORT,
            description = "Environment viewer port (default: ${DEFAULT-VALUE}).")
    int port;

    @Option(names = "--sonar", description = "Draw sonar cones from the start (key s toggles).")
    boolean sonar;

    @Option(names = "--no-trails", description = "Do not draw trails at first (key t toggles).")
    boolean noTrails;

    @Option(names = "--watch", paramLabel = "ROBOT",
            description = "Open only this robot's window (the robot-specific viewer: its sensors, command and "
                    + "messages); in the world window a click on a robot opens its window too.")
    String watch;

    @Option(names = "--fps", defaultValue = "30", description = "Frames per second (default: ${DEFAULT-VALUE}).")
    int fps;

    @Mixin
    ConnectOptions connect;

    @Option(names = "--next-run-wait-s", defaultValue = "0",
            description = "After a simulation ends (or the connection is lost), wait this long for the next run "
                    + "on the same port, then give up and keep the last picture (default: ${DEFAULT-VALUE} = for as "
                    + "long as the window is open).")
    int nextRunWaitS;

    /** First and longest interval between attempts to reach the next run, ms. */
    static final long FIRST_RETRY_MS = 250;
    static final long MAX_RETRY_MS = 2000;

    @Override
    public Integer call() throws Exception {
        if (GraphicsEnvironment.isHeadless()) {
            System.err.println("viewer2d: no display (set DISPLAY); without one, watch in a browser: --web-port 8080 on "
                    + "environment.sh, headless.sh or replay.sh, then http://localhost:8080/");
            return 2;
        }
        if (fps < 1 || fps > 240) {
            System.err.println("viewer2d: --fps must be in 1..240, got " + fps);
            return 2;
        }
        if (nextRunWaitS < 0) {
            System.err.println("viewer2d: --next-run-wait-s must be >= 0, got " + nextRunWaitS);
            return 2;
        }
        if (watch != null) {
            try {
                RobotWatch.open(host, port, watch, fps, connect.millis(), nextRunWaitS * 1000L, true);
            } catch (IOException e) {
                System.err.println("viewer2d: " + e.getMessage());
                return 1;
            }
            windowOpen = true;
            return 0;
        }
        SceneFeed feed = new SceneFeed(System::nanoTime);
        ViewerHello hello = new ViewerHello(false, fps);
        ViewerClient client;
        try {
            client = ViewerClient.connect(host, port, hello, connect.millis());
        } catch (IOException e) {
            System.err.println("viewer2d: " + e.getMessage());
            return 1;
        }
        if (client.refusal() != null) { // (a port of another kind, the wrong keys: no window for it)
            client.close();
            System.err.println("viewer2d: " + host + ":" + port + ": " + client.refusal().reason());
            return 1;
        }
        new RunFollower(host, port, hello, feed, FIRST_RETRY_MS, MAX_RETRY_MS, nextRunWaitS * 1000L).start(client);
        ViewerWindow.open("RoboSim - " + host + ":" + port, feed, new SceneRenderer.Options(true, !noTrails, sonar),
                fps, robot -> RobotWatch.openLater(host, port, robot, fps,
                connect.millis(), nextRunWaitS * 1000L));
        windowOpen = true;
        return 0;
    }

    /** Set once the window is up: the process then lives until the window is closed. */
    private boolean windowOpen;

    public static void main(String[] args) {
        Viewer2DMain app = new Viewer2DMain();
        int code = CommandLines.of("viewer2d", app).execute(args);
        if (!app.windowOpen) {
            System.exit(code);
        }
    }
}
