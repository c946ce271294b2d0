package robosim.hardware;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.api.RobotControl;
import robosim.protocol.Protocol;

/**
 * Many robots in one JVM (for large robot counts): each robot has its own socket, its own
 * Hardware Simulator thread ({@code hardware[name]}) and its own control thread.
 */
@Command(name = "robots.sh", mixinStandardHelpOptions = true,
        description = "Runs several robots in one process, each with its own connection and threads.")
public final class MultiRobotMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(MultiRobotMain.class);

    @Parameters(index = "0", paramLabel = "HOST", description = "Environment host.")
    String host;

    @Parameters(index = "1", paramLabel = "PORT", defaultValue = "" + Protocol.DEFAULT_ROBOT_PORT,
            description = "Environment robot port (default: ${DEFAULT-VALUE}).")
    int port;

    @Option(names = "--robot", required = true, paramLabel = "NAME:TYPE:CONTROL_CLASS",
            description = "A robot to run; repeat for each.")
    List<String> robots;

    @Mixin
    ConnectOptions connect;

    @Override
    public Integer call() throws Exception {
        List<String[]> parsed = new ArrayList<>();
        for (String r : robots) {
            String[] p = r.split(":", 3);
            if (p.length != 3 || p[0].isBlank()) {
                System.err.println("robots: --robot " + r + " is not NAME:TYPE:CONTROL_CLASS");
                return 2;
            }
            try {
                RobotLauncher.control(p[2]);
                RobotType.byName(p[1]);
            } catch (IllegalArgumentException e) {
                System.err.println("robots: robot " + p[0] + ": " + e.getMessage());
                return 2;
            }
            parsed.add(p);
        }
        AtomicInteger failures = new AtomicInteger();
        List<Thread> threads = new ArrayList<>();
        for (String[] p : parsed) {
            Thread t = new Thread(() -> {
                try {
                    RobotControl control = RobotLauncher.control(p[2]);
                    RobotLauncher.run(p[0], RobotType.byName(p[1]), control, host, port, connect.connectTimeoutMs(),
                            connect.resetEvery);
                } catch (Exception e) {
                    failures.incrementAndGet();
                    LOG.error("robot {}: {}", p[0], e.getMessage());
                }
            }, "hardware[" + p[0] + "]");
            t.start();
            threads.add(t);
        }
        for (Thread t : threads) {
            t.join();
        }
        return failures.get() == 0 ? 0 : 1;
    }

    public static void main(String[] args) {
        CommandLine cl = new CommandLine(new MultiRobotMain());
        cl.setParameterExceptionHandler((ex, a) -> {
            System.err.println("robots: " + ex.getMessage() + " (see --help)");
            return 2;
        });
        System.exit(cl.execute(args));
    }
}
