package robosim.rl;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import robosim.protocol.CommandLines;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.control.ControlCommands;
import robosim.environment.control.ControlVerb;
import robosim.environment.control.WebViewers;
import robosim.environment.core.WorldSpec;
import robosim.environment.server.Acceptors;
import robosim.environment.server.Port;
import robosim.environment.server.PortGuide;
import robosim.environment.server.ServerContext;
import robosim.environment.server.ViewerClientWorker;
import robosim.environment.server.WebPortOption;
import robosim.environment.ParamOption;
import robosim.protocol.link.FirstHello;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;
import robosim.runner.EnvOption;
import robosim.sweep.AreaCellOption;
import robosim.sweep.MetricChoice;
import robosim.sweep.RunMetrics;
import robosim.web.WebViewerServer;

/**
 * {@code scripts/learning-host.sh}: K copies of an environment file's world ({@link BatchWorlds}) served to one
 * learner over the learning link ({@link BatchLink}) on loopback, world 0 to viewers if asked. Python's
 * {@code robosim.rl} starts it and reads where it listens from its first line; it serves one learner (the first
 * whose hello carries {@code ROBOSIM_LINK_KEY}, when that is set) and exits when the learner says bye or goes.
 * The file's robots are the agents: their control code is not run.
 */
@Command(name = "learning-host.sh", mixinStandardHelpOptions = true,
        description = "Serves K copies of an environment file's world to one learner (Python's robosim.rl) over the "
                + "learning link on loopback: one exchange a step for every robot of every world.")
public final class LearningHostMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(LearningHostMain.class);
    /** The most worlds a batch holds. */
    static final int MAX_WORLDS = 1024;

    @Mixin
    EnvOption env;

    @Mixin
    ParamOption params;

    @Option(names = "--worlds", defaultValue = "1", description = "Copies of the world, stepped together, 1 to "
            + MAX_WORLDS + " (default: ${DEFAULT-VALUE}).")
    int worlds;

    @Option(names = "--repeat", defaultValue = "1", description = "Time steps an action is held, 1 to 10000 "
            + "(default: ${DEFAULT-VALUE}).")
    int repeat;

    @Option(names = "--message-size", defaultValue = "0", description = "Numbers in a robot's message, 0 to 64 "
            + "(default: ${DEFAULT-VALUE}: no messages).")
    int messageSize;

    @Option(names = "--sensors", description = "Read each robot's sensors (its environment file's <sensor>s) with "
            + "each action's last time step, for the learner to observe (default: not: no ray cast, no noise drawn).")
    boolean sensors;

    @Option(names = "--actuators", description = "Act through each robot's devices too: its gripper and its type's "
            + "actuators (LEDs, range-and-bearing), fields after the velocities and the message in its action "
            + "(default: not: velocities and message only).")
    boolean actuators;

    @Option(names = "--random-headings", description = "Draw each robot's start heading from the episode's seed "
            + "(default: the file's headings).")
    boolean randomHeadings;

    @Mixin
    AreaCellOption areaCell;

    @Option(names = "--episode-metric", paramLabel = "NAME", description = "Record each world's episodes and compute "
            + "this metric of them when the learner asks (measure): a built-in metric's name or a robosim.sweep.Metric "
            + "class on the class path, as a sweep's (default: none).")
    String episodeMetric;

    @Option(names = "--loop-metric", paramLabel = "NAME", description = "A metric the world's loop functions report "
            + "(Experiment.report), a column of the metrics after the built-ins: its newest value in the episode, 0 "
            + "before their first report; a reward may name it (repeatable; default: none).")
    List<String> loopMetrics = new java.util.ArrayList<>();

    @Option(names = "--threads", description = "Threads that step the worlds, at most the machine's cores (a thread "
            + "spins a little between steps) (default: the cores).")
    Integer threads;

    @Mixin
    robosim.runner.LinkHostOptions host;

    @Option(names = "--viewer-port", defaultValue = "-1", description = "Serve world 0 to viewers (viewer2d.sh, "
            + "pose-log.sh) on this loopback port (default: ${DEFAULT-VALUE}: none; 0: one the system picks).")
    int viewerPort;

    @Mixin
    WebPortOption web;

    @Override
    public Integer call() throws Exception {
        WorldSpec spec;
        try {
            spec = new EnvironmentLoader().load(env.file(), params.values());
        } catch (EnvironmentFileException e) {
            System.err.println(e.getMessage());
            return 2;
        }
        String bad = badOption(spec);
        if (bad != null) {
            System.err.println("learning-host: " + bad);
            return 2;
        }
        int shares = threads != null ? threads : Runtime.getRuntime().availableProcessors();
        InetAddress loopback = InetAddress.getLoopbackAddress();
        MetricChoice metric = episodeMetric == null ? null : MetricChoice.parse(episodeMetric);
        try (BatchWorlds batch = new BatchWorlds(spec, worlds, new BatchWorlds.Settings(repeat, messageSize,
                randomHeadings, areaCell.metres(), shares, metric, sensors, actuators, loopMetrics));
                ServerSocket server = host.listen()) {
            WatchedWorld watch = viewerPort >= 0 || web.port() >= 0 ? new WatchedWorld(batch) : null;
            Acceptors viewers = null;
            WebViewerServer browsers = null;
            try {
                if (watch != null) {
                    ServerContext context = ServerContext.of(null, ObjectConnection.DEFAULT_RESET_EVERY,
                            ServerContext.DEFAULT_HANDSHAKE_TIMEOUT_MS, ServerContext.DEFAULT_WRITE_TIMEOUT_MS, GUIDE);
                    viewers = new Acceptors(context, loopback, 256);
                    viewers.bind(Port.VIEWER, Math.max(0, viewerPort), ServerContext.DEFAULT_MAX_CONNECTIONS,
                            (s, n) -> new ViewerClientWorker(context, s, "rl-viewer[" + n + "]", watch));
                    if (web.port() >= 0) {
                        browsers = WebViewers.start(web.port(), loopback, viewers.port(Port.VIEWER), null, NO_COMMANDS);
                    }
                    viewers.accept();
                }
            } catch (IOException e) {
                System.err.println("learning-host: " + e.getMessage());
                return 2;
            }
            System.out.println("robosim-batch-link listening on " + loopback.getHostAddress() + ":"
                    + server.getLocalPort() + (viewerPort >= 0 ? " viewers=" + viewers.port(Port.VIEWER) : "")
                    + (browsers != null ? " web=" + browsers.port() : ""));
            System.out.flush();
            try {
                return serve(server, batch, watch);
            } finally {
                if (watch != null) {
                    watch.end("the learner has gone", 2000);
                }
                if (browsers != null) {
                    browsers.close();
                }
                if (viewers != null) {
                    viewers.close();
                }
            }
        } catch (ProtocolException e) {
            System.err.println("learning-host: " + env.file() + ": " + e.getMessage());
            return 2;
        } catch (IOException e) {
            System.err.println("learning-host: " + Printable.of(String.valueOf(e.getMessage()), 1000));
            return 1;
        }
    }

    private int serve(ServerSocket server, BatchWorlds batch, WatchedWorld watch) throws IOException {
        String key = System.getenv("ROBOSIM_LINK_KEY");
        FirstHello.Welcomed<BatchLink> learner = host.awaitPeer(server, socket -> {
            socket.setTcpNoDelay(true);
            BatchLink link = new BatchLink(socket, batch, watch);
            link.welcome(key);
            return link;
        }, LOG);
        if (learner == null) {
            System.err.println("learning-host: no learner said hello within " + host.acceptTimeoutS() + " s");
            return 3;
        }
        try (Socket socket = learner.socket()) {
            long start = System.nanoTime();
            long steps;
            try {
                steps = learner.link().serve();
            } catch (IOException e) {
                System.err.println("learning-host: the learning link failed: " + Printable.of(e.getMessage(), 1000));
                return 1;
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            LOG.info(String.format(Locale.ROOT, "served %d steps of %d worlds x %d robots (%d robot-steps, x%d "
                    + "time steps an action) in %.1f s", steps, batch.count(), batch.robots(),
                    steps * batch.count() * batch.robots(), batch.repeat(), seconds));
            return 0;
        }
    }

    private String badOption(WorldSpec spec) {
        if (worlds < 1 || worlds > MAX_WORLDS) {
            return "--worlds must be 1 to " + MAX_WORLDS + ", got " + worlds;
        }
        if (repeat < 1 || repeat > 10_000) {
            return "--repeat must be 1 to 10000, got " + repeat;
        }
        if (messageSize < 0 || messageSize > 64) {
            return "--message-size must be 0 to 64, got " + messageSize;
        }
        String loop = BatchWorlds.Settings.loopMetricsProblem(loopMetrics);
        if (loop != null) {
            return "--loop-metric " + loop;
        }
        if (!loopMetrics.isEmpty() && spec.loopFunctions() == null) {
            return "--loop-metric " + Printable.of(loopMetrics.get(0), 64) + ": " + env.file() + " has no loop "
                    + "functions (<loopFunctions>) to report it";
        }
        int cores = Runtime.getRuntime().availableProcessors();
        if (threads != null && (threads < 1 || threads > cores)) {
            return "--threads must be 1 to " + cores + " (this machine's cores: a helper spins between steps), got "
                    + threads;
        }
        if (areaCell.problem() != null) {
            return areaCell.problem();
        }
        if (RunMetrics.cellProblem(spec.arena(), areaCell.metres()) != null) {
            return "--area-cell-m " + areaCell.metres() + ": " + RunMetrics.cellProblem(spec.arena(), areaCell.metres());
        }
        if (web.problem(null) != null) {
            return web.problem(null);
        }
        if (viewerPort < -1 || viewerPort > 65535) {
            return "--viewer-port must be -1 to 65535, got " + viewerPort;
        }
        if (host.problem() != null) {
            return host.problem();
        }
        if (episodeMetric != null) {
            MetricChoice metric = MetricChoice.parse(episodeMetric);
            String wrong = metric.kind() == MetricChoice.Kind.REPORT
                    ? "a report of control code (learning robots run none)" : metric.problem();
            if (wrong != null) {
                return "--episode-metric " + Printable.of(episodeMetric, 200) + ": " + wrong;
            }
        }
        if (spec.robots().isEmpty()) {
            return env.file() + ": no robots: a learning environment's agents are the file's robots";
        }
        if (!spec.joins().isEmpty()) {
            return env.file() + ": robots that join during a run are not for learning (the agents are the file's robots)";
        }
        for (WorldSpec.RobotSpec r : spec.robots()) {
            if (robosim.devices.RobotTypes.properties(r.type()) == null) {
                return env.file() + ": robot " + r.name() + ": type " + r.type() + " is not a known model";
            }
        }
        int sonars = spec.robots().stream().mapToInt(r -> robosim.devices.RobotTypes.properties(r.type()).sonars()
                .size()).max().orElse(0);
        for (WorldSpec.RobotSpec r : sensors ? spec.robots() : List.<WorldSpec.RobotSpec>of()) {
            for (String name : r.sensorNames()) {
                if (BatchLink.OBSERVED.contains(name)) {
                    return env.file() + ": robot " + r.name() + ": a sensor named " + name + " would hide the "
                            + "observation of that name: name it otherwise (<sensor name=\"...\">)";
                }
            }
        }
        long bytes = BatchLink.replyBytes(worlds, spec.robots().size(), sonars, messageSize,
                new SensorColumns(spec, sensors).width(), BatchWorlds.METRICS.size() + loopMetrics.size());
        if (bytes > LinkFrames.MAX_BYTES) {
            return worlds + " worlds of " + spec.robots().size() + " robots make a step's reply of " + bytes
                    + " bytes, over the link's " + LinkFrames.MAX_BYTES + ": fewer worlds (or a smaller message)";
        }
        return null;
    }

    /** A page asks nothing of a learning host: the learner steps it. */
    private static final ControlCommands NO_COMMANDS = new ControlCommands() {
        @Override
        public List<ControlVerb> verbs() {
            return List.of();
        }
    };

    /** What a learning host's viewer port says of itself. */
    private static final PortGuide GUIDE = new PortGuide() {
        @Override
        public String description(Port p) {
            return "a learning host's viewer port";
        }

        @Override
        public String wrongPort(Port here, java.io.Externalizable hello) {
            return "that is a learning host's viewer port (world 0 of a learner's batch); robots and Geometry "
                    + "connect to a live Environment";
        }

        @Override
        public String speaker() {
            return "this learning host";
        }
    };

    public static void main(String[] args) {
        CommandLines.exit("learning-host", new LearningHostMain(), args);
    }
}
