package robosim.environment.net;

import robosim.protocol.Printable;
import java.io.Closeable;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
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
import robosim.protocol.InMemoryLink;
import robosim.protocol.RobotHello;

/**
 * Runs one simulation over sockets: the report's {@code ClientWorkerCoordinator}, the Environment's
 * client interface. It keeps the report's name and role: it runs one thread per connected client (robot,
 * Geometry, viewer) and coordinates them through the one owner of time, the {@link SimulationLoop}, which
 * drives the {@link Run}. It waits until every robot named in the file (and, unless geometry is
 * in-process, a Geometry process) has connected, then steps in lock-step. As the Environment's facade it
 * opens the ports, starts the threads, and turns the control port's calls into events for the loop;
 * callers of {@link #pause}, {@link #resume}, {@link #step}, {@link #stop} wait on futures the loop
 * completes. Its threads are listed in the {@linkplain robosim.environment.net package} documentation.
 */
public final class ClientWorkerCoordinator implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ClientWorkerCoordinator.class);
    /** How long a thread posting an event waits for room in the loop's queue before giving up, ms. */
    private static final long POST_LIMIT_MS = 5_000;
    /** How long {@link #stop} waits for the loop to end the run, ms. */
    private static final long STOP_WAIT_MS = 5_000;

    private final WorldSpec spec;
    private final Settings settings;
    private final List<String> robotNames;
    private final Admission admission;
    private final List<RunListener> runListeners = new CopyOnWriteArrayList<>();
    private final Design design;
    private final Inbox<Run> inbox;
    private final Run run;
    private final ServerContext server;
    private final RunViewers viewers;
    private final Acceptors acceptors;
    private final CountDownLatch endedLatch = new CountDownLatch(1);
    private final CountDownLatch startedLatch = new CountDownLatch(1);
    private volatile boolean began;
    private Thread loop;
    /** Starts the file's robots in this JVM (a one-JVM run), or null: every robot connects. */
    private InMemoryLink.Starter inMemory;

    /** @throws IllegalArgumentException for {@code SEQUENTIAL} with a lost robot held (its stepper reads a fixed list) */
    public ClientWorkerCoordinator(WorldSpec spec, Settings settings) {
        this.design = Design.of(settings.design());
        String refusal = design.refusesLossPolicy(settings.onRobotLoss());
        if (refusal != null) {
            throw new IllegalArgumentException(refusal);
        }
        this.spec = spec;
        this.settings = settings;
        this.robotNames = spec.robots().stream().map(WorldSpec.RobotSpec::name).toList();
        this.admission = new Admission(spec, robotNames, settings.stepMessages());
        // each robot has at most a request and a departure outstanding; the rest is rare
        this.inbox = new Inbox<>(2 * (robotNames.size() + spec.joinable()) + 1024, POST_LIMIT_MS);
        this.server = ServerContext.of(settings.keys(), settings.resetEvery(), settings.handshakeTimeoutMs(),
                settings.writeTimeoutMs(), Port.environment(this::ports));
        this.viewers = new RunViewers(this::post, spec, this::status);
        this.run = new Run(this, new RunListeners(runListeners));
        this.acceptors = new Acceptors(server, settings.bind(), 1024);
    }

    /** Adds a listener; call before {@link #start} to hear everything. */
    public void listen(RunListener listener) {
        runListeners.add(listener);
    }

    /** Starts the run paused: nothing moves until {@link #resume} or {@link #step}. Call before {@link #start}. */
    public void startPaused() {
        if (loop != null) {
            throw new IllegalStateException("startPaused() after start()");
        }
        run.startPaused();
    }

    /**
     * Runs every robot the file names in this JVM, started by {@code starter} with its type and control class,
     * through an in-memory link ({@link InMemoryLink}): no socket and no serialization between them and the
     * loop. Robots that join later still connect. Call before {@link #start}; the robots start with
     * {@link #startRobotsInThisJvm}, after it.
     */
    public void robotsInThisJvm(InMemoryLink.Starter starter) {
        if (loop != null) {
            throw new IllegalStateException("robotsInThisJvm() after start()");
        }
        inMemory = starter;
    }

    /** Binds the three ports and starts accepting; a port in use is a {@link java.net.BindException} naming it. */
    public void start() throws IOException {
        int cap = settings.maxConnections();
        int robots = spec.robots().size() + spec.joinable(); // (and its join rules')
        acceptors.bind(Port.ROBOT, settings.robotPort(), robots + cap, (s, n) -> new RobotClientWorker(this, s, n));
        acceptors.bind(Port.VIEWER, settings.viewerPort(), cap,
                (s, n) -> new ViewerClientWorker(server, s, "viewer-worker[" + n + "]", viewers));
        if (!settings.inProcessGeometry()) {
            acceptors.bind(Port.GEOMETRY, settings.geometryPort(), cap, (s, n) -> new GeometryClientWorker(this, s));
        }
        startLoop();
        acceptors.accept();
        LOG.info("waiting for {} robot(s){}", robotNames.size(),
                settings.inProcessGeometry() ? "" : " and a Geometry process");
    }

    /**
     * After {@link #start}, with no lock held (each control class's constructor runs here): starts every robot of
     * the file in this JVM and says its hello; one that cannot start ends the run, saying why.
     */
    public void startRobotsInThisJvm() {
        for (WorldSpec.RobotSpec r : spec.robots()) {
            String refusal;
            try {
                helloInMemory(r.name(), r.type(), r.control()).thenAccept(why -> {
                    if (why != null && !LoopEvent.OVER.equals(why)) {
                        LOG.error("robot {} (in this JVM) was refused: {}", r.name(), Printable.of(why));
                    }
                });
                refusal = null;
            } catch (IllegalArgumentException e) {
                refusal = e.getMessage();
            }
            if (refusal != null) {
                stop("robot " + r.name() + " could not start in this JVM: " + refusal);
                return;
            }
        }
    }

    /**
     * Starts robot {@code name} in this JVM ({@link #robotsInThisJvm}) and says its hello: a robot of the file, or
     * one the control port has added. Returns the loop's verdict (null: welcomed, else why not).
     *
     * @throws IllegalArgumentException why it cannot start (its type, its control class, the hello's check)
     */
    public CompletableFuture<String> helloInMemory(String name, String type, String control) {
        if (inMemory == null) {
            throw new IllegalArgumentException("this Environment runs no robots in its JVM");
        }
        InMemoryPeer peer = new InMemoryPeer(run.inMemory(), name);
        peer.attach(inMemory.start(name, type, control, peer));
        RobotHello hello = peer.hello();
        String refusal = admission.check(hello, spec.indexOf(name));
        if (refusal != null) {
            throw new IllegalArgumentException(refusal);
        }
        CompletableFuture<String> verdict = new CompletableFuture<>();
        post(new LoopEvent.RobotJoins(peer, hello, spec.indexOf(name), verdict));
        return verdict;
    }

    /** True if this simulation runs its robots in this JVM ({@link #robotsInThisJvm}). */
    public boolean runsRobotsInThisJvm() {
        return inMemory != null;
    }

    /**
     * After the end: waits up to {@code ms} for the control code of the robots it ran in this JVM to end; returns
     * {@code NAME: what it threw} for each whose control code threw out of {@code run}.
     */
    public List<String> awaitControlCode(long ms) throws InterruptedException {
        return inMemory == null ? List.of() : inMemory.awaitControlCode(ms);
    }

    /** Starts the {@code simulation-loop} thread; events posted from now on are taken. */
    void startLoop() {
        loop = new Thread(new SimulationLoop(this, inbox, run), "simulation-loop");
        loop.setDaemon(true);
        loop.start();
    }

    /** The bound ports: robot, viewer, geometry (-1 when geometry is in-process). */
    public int[] ports() {
        return new int[] {acceptors.port(Port.ROBOT), acceptors.port(Port.VIEWER), acceptors.port(Port.GEOMETRY)};
    }

    /** What every connection is served with. */
    ServerContext server() {
        return server;
    }

    /** The run's viewers. */
    RunViewers viewers() {
        return viewers;
    }

    Settings settings() {
        return settings;
    }

    WorldSpec spec() {
        return spec;
    }

    /** The coordinator design this run uses, chosen once. */
    Design design() {
        return design;
    }

    Admission admission() {
        return admission;
    }

    /**
     * Hands {@code event} to the loop; if the run is over (or the loop's queue stays full past the post
     * limit), the event is refused instead, so whoever waits on its answer is answered.
     */
    void post(LoopEvent event) {
        if (!inbox.post(event) && !inbox.closed()) {
            LOG.warn("the simulation loop has not taken an event for {} ms; {} is refused", POST_LIMIT_MS,
                    event.getClass().getSimpleName());
        }
    }

    boolean isOver() {
        return inbox.closed();
    }

    /** Loop thread: the run has begun (or holds before step 0) with every client there. */
    void started() {
        began = true;
        startedLatch.countDown();
    }

    /** Loop thread, last: the loop is done; what is still queued is answered, the ports close. */
    void loopEnded() {
        inbox.close();
        acceptors.close();
        endedLatch.countDown();
        startedLatch.countDown();
    }

    /** Blocks until the simulation is over. */
    public void awaitEnd() throws InterruptedException {
        endedLatch.await();
    }

    // ---- run control (the control port) ------------------------------------------------------------------

    /**
     * Pauses after the step in progress (or before step 0, if the run has not begun); returns once the
     * Environment holds, or at once when no run is under way, or after the timeout.
     */
    public void pause(long timeout, TimeUnit unit) throws InterruptedException {
        CompletableFuture<Void> held = new CompletableFuture<>();
        post(new LoopEvent.Pause(held));
        await(held, timeout, unit);
    }

    /** Resumes a paused run (or lets it begin when every client is there); returns once the status says so. */
    public void resume() throws InterruptedException {
        CompletableFuture<Void> applied = new CompletableFuture<>();
        post(new LoopEvent.Resume(applied));
        await(applied, STOP_WAIT_MS, TimeUnit.MILLISECONDS);
    }

    /**
     * Runs {@code n} more steps and pauses again; waits until they are out (or the run ends, or the
     * timeout passes). Returns the steps out so far.
     */
    public long step(long n, long timeout, TimeUnit unit) throws InterruptedException {
        CompletableFuture<Long> done = new CompletableFuture<>();
        post(new LoopEvent.StepN(n, done));
        Long at = await(done, timeout, unit);
        return at == null ? run.record().stepsReleased : at;
    }

    static <T> T await(CompletableFuture<T> f, long timeout, TimeUnit unit) throws InterruptedException {
        try {
            return f.get(timeout, unit);
        } catch (TimeoutException | ExecutionException e) {
            return null;
        }
    }

    /** Adds and removes robots from the control port. */
    public RobotRoster roster() {
        return new RobotRoster(this);
    }

    /** Ends the simulation: robots, viewers and Geometry are told why. Returns once it has ended (at most a few s). */
    public void stop(String reason) {
        if (loop == null) {
            inbox.close();
            endedLatch.countDown();
            startedLatch.countDown();
            return;
        }
        post(new LoopEvent.Stop(reason));
        try {
            if (!endedLatch.await(STOP_WAIT_MS, TimeUnit.MILLISECONDS)) {
                LOG.warn("the simulation loop did not end the run within {} ms of: {}", STOP_WAIT_MS, reason);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** What the control port reports: published by the loop, read without waiting for it. */
    public RunStatus status() {
        return run.record().status(robotNames, run.viewers().count());
    }

    public RunSummary summary() {
        long inWorld = run.record().states.stream().filter(r -> !RobotState.ADDED.equals(r.state())).count();
        return run.record().summary((int) Math.max(robotNames.size(), inWorld));
    }

    // ---- waiting for the run ---------------------------------------------------------------------------

    /** Waits until every client is there and the run has begun; true if it began (false if it ended first, or on timeout). */
    public boolean awaitStart(long timeout, TimeUnit unit) throws InterruptedException {
        return startedLatch.await(timeout, unit) && began;
    }

    public boolean awaitEnd(long timeout, TimeUnit unit) throws InterruptedException {
        return endedLatch.await(timeout, unit);
    }

    /** After the end: waits up to {@code timeoutMs} each for the recording and for viewer workers to send what they hold. */
    public void awaitOutputDone(long timeoutMs) throws InterruptedException {
        RunRecorder recorder = run.recorder(); // (its own wait: a stuck viewer takes nothing from it)
        if (recorder != null) {
            recorder.awaitWritten(timeoutMs);
        }
        run.viewers().awaitDone(timeoutMs);
    }

    /** After the end: waits until the listening sockets are really released, so a next simulation can bind them. */
    public void awaitServersClosed(long timeoutMs) throws InterruptedException {
        acceptors.awaitClosed(timeoutMs);
    }

    @Override
    public void close() {
        stop("the Environment was shut down");
        acceptors.close();
        for (ViewerSink v : run.viewers().all()) {
            v.drop();
        }
    }
}
