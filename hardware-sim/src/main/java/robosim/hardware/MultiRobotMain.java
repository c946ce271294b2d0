package robosim.hardware;

import robosim.devices.RobotType;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.api.RobotControl;
import robosim.protocol.CommandLines;
import robosim.protocol.ClientOptions;
import robosim.protocol.Protocol;

/**
 * Many robots in one JVM (for large robot counts), each with its own control thread. With
 * {@code --connection SHARED} (the default) every robot goes over one connection, run by one
 * {@code exchange} thread ({@link SharedLink}); with {@code PER_ROBOT} each robot has its own socket, and
 * {@code --exchange SHARED} (one {@code exchange} thread for every robot's exchange, in the order given),
 * {@code ONE_THREAD} (a Hardware Simulator thread per robot, {@code hardware[name]}) or {@code SEND_RECEIVE}
 * (a sending and a receiving thread per robot) say how they are threaded.
 */
@Command(name = "robots.sh", mixinStandardHelpOptions = true,
        description = "Runs several robots in one process, over one shared connection or a connection each.")
public final class MultiRobotMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(MultiRobotMain.class);

    @Parameters(index = "0", paramLabel = "HOST", description = "Environment host.")
    String host;

    @Parameters(index = "1", paramLabel = "PORT", defaultValue = "" + Protocol.DEFAULT_ROBOT_PORT,
            description = "Environment robot port (default: ${DEFAULT-VALUE}).")
    int port;

    @Option(names = "--robot", required = true, paramLabel = "NAME:TYPE:CONTROL",
            description = "A robot to run; repeat for each. CONTROL: a control class, or python:PATH (a script).")
    List<String> robots;

    @Mixin
    ClientOptions client;

    @Mixin
    ExchangeOption exchange;

    @Mixin
    ConnectionOption connection;

    @Override
    public Integer call() throws Exception {
        if (robosim.protocol.Connector.badPort(port) != null) {
            System.err.println("robots: " + host + ":" + port + ": " + robosim.protocol.Connector.badPort(port));
            return 2;
        }
        List<String[]> parsed = new ArrayList<>();
        for (String r : robots) {
            String[] p = r.split(":", 3);
            if (p.length != 3 || p[0].isBlank()) {
                System.err.println("robots: --robot " + r + " is not NAME:TYPE:CONTROL");
                return 2;
            }
            try {
                RobotLauncher.control(p[2]);
                robosim.devices.RobotTypes.byName(p[1]);
            } catch (IllegalArgumentException e) {
                System.err.println("robots: robot " + p[0] + ": " + e.getMessage());
                return 2;
            }
            parsed.add(p);
        }
        LOG.info("{}", ControlThreads.describe());
        RobotLauncher launcher = new RobotLauncher(host, port, client);
        if (connection.given() != ConnectionOption.Connection.PER_ROBOT) {
            if (parsed.size() > robosim.protocol.Limits.MAX_ROBOTS_PER_CONNECTION) {
                System.err.println("robots: " + parsed.size() + " robots are more than one shared connection carries ("
                        + robosim.protocol.Limits.MAX_ROBOTS_PER_CONNECTION + "): use --connection PER_ROBOT or "
                        + "several processes");
                return 2;
            }
            return runOnThisThread(launcher, parsed, true);
        }
        ExchangeOption.Threading threading = exchange.or(ExchangeOption.Threading.SHARED);
        if (threading == ExchangeOption.Threading.SHARED) {
            return runOnThisThread(launcher, parsed, false);
        }
        HardwareSimulator.Exchange each = threading == ExchangeOption.Threading.SEND_RECEIVE
                ? HardwareSimulator.Exchange.SEND_RECEIVE : HardwareSimulator.Exchange.ONE_THREAD;
        AtomicInteger failures = new AtomicInteger();
        List<HardwareSimulator> ran = java.util.Collections.synchronizedList(new ArrayList<>());
        List<Thread> threads = new ArrayList<>();
        for (String[] p : parsed) {
            Thread t = new Thread(() -> {
                try {
                    RobotControl control = RobotLauncher.control(p[2]);
                    HardwareSimulator sim = launcher.connect(p[0], robosim.devices.RobotTypes.byName(p[1]));
                    ran.add(sim);
                    sim.run(control, each);
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
        return failures.get() > 0 ? 1 : controlFailures(ran);
    }

    /** 0, or {@link HardwareSimulator#EXIT_CONTROL_FAILED} naming each robot whose control code failed. */
    private static int controlFailures(List<HardwareSimulator> sims) {
        int code = 0;
        synchronized (sims) {
            for (HardwareSimulator sim : sims) {
                if (sim.controlFailure() != null) {
                    System.err.println("robot " + sim.name() + ": its control code failed: " + sim.controlFailure());
                    code = HardwareSimulator.EXIT_CONTROL_FAILED;
                }
            }
        }
        return code;
    }

    /**
     * Every robot's exchange on this thread ({@code exchange}): over one connection ({@code --connection SHARED}),
     * or each robot connected in turn over its own ({@code --exchange SHARED}).
     */
    private int runOnThisThread(RobotLauncher launcher, List<String[]> parsed, boolean oneConnection) {
        List<HardwareSimulator> sims = new ArrayList<>();
        List<RobotControl> controls = new ArrayList<>();
        try {
            for (String[] p : parsed) {
                controls.add(RobotLauncher.control(p[2]));
                RobotType type = robosim.devices.RobotTypes.byName(p[1]);
                sims.add(oneConnection ? new HardwareSimulator(p[0], type)
                        : launcher.connect(p[0], type));
            }
            java.net.Socket socket = oneConnection ? launcher.open() : null;
            Thread.currentThread().setName("exchange");
            if (oneConnection) {
                SharedLink.connect(sims, socket, launcher.resetEvery(), robosim.protocol.SimulationKeys.fromEnvironment(),
                        launcher.connectTimeoutMs()).run(controls);
            } else {
                ManyRobots.runShared(sims, controls);
            }
            return controlFailures(sims);
        } catch (java.io.IOException e) {
            System.err.println("robots: " + (e.getMessage().contains(host + ":" + port) ? e.getMessage()
                    : host + ":" + port + ": " + e.getMessage()));
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
    }

    public static void main(String[] args) {
        CommandLines.exit("robots", new MultiRobotMain(), args);
    }
}
