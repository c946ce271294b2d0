package robosim.environment.net;

import robosim.environment.run.HelloCheck;
import robosim.environment.run.LoopEvent;
import robosim.environment.run.Progress;
import robosim.environment.run.ReleaseListener;
import robosim.environment.run.RobotState;
import robosim.environment.run.Run;
import robosim.environment.run.RunListener;
import robosim.environment.run.RunListeners;
import robosim.environment.run.RunRecorder;
import robosim.environment.run.RunStatus;
import robosim.environment.run.RunSummary;
import robosim.environment.run.RunViewers;
import robosim.environment.run.Settings;
import robosim.environment.run.SimulationLoop;
import robosim.environment.run.Transport;
import java.io.Closeable;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.WorldSpec;
import robosim.environment.server.Acceptors;
import robosim.environment.server.Port;
import robosim.environment.server.ServerContext;
import robosim.environment.server.ViewerClientWorker;
import robosim.environment.server.ViewerSink;
import robosim.protocol.Printable;

/**
 * Runs one simulation over sockets: the report's {@code ClientWorkerCoordinator}, the Environment's client
 * interface, and the one class that knows every part. It keeps the report's name and role: it runs one thread per
 * connected client (robot, Geometry, viewer) and coordinates them through the one owner of time, the
 * {@link SimulationLoop}, which drives the {@link Run}. It waits until every robot named in the file (and, unless
 * geometry is in-process, a Geometry process) has connected, then steps in lock-step. As the Environment's facade
 * it builds the run and its outputs (viewers, the recording), the loop, the transports (their {@link RobotContext},
 * the shared connections' and the in-memory robots' {@link LoopHook}s) and the ports ({@link Acceptors}, whose
 * workers get a {@link ServerContext} and never this class), starts the threads, and turns the control port's
 * calls into events for the loop; callers of {@link #pause}, {@link #resume}, {@link #step}, {@link #stop} wait on
 * futures the loop completes. Its threads are listed in the {@linkplain robosim.environment.net package}
 * documentation.
 */
public final class ClientWorkerCoordinator implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ClientWorkerCoordinator.class);
    /** How long {@link #stop} waits for the loop to end the run, ms. */
    private static final long STOP_WAIT_MS = 5_000;
    /** How long {@link #resume} waits for the loop, ms. */
    private static final long RESUME_WAIT_MS = 5_000;

    private final WorldSpec spec;
    private final Settings settings;
    private final List<String> robotNames;
    private final List<RunListener> runListeners = new CopyOnWriteArrayList<>();
    private final HelloCheck check;
    private final SimulationLoop loop;
    private final RunViewers viewers;
    /** The recording ({@code --record}), or null. */
    private final RunRecorder recorder;
    private final Run run;
    /** The robots of the file in this JVM ({@code --one-jvm}), or null: every robot connects. */
    private final InMemoryTransport inMemory;
    private final SharedOutput frames = new SharedOutput();
    private final RobotContext robots;
    private final ServerContext server;
    private final Acceptors acceptors;
    private volatile boolean started;

    /** @throws IllegalArgumentException a robot in this JVM whose hello the file refuses (at {@link #startRobotsInThisJvm}) */
    public ClientWorkerCoordinator(WorldSpec spec, Settings settings) {
        this.spec = spec;
        this.settings = settings;
        this.robotNames = spec.robots().stream().map(WorldSpec.RobotSpec::name).toList();
        this.check = new HelloCheck(spec);
        // each robot has at most a request and a departure outstanding; the rest is rare
        this.loop = new SimulationLoop(2 * (robotNames.size() + spec.joinable()) + 1024, settings, this::loopEnded);
        this.viewers = new RunViewers(loop::post, spec, this::status);
        this.recorder = settings.record() == null ? null : new RunRecorder(settings.record(), settings.recordReadings());
        List<ReleaseListener> outputs = new ArrayList<>(List.of(viewers));
        if (recorder != null) {
            outputs.add(recorder);
        }
        this.run = new Run(spec, settings, check, System::nanoTime, new RunListeners(runListeners), outputs);
        Design design = switch (settings.design()) {
            case THREADS -> new ThreadsDesign();
            case SEQUENTIAL -> new SequentialDesign(loop);
            case TWO_THREADS -> new TwoThreadsDesign();
        };
        runListeners.add(design);
        this.inMemory = settings.robotsInThisJvm() == null ? null
                : new InMemoryTransport(settings.robotsInThisJvm(), check, loop::post);
        this.robots = new RobotContext(check, loop, design, settings.design().refuses(Transport.SHARED));
        this.server = ServerContext.of(settings.keys(), settings.resetEvery(), settings.handshakeTimeoutMs(),
                settings.writeTimeoutMs(), Port.environment(this::ports));
        this.acceptors = new Acceptors(server, settings.bind(), 1024);
    }

    /** Adds a listener; call before {@link #start} to hear everything. */
    public void listen(RunListener listener) {
        runListeners.add(listener);
    }

    /** Starts the run paused: nothing moves until {@link #resume} or {@link #step}. Call before {@link #start}. */
    public void startPaused() {
        if (started) {
            throw new IllegalStateException("startPaused() after start()");
        }
        run.startPaused();
    }

    /** Binds the ports and starts the loop and accepting; a port in use is a {@link java.net.BindException} naming it. */
    public void start() throws IOException {
        int cap = settings.maxConnections();
        int expected = robotNames.size() + spec.joinable(); // (and its join rules')
        acceptors.bind(Port.ROBOT, settings.robotPort(), expected + cap,
                (s, n) -> new RobotClientWorker(server, robots, frames, s, n));
        acceptors.bind(Port.VIEWER, settings.viewerPort(), cap,
                (s, n) -> new ViewerClientWorker(server, s, "viewer-worker[" + n + "]", viewers));
        if (!settings.inProcessGeometry()) {
            acceptors.bind(Port.GEOMETRY, settings.geometryPort(), cap, (s, n) -> new GeometryClientWorker(server, loop, s));
        }
        started = true;
        loop.start(run, inMemory == null ? List.of(frames) : List.of(inMemory, frames));
        acceptors.accept();
        LOG.info("waiting for {} robot(s){}", robotNames.size(),
                settings.inProcessGeometry() ? "" : " and a Geometry process");
    }

    /**
     * After {@link #start}, with no lock held (each control class's constructor runs here): starts every robot of
     * the file in this JVM ({@link Settings#robotsInThisJvm}) and says its hello; one that cannot start ends the
     * run, saying why.
     */
    public void startRobotsInThisJvm() {
        if (inMemory == null) {
            return;
        }
        for (WorldSpec.RobotSpec r : spec.robots()) {
            try {
                inMemory.start(r.name(), r.type(), r.control()).thenAccept(why -> {
                    if (why != null && !Progress.OVER.equals(why)) {
                        LOG.error("robot {} (in this JVM) was refused: {}", r.name(), Printable.of(why));
                    }
                });
            } catch (IllegalArgumentException e) {
                stop("robot " + r.name() + " could not start in this JVM: " + e.getMessage());
                return;
            }
        }
    }

    /** True if this simulation runs its robots in this JVM ({@link Settings#robotsInThisJvm}). */
    public boolean runsRobotsInThisJvm() {
        return inMemory != null;
    }

    /**
     * After the end: waits up to {@code ms} for the control code of the robots it ran in this JVM to end; says whose
     * threw out of {@code run} and whose is still running.
     */
    public robosim.protocol.InMemoryLink.ControlEnd awaitControlCode(long ms) throws InterruptedException {
        return inMemory == null ? robosim.protocol.InMemoryLink.ControlEnd.CLEAN : inMemory.awaitControlCode(ms);
    }

    /** The bound ports: robot, viewer, geometry (-1 when geometry is in-process). */
    public int[] ports() {
        return new int[] {acceptors.port(Port.ROBOT), acceptors.port(Port.VIEWER), acceptors.port(Port.GEOMETRY)};
    }

    /** Loop thread, last: the loop is done; the ports close (the connection watch ends once its connections have). */
    private void loopEnded() {
        acceptors.close();
    }

    /** Blocks until the simulation is over. */
    public void awaitEnd() throws InterruptedException {
        loop.awaitEnd();
    }

    // ---- run control (the control port) ------------------------------------------------------------------

    /**
     * Pauses after the step in progress (or before step 0, if the run has not begun); returns once the
     * Environment holds, or at once when no run is under way, or after the timeout.
     */
    public void pause(long timeout, TimeUnit unit) throws InterruptedException {
        CompletableFuture<Void> held = new CompletableFuture<>();
        loop.post(new LoopEvent.Pause(held));
        await(held, timeout, unit);
    }

    /** Resumes a paused run (or lets it begin when every client is there); returns once the status says so. */
    public void resume() throws InterruptedException {
        CompletableFuture<Void> applied = new CompletableFuture<>();
        loop.post(new LoopEvent.Resume(applied));
        await(applied, RESUME_WAIT_MS, TimeUnit.MILLISECONDS);
    }

    /**
     * Runs {@code n} more steps and pauses again; waits until they are out (or the run ends, or the
     * timeout passes). Returns the steps out so far.
     */
    public long step(long n, long timeout, TimeUnit unit) throws InterruptedException {
        CompletableFuture<Long> done = new CompletableFuture<>();
        loop.post(new LoopEvent.StepN(n, done));
        Long at = await(done, timeout, unit);
        return at == null ? run.published().stepsReleased() : at;
    }

    private static <T> T await(CompletableFuture<T> f, long timeout, TimeUnit unit) throws InterruptedException {
        try {
            return f.get(timeout, unit);
        } catch (TimeoutException | ExecutionException e) {
            return null;
        }
    }

    /** Adds and removes robots from the control port. */
    public RobotRoster roster() {
        return new RobotRoster(loop, inMemory);
    }

    /** Ends the simulation: robots, viewers and Geometry are told why. Returns once it has ended (at most a few s). */
    public void stop(String reason) {
        if (!started) {
            loop.never();
            run.published().ready(false);
            return;
        }
        loop.post(new LoopEvent.Stop(reason));
        try {
            if (!loop.awaitEnd(STOP_WAIT_MS, TimeUnit.MILLISECONDS)) {
                LOG.warn("the simulation loop did not end the run within {} ms of: {}", STOP_WAIT_MS, reason);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** What the control port reports: published by the loop, read without waiting for it. */
    public RunStatus status() {
        return run.published().status(robotNames, viewers.list().count());
    }

    /** The run's built-in metrics as of the last step out, by name in column order (none before it began). */
    public java.util.Map<String, Double> metrics() {
        return run.published().metrics();
    }

    public RunSummary summary() {
        long inWorld = run.published().states().stream().filter(r -> !RobotState.ADDED.equals(r.state())).count();
        return run.published().summary((int) Math.max(robotNames.size(), inWorld));
    }

    // ---- waiting for the run ---------------------------------------------------------------------------

    /** Waits until every client is there and the run has begun; true if it began (false if it ended first, or on timeout). */
    public boolean awaitStart(long timeout, TimeUnit unit) throws InterruptedException {
        return run.published().awaitReady(timeout, unit);
    }

    public boolean awaitEnd(long timeout, TimeUnit unit) throws InterruptedException {
        return loop.awaitEnd(timeout, unit);
    }

    /** After the end: waits up to {@code timeoutMs} each for the recording and for viewer workers to send what they hold. */
    public void awaitOutputDone(long timeoutMs) throws InterruptedException {
        if (recorder != null) { // (its own wait: a stuck viewer takes nothing from it)
            recorder.awaitWritten(timeoutMs);
        }
        viewers.list().awaitDone(timeoutMs);
    }

    /** After the end: waits until the listening sockets are really released, so a next simulation can bind them. */
    public void awaitServersClosed(long timeoutMs) throws InterruptedException {
        acceptors.awaitClosed(timeoutMs);
    }

    @Override
    public void close() {
        stop("the Environment was shut down");
        acceptors.close();
        for (ViewerSink v : viewers.list().all()) {
            v.drop();
        }
    }
}
