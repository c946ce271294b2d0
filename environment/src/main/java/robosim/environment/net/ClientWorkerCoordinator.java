package robosim.environment.net;

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

/**
 * Runs one simulation over sockets, the report's client interface: it waits until every robot named in
 * the file (and, unless geometry is in-process, a Geometry process) has connected, then steps in
 * lock-step. This class is the facade: it opens the ports, starts the threads, and turns the control
 * port's calls into events for the loop. Its threads, each named, none holding a lock across a socket
 * read or write, a sleep or a wait:
 * <ul>
 * <li>{@code simulation-loop} ({@link SimulationLoop}): the one owner of time; blocks on its event
 *     queue, timed to the next deadline, and in its writes to robots (bounded by the write watchdog).</li>
 * <li>{@code write-watchdog} ({@link WriteWatchdog}): cuts off a robot that has not taken one of the
 *     loop's writes within the write timeout; sleeps between looks.</li>
 * <li>{@code accept-robots}, {@code accept-viewers}, {@code accept-geometry} ({@link Listeners}): block
 *     in accept; each socket gets a worker thread (one over the port's cap is closed at once).</li>
 * <li>{@code handshake-deadlines} ({@link Listeners}): closes a connection whose hello is not accepted
 *     within the handshake timeout; sleeps until the next deadline.</li>
 * <li>{@code robot-worker[name]} ({@link RobotClientWorker}), one per robot: the handshake, then blocks
 *     in its socket read and posts each request (in {@code SEQUENTIAL} only the step-0 one; it then
 *     waits for the end).</li>
 * <li>{@code robot-writer[name]} ({@link RobotWriter}, {@code TWO_THREADS} only): blocks on its queue
 *     and in its socket write.</li>
 * <li>{@code stepper} ({@link SequentialReader}, {@code SEQUENTIAL} only): blocks in each robot's
 *     socket read in world order.</li>
 * <li>{@code geometry-worker} ({@link GeometryClientWorker}): blocks on its task queue, then in the
 *     Geometry round trip (write the step, read the answer).</li>
 * <li>{@code viewer-worker[n]} ({@link ViewerClientWorker}), one per viewer: blocks on its
 *     {@link ViewerQueue} and in its socket write (under the viewer write deadline).</li>
 * </ul>
 * Callers of {@link #pause}, {@link #resume}, {@link #step}, {@link #stop} wait on futures the loop completes.
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
    private final Handshakes handshakes;
    private final List<RunListener> runListeners = new CopyOnWriteArrayList<>();
    private final Design design;
    private final Inbox<Run> inbox;
    private final Run run;
    private final Listeners listeners;
    private final CountDownLatch endedLatch = new CountDownLatch(1);
    private final CountDownLatch startedLatch = new CountDownLatch(1);
    private volatile boolean began;
    private Thread loop;
    /** Times the loop's writes to robots (does nothing without a write timeout). */
    private final WriteWatchdog writeWatchdog;

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
        this.handshakes = new Handshakes(spec, robotNames, settings.stepMessages());
        // each robot has at most a request and a departure outstanding; the rest is rare
        this.inbox = new Inbox<>(2 * (robotNames.size() + spec.joinable()) + 1024, POST_LIMIT_MS);
        this.run = new Run(this, new RunListeners(runListeners));
        this.listeners = new Listeners(this);
        this.writeWatchdog = new WriteWatchdog(settings.writeTimeoutMs());
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

    /** Binds the three ports and starts accepting; a port in use is a {@link java.net.BindException} naming it. */
    public void start() throws IOException {
        listeners.bind();
        startLoop();
        listeners.accept();
        LOG.info("waiting for {} robot(s){}", robotNames.size(),
                settings.inProcessGeometry() ? "" : " and a Geometry process");
    }

    /** Starts the {@code simulation-loop} thread; events posted from now on are taken. */
    void startLoop() {
        writeWatchdog.start();
        loop = new Thread(new SimulationLoop(this, inbox, run), "simulation-loop");
        loop.setDaemon(true);
        loop.start();
    }

    /** The bound ports: robot, viewer, geometry (-1 when geometry is in-process). */
    public int[] ports() {
        return listeners.ports();
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

    Handshakes handshakes() {
        return handshakes;
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
        listeners.close();
        writeWatchdog.stop();
        endedLatch.countDown();
        startedLatch.countDown();
    }

    /** Times the loop's writes to each robot. */
    WriteWatchdog writeWatchdog() {
        return writeWatchdog;
    }

    /** A viewer's worker has ended (any thread, also after the run): it is no longer one of the run's viewers. */
    void viewerLeft(ViewerClientWorker viewer, String why) {
        run.viewers().remove(viewer, why);
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
        return run.record().summary(Math.max(robotNames.size(), run.record().states.size()));
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
        listeners.awaitClosed(timeoutMs);
    }

    @Override
    public void close() {
        stop("the Environment was shut down");
        listeners.close();
        for (ViewerSink v : run.viewers().all()) {
            v.drop();
        }
    }
}
