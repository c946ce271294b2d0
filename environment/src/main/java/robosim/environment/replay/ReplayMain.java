package robosim.environment.replay;

import java.io.Externalizable;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.environment.control.ControlServer;
import robosim.environment.control.WebViewers;
import robosim.environment.run.RunListener;
import robosim.environment.server.Acceptors;
import robosim.environment.server.Port;
import robosim.environment.server.PortGuide;
import robosim.environment.server.ServerContext;
import robosim.environment.server.ServerOptions;
import robosim.environment.server.ViewerClientWorker;
import robosim.environment.server.Viewers;
import robosim.protocol.GeometryHello;
import robosim.protocol.RecordingReader;
import robosim.protocol.SimulationKeys;
import robosim.protocol.StepNumbers;
import robosim.web.WebViewerServer;

/**
 * {@code scripts/replay.sh FILE}: serves a recording ({@code --record}) on the viewer port as the live
 * Environment served the run, steered from the control port. Prints {@code listening viewers=P control=P}
 * once its ports are bound and {@code replay ended step=S} at the end. Exit codes: 0 done, 2 bad input.
 */
@Command(name = "replay.sh", mixinStandardHelpOptions = true,
        description = "Replays a recording made with --record to any viewer: pause, step, seek and speed from "
                + "the Control Panel or the control port.")
public final class ReplayMain implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "The recording (environment.sh or headless.sh --record).")
    Path file;

    @Mixin
    ServerOptions server;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--speed", defaultValue = "1", description = "Times real time, from " + ReplayClock.MIN_SPEED
            + " to " + ReplayClock.MAX_SPEED + " (default: ${DEFAULT-VALUE}: the run's time step per step).")
    double speed;

    @Option(names = "--paused", description = "Hold before the first step until resume or step (default: start "
            + "when the first viewer connects).")
    boolean paused;

    @Option(names = "--exit-at-end", description = "After the last step send the end to every viewer and exit, as "
            + "the live run did (default: hold at the last step, so viewers can seek back, until stop).")
    boolean exitAtEnd;

    @Override
    public Integer call() throws Exception {
        if (!(speed >= ReplayClock.MIN_SPEED && speed <= ReplayClock.MAX_SPEED)) {
            System.err.println("replay: --speed must be from " + ReplayClock.MIN_SPEED + " to "
                    + ReplayClock.MAX_SPEED + ", got " + speed);
            return 2;
        }
        InetAddress bindAddress;
        SimulationKeys keys;
        RecordingReader recording;
        try {
            bindAddress = server.bind();
            keys = SimulationKeys.fromEnvironment();
            String bad = server.handshakeTimeoutMs() < 1 ? "--handshake-timeout-ms must be >= 1 (a viewer's hello "
                    + "has a deadline), got " + server.handshakeTimeoutMs() : server.problem(keys, bindAddress);
            if (bad != null) {
                System.err.println("replay: " + bad);
                return 2;
            }
            recording = new RecordingReader(file);
        } catch (java.net.UnknownHostException e) {
            System.err.println("replay: --bind " + server.bindName() + ": no such address");
            return 2;
        } catch (IOException e) {
            System.err.println("replay: " + e.getMessage());
            return 2;
        }
        Viewers viewers = new Viewers();
        ReplayClock clock = new ReplayClock(recording, viewers, speed, exitAtEnd, paused);
        ServerContext context = server.context(keys, GUIDE);
        Acceptors port = new Acceptors(context, bindAddress, 256);
        ControlServer control = null;
        WebViewerServer web = null;
        try {
            try {
                port.bind(Port.VIEWER, server.viewerPort(), server.maxConnections(),
                        (s, n) -> new ViewerClientWorker(context, s, "replay-viewer[" + n + "]", clock));
            } catch (BindException e) {
                if (given("--viewer-port")) {
                    throw e;
                }
                // the default taken (by a live run): a free one, with a context of its own (the failed bind stopped
                // the first one's connection watch)
                ServerContext fresh = server.context(keys, GUIDE);
                port = new Acceptors(fresh, bindAddress, 256);
                port.bind(Port.VIEWER, 0, server.maxConnections(),
                        (s, n) -> new ViewerClientWorker(fresh, s, "replay-viewer[" + n + "]", clock));
                System.err.println("replay: the viewer port " + server.viewerPort() + " is taken; viewers connect to "
                        + port.port(Port.VIEWER) + " (--viewer-port to choose)");
            }
            if (server.controlPort() >= 0) {
                control = new ControlServer(new ReplayCommands(clock, file), keys, server.handshakeTimeoutMs());
                try {
                    control.start(bindAddress, server.controlPort());
                } catch (BindException e) {
                    if (given("--control-port")) {
                        throw e;
                    }
                    control = new ControlServer(new ReplayCommands(clock, file), keys, server.handshakeTimeoutMs());
                    control.start(bindAddress, 0);
                    System.err.println("replay: the control port " + server.controlPort() + " is taken; the control "
                            + "port is " + control.port() + " (--control-port to choose)");
                }
            }
            if (server.webPort() >= 0) {
                web = WebViewers.start(server.webPort(), bindAddress, port.port(Port.VIEWER), keys,
                        new ReplayCommands(clock, file));
            }
        } catch (IOException e) {
            close(port, control, recording);
            System.err.println("replay: " + e.getMessage() + (e instanceof BindException
                    ? " (choose another with --viewer-port or --control-port)" : ""));
            return 2;
        }
        clock.start();
        port.accept();
        Runtime.getRuntime().addShutdownHook(new Thread(() -> stopOnSignal(clock, viewers), "shutdown"));
        System.out.println("listening viewers=" + port.port(Port.VIEWER) + " control=" + (control == null ? -1 : control.port())
                + (web == null ? "" : " web=" + web.port()));
        System.out.println("replaying " + file + ": " + recording.steps() + " steps"
                + (recording.steps() == 0 ? "" : " (" + StepNumbers.shown(recording.stepNumber(0)) + " to "
                + StepNumbers.shown(recording.stepNumber(recording.steps() - 1)) + ")")
                + (recording.end() == null ? ", cut short" + (recording.cutShort() == null ? "" : ": " + recording.cutShort())
                : ", ended: " + recording.end().reason()));
        System.out.flush();
        try {
            while (!clock.awaitEnd(TimeUnit.DAYS.toMillis(1))) {
                // a replay held at its end waits for stop for as long as it takes
            }
            viewers.awaitDone(Math.max(1000, server.writeTimeoutMs()));
            System.out.println("replay ended step=" + clock.endedAt());
            return 0;
        } finally {
            if (web != null) {
                web.close();
            }
            close(port, control, recording);
        }
    }

    /** Ctrl-C or SIGTERM: the end goes to every viewer before the process goes. */
    private static void stopOnSignal(ReplayClock clock, Viewers viewers) {
        try {
            clock.stop("the replay was stopped").get(5, TimeUnit.SECONDS);
            viewers.awaitDone(2000);
        } catch (Exception e) {
            // going anyway
        }
    }

    private static void close(Acceptors port, ControlServer control, RecordingReader recording) {
        port.close();
        if (control != null) {
            control.close();
        }
        try {
            recording.close();
        } catch (IOException ignored) {
            // read only
        }
    }

    /** What a replay's viewer port says of itself: a recording played back, not a live Environment. */
    private static final PortGuide GUIDE = new PortGuide() {
        @Override
        public String description(Port port) {
            return "a replay's viewer port";
        }

        @Override
        public String wrongPort(Port here, Externalizable hello) {
            return "that is a replay's viewer port (a recording played back); "
                    + (hello instanceof GeometryHello ? "Geometry connects" : "robots connect") + " to a live Environment";
        }

        @Override
        public String speaker() {
            return "this replay";
        }
    };

    public static void main(String[] args) {
        CommandLines.exit("replay", new ReplayMain(), args);
    }

    /** Whether the command line gave {@code option} (a port given is kept, taken or not; a default gives way). */
    private boolean given(String option) {
        return spec.commandLine().getParseResult().hasMatchedOption(option);
    }
}
