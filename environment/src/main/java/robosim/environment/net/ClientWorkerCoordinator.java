package robosim.environment.net;

import java.io.Closeable;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.channels.ServerSocketChannel;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.EnvironmentMap;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.protocol.PoseUpdate;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotWelcome;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.WorldSnapshot;

/**
 * Runs one simulation over sockets: waits until every robot named in the file (and, unless
 * geometry is in-process, a Geometry process) has connected, then steps in lock-step.
 *
 * <p>Threads it owns: {@code accept-robots}, {@code accept-viewers}, {@code accept-geometry} (one
 * per listening socket); one {@code robot-worker[name]} per robot; one {@code viewer-worker[n]} per
 * viewer; one {@code geometry-worker}. All shared state is guarded by {@link #lock}. The step
 * itself - core, geometry round trip, every robot's response, viewer publication - runs on the
 * thread of the last robot worker to arrive with its request ({@link #processMessage}); the other
 * robot workers are then already back in their socket reads. Every write to a robot's connection
 * after its welcome happens under the lock.
 */
public final class ClientWorkerCoordinator implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ClientWorkerCoordinator.class);

    /**
     * How the Environment runs.
     *
     * @param maxSteps steps to run before ending; 0 runs until stopped
     * @param stepMessages true (the default): the next step number follows every response; false: only
     *     step 0 is sent and robots count on (the report's untested idea, measured in docs/PERFORMANCE.md)
     */
    public record Settings(InetAddress bind, int robotPort, int viewerPort, int geometryPort,
            boolean inProcessGeometry, long maxSteps, int resetEvery, int handshakeTimeoutMs, double speed,
            Design design, boolean stepMessages, long stepTimeoutMs, long geometryTimeoutMs,
            GeometryLoss onGeometryLoss) {
        /** Default step and Geometry timeouts, ms. */
        public static final long DEFAULT_STEP_TIMEOUT_MS = 60_000;
        public static final long DEFAULT_GEOMETRY_TIMEOUT_MS = 10_000;

        /** As fast as possible (no pacing), the default (sequential) design, a step number every step. */
        public Settings(InetAddress bind, int robotPort, int viewerPort, int geometryPort, boolean inProcessGeometry,
                long maxSteps, int resetEvery, int handshakeTimeoutMs) {
            this(bind, robotPort, viewerPort, geometryPort, inProcessGeometry, maxSteps, resetEvery,
                    handshakeTimeoutMs, 0, Design.SEQUENTIAL, true, DEFAULT_STEP_TIMEOUT_MS,
                    DEFAULT_GEOMETRY_TIMEOUT_MS, GeometryLoss.IN_PROCESS);
        }

        public Settings withDesign(Design d) {
            return new Settings(bind, robotPort, viewerPort, geometryPort, inProcessGeometry, maxSteps, resetEvery,
                    handshakeTimeoutMs, speed, d, stepMessages, stepTimeoutMs, geometryTimeoutMs, onGeometryLoss);
        }

        public Settings withStepMessages(boolean on) {
            return new Settings(bind, robotPort, viewerPort, geometryPort, inProcessGeometry, maxSteps, resetEvery,
                    handshakeTimeoutMs, speed, design, on, stepTimeoutMs, geometryTimeoutMs, onGeometryLoss);
        }

        /** A robot that has not sent its request this long after the step was released is dropped (0: never). */
        public Settings withStepTimeoutMs(long ms) {
            return new Settings(bind, robotPort, viewerPort, geometryPort, inProcessGeometry, maxSteps, resetEvery,
                    handshakeTimeoutMs, speed, design, stepMessages, ms, geometryTimeoutMs, onGeometryLoss);
        }

        /** A Geometry process that takes longer than this over one step counts as lost (0: never). */
        public Settings withGeometryTimeoutMs(long ms) {
            return new Settings(bind, robotPort, viewerPort, geometryPort, inProcessGeometry, maxSteps, resetEvery,
                    handshakeTimeoutMs, speed, design, stepMessages, stepTimeoutMs, ms, onGeometryLoss);
        }

        public Settings withGeometryLoss(GeometryLoss policy) {
            return new Settings(bind, robotPort, viewerPort, geometryPort, inProcessGeometry, maxSteps, resetEvery,
                    handshakeTimeoutMs, speed, design, stepMessages, stepTimeoutMs, geometryTimeoutMs, policy);
        }
    }

    /**
     * What the Environment does when its Geometry process dies or stops answering mid-run:
     * {@code IN_PROCESS} (the default) resolves the step, and every later one, with the same geometry
     * library in-process (the results are the same, bit for bit) until a new Geometry process attaches;
     * {@code WAIT} holds the step until a new Geometry process attaches.
     */
    public enum GeometryLoss { IN_PROCESS, WAIT }

    /**
     * How robots' requests are read and responses written, the report's coordinator designs:
     * {@code THREADS}, one thread per robot that reads its requests, the responses all written by the
     * thread that ran the step (the default); {@code SEQUENTIAL}, the original's loop: after the
     * handshakes one {@code stepper} thread reads every robot's request in world order, runs the step
     * and delivers; {@code TWO_THREADS}, two threads per robot, one reading its requests and one
     * ({@code robot-writer[name]}) writing its responses, handed over by the thread that ran the step.
     */
    public enum Design { THREADS, SEQUENTIAL, TWO_THREADS }

    /** How a finished run went. */
    /** How a run went; {@code departures} says, for each robot that left mid-run, when and why. */
    public record Summary(long steps, int robots, double wallSeconds, String reason, boolean completed,
            long messagesDelivered, long messagesOutOfRange, long messagesRefused, int robotsLeft,
            int geometryLosses, int geometryAttaches, List<Departure> departures) {
    }

    /** A robot that left the run at {@code step}, and why (network text already made safe to print). */
    public record Departure(String robot, long step, String why) {
    }

    private enum State { WAITING, RUNNING, ENDED }

    private final WorldSpec spec;
    private final Settings settings;
    private final int robotCount;
    private final List<String> robotNames;
    private final ReentrantLock lock = new ReentrantLock();
    private final CountDownLatch endedLatch = new CountDownLatch(1);
    /** Counted down when every client is there and the run begins, or when it ends without beginning. */
    private final CountDownLatch startedLatch = new CountDownLatch(1);
    private final List<Departure> departures = new ArrayList<>();
    private final List<ViewerClientWorker> viewers = new CopyOnWriteArrayList<>();
    private final List<ServerSocket> servers = new ArrayList<>();
    private final List<Thread> acceptors = new CopyOnWriteArrayList<>();

    private final RobotClientWorker[] robots;
    private final RobotProperties[] properties;
    private final StepRequest[] requests;
    private final boolean[] active;
    private final boolean[] begun;
    /** Robots whose connection has closed (they exited, were dropped, or the run ended): never "connected". */
    private final boolean[] gone;
    private boolean robotsTold;
    private int registered;
    private volatile GeometryClientWorker geometry;
    /** A Geometry process being sent the world mid-run (under the lock), so stop() can unblock it. */
    private volatile GeometryClientWorker attaching;
    private State state = State.WAITING;
    private SimulationCore core;
    private int activeCount;
    private int arrived;
    private long generation;
    private long stepsDone;
    private long startNanos;
    private long endNanos;
    private String endReason = "";
    private boolean completed;
    private int serial;
    private int robotsLeft;
    private int geometryLosses;
    private int geometryAttaches;
    /** Signalled when a Geometry process attaches or the simulation ends (WAIT policy). */
    private final java.util.concurrent.locks.Condition geometryChanged = lock.newCondition();
    private boolean stepRunning;
    private long stepReleasedNanos;
    /** SEQUENTIAL: the robot whose request the stepper is reading now, or -1. */
    private volatile int stepperReading = -1;
    private java.util.concurrent.ScheduledExecutorService watchdog;
    // pause, resume, step N (the control port)
    private final java.util.concurrent.locks.Condition pauseChanged = lock.newCondition();
    private boolean paused;
    private long stepBudget;
    private boolean holding;
    /** True while the step's thread waits for the pace ({@code --speed}), the lock released. */
    private boolean pacing;
    /** Pacing counts from here: the start, or the end of the last hold (a pause is not caught up after). */
    private long paceOriginNanos;
    private long paceOriginStep;
    private boolean beginPending;
    private long rateMarkNanos;
    private long rateMarkSteps;
    private double recentRate;
    /** Steps whose responses have gone out (stepsDone counts a step held by a pause too). */
    private long stepsReleased;

    public ClientWorkerCoordinator(WorldSpec spec, Settings settings) {
        this.spec = spec;
        this.settings = settings;
        this.robotCount = spec.robots().size();
        List<String> names = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            names.add(r.name());
        }
        this.robotNames = List.copyOf(names);
        this.robots = new RobotClientWorker[robotCount];
        this.properties = new RobotProperties[robotCount];
        this.requests = new StepRequest[robotCount];
        this.active = new boolean[robotCount];
        this.begun = new boolean[robotCount];
        this.gone = new boolean[robotCount];
    }

    /** Binds the three ports and starts accepting; a port in use is a {@link BindException} naming it. */
    public void start() throws IOException {
        ServerSocket robotServer = bind("robot", settings.robotPort());
        ServerSocket viewerServer = bind("viewer", settings.viewerPort());
        ServerSocket geometryServer = settings.inProcessGeometry() ? null : bind("geometry", settings.geometryPort());
        acceptOn(robotServer, "accept-robots", s -> new RobotClientWorker(this, s, nextSerial()));
        acceptOn(viewerServer, "accept-viewers", s -> new ViewerClientWorker(this, s, nextSerial()));
        if (geometryServer != null) {
            acceptOn(geometryServer, "accept-geometry", s -> new GeometryClientWorker(this, s));
        } else {
            lock.lock();
            try {
                maybeStart();
            } finally {
                lock.unlock();
            }
        }
        LOG.info("waiting for {} robot(s){}", robotCount, settings.inProcessGeometry() ? "" : " and a Geometry process");
    }

    private synchronized int nextSerial() {
        return ++serial;
    }

    /**
     * Listens through a blocking {@link ServerSocketChannel}: the sockets it accepts read with one
     * system call per blocking read (see {@link robosim.protocol.Connector}).
     */
    private ServerSocket bind(String what, int port) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        // a later simulation of the same Environment listens on the same port at once
        channel.setOption(java.net.StandardSocketOptions.SO_REUSEADDR, true);
        ServerSocket s = channel.socket();
        try {
            s.bind(new InetSocketAddress(settings.bind(), port), 1024);
        } catch (BindException e) {
            channel.close();
            close();
            throw new BindException(what + " port " + port + " is already in use");
        }
        servers.add(s);
        return s;
    }

    private void acceptOn(ServerSocket server, String threadName, Function<Socket, ClientWorker> factory) {
        Thread t = new Thread(() -> {
            while (!server.isClosed()) {
                try {
                    Socket s = server.getChannel().accept().socket();
                    factory.apply(s).start();
                } catch (IOException e) {
                    if (!server.isClosed()) {
                        LOG.warn("{}: accept failed: {}", threadName, e.getMessage());
                        LockSupport.parkNanos(100_000_000L); // back off: e.g. out of file descriptors
                    }
                }
            }
        }, threadName);
        t.setDaemon(true);
        acceptors.add(t);
        t.start();
    }

    /**
     * After the end: waits until the listening sockets are really released (a blocked accept defers
     * the close until its thread leaves), so a next simulation can bind the same ports at once.
     */
    public void awaitServersClosed(long timeoutMs) throws InterruptedException {
        closeServers();
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        for (Thread t : acceptors) {
            t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
        }
    }

    /** The bound ports: robot, viewer, geometry (-1 when geometry is in-process). */
    public int[] ports() {
        int[] p = new int[3];
        p[0] = servers.get(0).getLocalPort();
        p[1] = servers.get(1).getLocalPort();
        p[2] = servers.size() > 2 ? servers.get(2).getLocalPort() : -1;
        return p;
    }

    Settings settings() {
        return settings;
    }

    WorldSpec spec() {
        return spec;
    }

    List<String> robotNames() {
        return robotNames;
    }

    Logger log() {
        return LOG;
    }

    // ---- registration -------------------------------------------------------------------------

    /**
     * Registers a robot and, under the lock, sends its welcome; returns null when accepted, else the
     * reason it is refused (the caller sends the refusal).
     */
    String register(RobotClientWorker worker, RobotHello hello, int index) throws IOException {
        if (hello.protocolVersion() != Protocol.VERSION) {
            return "protocol version " + hello.protocolVersion() + " is not supported (the Environment speaks "
                    + Protocol.VERSION + ")";
        }
        if (index < 0) {
            return "no robot named \"" + hello.name() + "\" in " + spec.source() + " (robots: "
                    + String.join(", ", robotNames) + ")";
        }
        String contradiction = spec.robots().get(index).contradiction(hello.properties(), spec.source());
        if (contradiction != null) {
            return contradiction;
        }
        lock.lock();
        try {
            if (state != State.WAITING) {
                return "the simulation is " + (state == State.RUNNING ? "already running" : "over");
            }
            if (robots[index] != null) {
                return "robot " + hello.name() + " is already connected";
            }
            WorldSpec.RobotSpec r = spec.robots().get(index);
            worker.welcome(RobotWelcome.accepted(spec.timeStepMs(), r.xMm(), r.yMm(), r.headingDeg(), robotNames,
                    r.sensorNames()).withStepMessages(settings.stepMessages()));
            robots[index] = worker;
            properties[index] = hello.properties();
            registered++;
            LOG.info("robot {} connected ({} of {})", hello.name(), registered, robotCount);
            maybeStart();
            return null;
        } finally {
            lock.unlock();
        }
    }

    String attachGeometry(GeometryClientWorker worker) {
        lock.lock();
        try {
            if (state == State.ENDED) {
                return "the simulation is over";
            }
            if (geometry != null && state == State.RUNNING) {
                // no step holds the lock now, so none is talking to it: the newcomer takes over (the old one
                // may have died between steps, which nothing notices until the next step)
                LOG.warn("a new Geometry process attaches while one is attached: it replaces the old one");
                geometry.drop();
                geometry = null;
            }
            if (geometry != null) {
                return "a Geometry process is already attached";
            }
            if (state == State.RUNNING) {
                // the old one was lost: this one takes over from the next step (or the step waiting for it)
                attaching = worker;
                try {
                    worker.sendWorld(core.map().geometryWorld());
                } catch (IOException e) {
                    return "could not send it the world: " + e.getMessage();
                } finally {
                    attaching = null;
                }
                geometry = worker;
                geometryAttaches++;
                core.useGeometry(worker);
                LOG.warn("a new Geometry process attached at step {}: geometry is resolved there again", stepsDone);
                geometryChanged.signalAll();
                return null;
            }
            geometry = worker;
            LOG.info("Geometry process attached");
            maybeStart();
            return null;
        } finally {
            lock.unlock();
        }
    }

    /** Under the lock: starts the run once every robot and the geometry are there. */
    private void maybeStart() {
        if (state != State.WAITING || registered < robotCount
                || (!settings.inProcessGeometry() && geometry == null)) {
            return;
        }
        List<RobotProperties> props = Arrays.asList(properties.clone());
        core = settings.inProcessGeometry() ? SimulationCore.withInProcessGeometry(spec, props)
                : new SimulationCore(spec, props, geometry);
        if (geometry != null) {
            try {
                geometry.sendWorld(core.map().geometryWorld());
            } catch (IOException e) {
                LOG.warn("could not send the world to Geometry ({}); waiting for another", e.getMessage());
                geometry.drop();
                geometry = null;
                return;
            }
        }
        core.onGeometryLoss(this::geometryLost);
        Arrays.fill(active, true);
        activeCount = robotCount;
        state = State.RUNNING;
        startNanos = System.nanoTime();
        stepReleasedNanos = startNanos;
        startedLatch.countDown();
        startWatchdog();
        LOG.info("all {} robot(s) connected: running{}", robotCount,
                settings.maxSteps() > 0 ? " for " + settings.maxSteps() + " steps" : "");
        rateMarkNanos = startNanos;
        if (paused && stepBudget == 0) {
            beginPending = true;
            LOG.info("every client is here; paused before step 0 (start or step from the control port)");
            pauseChanged.signalAll();
            announce(RunState.Phase.PAUSED);
        } else {
            beginAll();
        }
        if (activeCount == 0) {
            finish("every robot has left", false);
        } else if (sequential()) {
            Thread stepper = new Thread(this::stepSequentially, "stepper");
            stepper.setDaemon(true);
            stepper.start();
        }
    }

    /** Under the lock: sends every robot step 0, starting the lock-step. */
    private void beginAll() {
        beginPending = false;
        announce(RunState.Phase.RUNNING);
        startNanos = System.nanoTime();
        stepReleasedNanos = startNanos;
        rateMarkNanos = startNanos;
        paceOriginNanos = startNanos;
        paceOriginStep = 0;
        for (int i = 0; i < robotCount; i++) {
            if (!active[i]) {
                continue;
            }
            try {
                robots[i].begin(0);
                begun[i] = true;
            } catch (IOException e) {
                depart(i, "could not send it the first step: " + e.getMessage());
                robots[i].drop();
            }
        }
    }

    /**
     * The original's loop ({@link Design#SEQUENTIAL}), on the {@code stepper} thread (step 0's requests are
     * read by the workers, so a robot leaving before the start is noticed): read each
     * active robot's request in world order, then run and deliver the step under the lock. A robot
     * whose read fails or who breaks the protocol is dropped, as in the threaded design.
     */
    private void stepSequentially() {
        try {
            while (true) {
                long k;
                RobotClientWorker[] order;
                lock.lock();
                try {
                    if (state != State.RUNNING) {
                        return;
                    }
                    k = stepsDone;
                    order = robots.clone();
                } finally {
                    lock.unlock();
                }
                for (int i = 0; i < robotCount; i++) {
                    if (!isActive(i)) {
                        continue;
                    }
                    try {
                        stepperReading = i;
                        StepRequest request;
                        try {
                            request = k == 0 ? order[i].takeFirst() : order[i].readRequest(k);
                        } finally {
                            stepperReading = -1;
                        }
                        if (request == null) {
                            leave(order[i], i, "its first request could not be read");
                            continue;
                        }
                        processMessage(i, k, request);
                    } catch (IOException e) {
                        order[i].drop();
                        leave(order[i], i, e.getMessage() == null ? e.toString() : e.getMessage());
                    }
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private boolean isActive(int i) {
        lock.lock();
        try {
            return state == State.RUNNING && active[i];
        } finally {
            lock.unlock();
        }
    }

    /** True when robots' requests are read by one stepper thread, not by their workers. */
    boolean sequential() {
        return settings.design() == Design.SEQUENTIAL;
    }

    /** True while robot {@code index} may still send requests: before the start, or while it takes part. */
    boolean accepts(int index) {
        lock.lock();
        try {
            return state == State.WAITING || (state == State.RUNNING && active[index]);
        } finally {
            lock.unlock();
        }
    }

    // ---- the step ------------------------------------------------------------------------------

    /**
     * Hands in robot {@code index}'s request for step k and returns at once, unless it is the last
     * to arrive: then this thread runs the step and delivers every robot's response.
     */
    void processMessage(int index, long k, StepRequest request) throws InterruptedException, ProtocolException {
        lock.lock();
        try {
            if (state == State.WAITING) {
                throw new ProtocolException("sent a request before the simulation started");
            }
            if (state != State.RUNNING || !active[index]) {
                return;
            }
            if (stepsDone != k || stepsReleased != k || requests[index] != null) {
                throw new ProtocolException("sent a request for step " + k + " before its response to step "
                        + (stepsDone - 1));
            }
            requests[index] = request;
            arrived++;
            if (arrived == activeCount && !stepRunning) {
                runStep();
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Under the lock, on the releasing thread: the core's step, then each robot's response with the
     * next step number (or the end), then the poses to every viewer.
     */
    private void runStep() throws InterruptedException {
        long k = stepsDone;
        stepRunning = true;
        try {
            core.step(k, requests);
        } catch (IOException | RuntimeException e) {
            finish("step " + k + " failed: " + e.getMessage(), false);
            return;
        } finally {
            Arrays.fill(requests, null);
            arrived = 0;
            stepRunning = false;
        }
        stepsDone = k + 1;
        if (!pace(stepsDone) || !holdWhilePaused()) {
            return; // ended while paused: the robots have been told
        }
        boolean last = settings.maxSteps() > 0 && stepsDone >= settings.maxSteps();
        SimulationEnd end = last ? new SimulationEnd(k, "completed " + stepsDone + " steps") : null;
        for (int i = 0; i < robotCount; i++) {
            if (!active[i]) {
                continue;
            }
            try {
                robots[i].deliver(core.response(i), stepsDone, end);
            } catch (IOException e) {
                depart(i, "could not send its response: " + e.getMessage());
                robots[i].drop();
            }
        }
        long released = System.nanoTime();
        stepsReleased++;
        if (paused) {
            pauseChanged.signalAll(); // "step N" waits for its last step to go out
        }
        if (released - rateMarkNanos >= 500_000_000L) {
            recentRate = (stepsDone - rateMarkSteps) * 1e9 / (released - rateMarkNanos);
            rateMarkNanos = released;
            rateMarkSteps = stepsDone;
        }
        if (!viewers.isEmpty()) {
            PoseUpdate update = core.viewerUpdate();
            for (ViewerClientWorker v : viewers) {
                v.offer(update);
            }
        }
        // robots are timed from here: a recording viewer that held the step up is not their delay
        stepReleasedNanos = System.nanoTime();
        if (last) {
            robotsTold = true;
            finish(end.reason(), true);
        } else if (activeCount == 0) {
            finish("every robot has left", false);
        }
    }

    /**
     * Under the lock, on the step's thread, after step {@code steps - 1} is computed and before its
     * responses go out: with {@code speed} > 0, holds the step until simulated time runs at most
     * {@code speed} times real time (counted from the start or the last pause), so a person can
     * watch. It waits on a condition, so the lock is free meanwhile (the status, a pause, a stop, a
     * viewer joining go on), exactly as while paused; a pause ends the wait and holds the step. False
     * if the simulation ended meanwhile.
     */
    private boolean pace(long steps) throws InterruptedException {
        if (settings.speed() <= 0) {
            return true;
        }
        long due = paceOriginNanos
                + (long) ((steps - paceOriginStep) * spec.timeStepMs() * 1_000_000L / settings.speed());
        pacing = true;
        try {
            // a pause takes hold at once (the hold follows); the pace counts afresh after it
            long wait = due - System.nanoTime();
            while (wait > 0 && state == State.RUNNING && !(paused && stepBudget == 0)) {
                pauseChanged.awaitNanos(wait);
                wait = due - System.nanoTime();
            }
        } finally {
            pacing = false;
        }
        return state == State.RUNNING;
    }

    /** Under the lock: robot i no longer takes part; it stands where it is. */
    private void depart(int i, String why) {
        active[i] = false;
        activeCount--;
        if (requests[i] != null) {
            requests[i] = null;
            arrived--;
        }
        core.depart(i);
        robotsLeft++;
        departures.add(new Departure(robotNames.get(i), stepsDone, printable(why)));
        LOG.warn("robot {} left at step {} ({}); it is removed from the world and the others go on",
                robotNames.get(i), stepsDone, why);
    }

    boolean isRunning() {
        lock.lock();
        try {
            return state == State.RUNNING;
        } finally {
            lock.unlock();
        }
    }

    /** A robot worker has gone (its connection closed or failed). */
    void leave(RobotClientWorker worker, int index, String why) {
        lock.lock();
        try {
            if (robots[index] != worker) {
                return;
            }
            gone[index] = state != State.WAITING; // before the start its name is simply free again
            if (state == State.WAITING) {
                robots[index] = null;
                properties[index] = null;
                registered--;
                LOG.warn("robot {} left before the start ({}); waiting for it again", robotNames.get(index), why);
            } else if (state == State.RUNNING && active[index]) {
                depart(index, why);
                if (activeCount == 0) {
                    finish("every robot has left", false);
                } else if (arrived == activeCount && !stepRunning) {
                    try {
                        runStep();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }
            }
        } finally {
            lock.unlock();
        }
    }

    void geometryExited(GeometryClientWorker worker, String why) {
        lock.lock();
        try {
            if (geometry == worker && state == State.WAITING) {
                geometry = null;
                LOG.warn("Geometry process left before the start ({}); waiting for another", why);
            } else if (geometry == worker && state == State.ENDED) {
                geometry = null; // told the end and gone; during a run a loss is the step's to notice
            }
        } finally {
            lock.unlock();
        }
    }

    // ---- pause, resume, step N, status (the control port) ---------------------------------------

    /**
     * Under the lock, on the step's thread, after step k is computed and before its responses go out:
     * waits while paused (the robots wait for their responses). False if the simulation ended meanwhile.
     */
    private boolean holdWhilePaused() throws InterruptedException {
        if (paused && stepBudget > 0) {
            stepBudget--;
            if (stepBudget == 0) {
                pauseChanged.signalAll(); // a "step N" waiter: the last of its steps is going out
            }
            return true;
        }
        if (!paused) {
            return true;
        }
        holding = true;
        pauseChanged.signalAll();
        announce(RunState.Phase.PAUSED);
        try {
            while (paused && stepBudget == 0 && state == State.RUNNING) {
                pauseChanged.await();
            }
        } finally {
            holding = false;
            stepReleasedNanos = System.nanoTime(); // robots are not late for the time we held them
            rateMarkNanos = stepReleasedNanos;
            rateMarkSteps = stepsDone;
            paceOriginNanos = stepReleasedNanos; // pace on from here: no rush to catch up the pause
            paceOriginStep = stepsDone;
        }
        if (state != State.RUNNING) {
            return false;
        }
        announce(RunState.Phase.RUNNING);
        if (paused) {
            stepBudget--;
            if (stepBudget == 0) {
                pauseChanged.signalAll();
            }
        }
        return true;
    }

    /**
     * Pauses after the step in progress (or before step 0, if the run has not begun); returns once
     * the Environment holds, or at once when no run is under way.
     */
    public void pause(long timeout, TimeUnit unit) throws InterruptedException {
        long nanos = unit.toNanos(timeout);
        lock.lock();
        try {
            paused = true;
            stepBudget = 0;
            pauseChanged.signalAll(); // a step waiting for its pace holds at once
            while (state == State.RUNNING && !holding && !beginPending && nanos > 0) {
                nanos = pauseChanged.awaitNanos(nanos);
            }
        } finally {
            lock.unlock();
        }
    }

    /** Resumes a paused run (or lets it begin when every client is there). */
    public void resume() {
        lock.lock();
        try {
            paused = false;
            stepBudget = 0;
            if (beginPending && state == State.RUNNING) {
                beginAll();
            }
            pauseChanged.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Runs {@code n} more steps and pauses again; waits until they are done (or the run ends, or the
     * timeout passes). Returns the steps done so far.
     */
    public long step(long n, long timeout, TimeUnit unit) throws InterruptedException {
        long nanos = unit.toNanos(timeout);
        lock.lock();
        try {
            paused = true;
            long target = stepsReleased + n;
            stepBudget += n;
            if (beginPending && state == State.RUNNING) {
                beginAll();
            }
            pauseChanged.signalAll();
            while (state != State.ENDED && paused && stepsReleased < target && nanos > 0) {
                nanos = pauseChanged.awaitNanos(nanos);
            }
            return stepsReleased;
        } finally {
            lock.unlock();
        }
    }

    /** Starts the run paused: nothing moves until {@link #resume} or {@link #step}. Call before {@link #start}. */
    public void startPaused() {
        lock.lock();
        try {
            paused = true;
        } finally {
            lock.unlock();
        }
    }

    /**
     * What the control port reports.
     *
     * @param connected robots whose connection is open and who take part (or wait for the start)
     * @param left robots that were in this simulation and whose connection has closed or who were removed
     * @param geometry {@code in-process} (no Geometry process: {@code --no-geometry}, or going on without
     *     a lost one), {@code attached}, {@code waiting} (for a Geometry process) or {@code none} (ended)
     */
    public record Status(String state, long step, double stepsPerSecond, List<String> robots, List<String> connected,
            List<String> left, String geometry, String reason) {
    }

    public Status status() {
        lock.lock();
        try {
            List<String> connected = new ArrayList<>();
            List<String> left = new ArrayList<>();
            for (int i = 0; i < robotCount; i++) {
                if (robots[i] != null && !gone[i] && (state == State.WAITING || active[i])) {
                    connected.add(robotNames.get(i));
                } else if (robots[i] != null && state != State.WAITING) {
                    left.add(robotNames.get(i));
                }
            }
            String st = switch (state) {
                case WAITING -> "WAITING";
                case ENDED -> "ENDED";
                case RUNNING -> paused && (holding || beginPending || stepBudget == 0) ? "PAUSED" : "RUNNING";
            };
            double rate = "RUNNING".equals(st) ? recentRate : 0;
            return new Status(st, stepsReleased, rate, robotNames, connected, left, geometryStatus(), endReason);
        } finally {
            lock.unlock();
        }
    }

    /** Under the lock: where collision and sonar are resolved now, for {@link #status}. */
    private String geometryStatus() {
        if (settings.inProcessGeometry()) {
            return "in-process";
        }
        if (geometry != null) {
            return "attached";
        }
        if (state == State.ENDED) {
            return "none";
        }
        boolean goingOnWithout = state == State.RUNNING && geometryLosses > 0
                && settings.onGeometryLoss() == GeometryLoss.IN_PROCESS;
        return goingOnWithout ? "in-process" : "waiting";
    }

    // ---- faults: a lost Geometry process, a silent robot --------------------------------------

    /**
     * Under the lock, on the step's thread, when the geometry service failed mid-step: drops a failed
     * Geometry process and returns what to retry the step with, as {@link Settings#onGeometryLoss} says.
     */
    private robosim.environment.core.GeometryService geometryLost(robosim.environment.core.GeometryService failed,
            IOException cause) throws IOException {
        if (!(failed instanceof GeometryClientWorker lost)) {
            throw cause; // in-process geometry failing is a bug: the step fails and says why
        }
        lost.drop();
        if (geometry == lost) {
            geometry = null;
        }
        geometryLosses++;
        geometryChanged.signalAll();
        String why = cause.getMessage() == null ? cause.toString() : cause.getMessage();
        if (settings.onGeometryLoss() == GeometryLoss.IN_PROCESS) {
            LOG.warn("Geometry process lost in step {} ({}); going on with in-process geometry (same results); "
                    + "a new Geometry process may attach", stepsDone, why);
            return new robosim.environment.core.InProcessGeometry(core.map().geometryWorld());
        }
        LOG.warn("Geometry process lost in step {} ({}); the step waits for a new Geometry process", stepsDone, why);
        try {
            while (geometry == null) {
                if (state != State.RUNNING) {
                    throw new IOException("the simulation ended while waiting for a Geometry process");
                }
                geometryChanged.await();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for a Geometry process");
        }
        return geometry;
    }

    /** Starts the timer that enforces the step and Geometry timeouts, if either is set. */
    private void startWatchdog() {
        long step = settings.stepTimeoutMs();
        long geo = settings.inProcessGeometry() ? 0 : settings.geometryTimeoutMs();
        if (step <= 0 && geo <= 0) {
            return;
        }
        long shortest = Math.min(step <= 0 ? Long.MAX_VALUE : step, geo <= 0 ? Long.MAX_VALUE : geo);
        long period = Math.max(5, Math.min(250, shortest / 4));
        // two threads: the robot check may end up running a step (and wait on Geometry), while the
        // Geometry check must still run
        watchdog = java.util.concurrent.Executors.newScheduledThreadPool(2, r -> {
            Thread t = new Thread(r, "watchdog");
            t.setDaemon(true);
            return t;
        });
        watchdog.scheduleWithFixedDelay(this::enforceGeometryTimeout, period, period, TimeUnit.MILLISECONDS);
        watchdog.scheduleWithFixedDelay(this::enforceStepTimeout, period, period, TimeUnit.MILLISECONDS);
    }

    /** On a watchdog thread, without the lock: drops a Geometry process that has taken too long over a step. */
    private void enforceGeometryTimeout() {
        GeometryClientWorker g = geometry;
        long geo = settings.geometryTimeoutMs();
        if (g != null && geo > 0 && g.busyFor(System.nanoTime()) > TimeUnit.MILLISECONDS.toNanos(geo)) {
            LOG.warn("Geometry process has not answered step {} within {} ms; dropping it", stepsDone, geo);
            g.drop(); // the step's read fails and the loss policy takes over
        }
    }

    /** On a watchdog thread: drops robots that have sent nothing for too long after their step went out. */
    private void enforceStepTimeout() {
        try {
            long step = settings.stepTimeoutMs();
            if (step <= 0 || !lock.tryLock()) {
                return; // a step is running: robots are not late while the Environment works
            }
            try {
                long now = System.nanoTime();
                // threads waiting for the lock may be robots' requests that arrived in time
                if (state != State.RUNNING || stepRunning || holding || pacing || beginPending
                        || lock.hasQueuedThreads()
                        || now - stepReleasedNanos <= TimeUnit.MILLISECONDS.toNanos(step)) {
                    return;
                }
                for (int i = 0; i < robotCount; i++) {
                    if (active[i] && requests[i] == null && (!sequential() || stepperReading == i)) {
                        RobotClientWorker late = robots[i];
                        depart(i, "sent no request for step " + stepsDone + " within " + step + " ms (step timeout)");
                        late.drop();
                    }
                }
                if (activeCount == 0) {
                    finish("every robot has left", false);
                } else if (arrived == activeCount && !stepRunning && arrived > 0) {
                    runStep();
                }
            } finally {
                lock.unlock();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            LOG.error("watchdog failed", e);
        }
    }

    // ---- viewers -------------------------------------------------------------------------------

    /** Registers a viewer and returns the snapshot it starts from; updates follow without a gap. */
    WorldSnapshot addViewer(ViewerClientWorker viewer) {
        lock.lock();
        try {
            WorldSnapshot snapshot;
            if (core != null) {
                snapshot = core.map().snapshot(stepsDone - 1);
            } else {
                List<RobotProperties> props = new ArrayList<>();
                double[] x = new double[robotCount];
                double[] y = new double[robotCount];
                double[] h = new double[robotCount];
                for (int i = 0; i < robotCount; i++) {
                    WorldSpec.RobotSpec r = spec.robots().get(i);
                    props.add(properties[i] != null ? properties[i] : expected(r));
                    x[i] = r.xMm();
                    y[i] = r.yMm();
                    h[i] = r.headingDeg();
                }
                snapshot = EnvironmentMap.snapshot(spec, props, new PoseUpdate(-1, x, y, h));
            }
            viewers.add(viewer);
            if (state == State.ENDED) {
                viewer.end(endMessage());
            } else {
                viewer.state(new RunState(stepsReleased, state == State.WAITING ? RunState.Phase.WAITING
                        : holding || beginPending ? RunState.Phase.PAUSED : RunState.Phase.RUNNING));
            }
            LOG.info("{} connected ({} viewer(s))", viewer.name(), viewers.size());
            return snapshot;
        } finally {
            lock.unlock();
        }
    }

    /** What a robot not yet connected looks like: its model, or a disc of the file's radius. */
    private static RobotProperties expected(WorldSpec.RobotSpec r) {
        RobotProperties model = RobotModels.byName(r.type());
        return model != null ? model : new RobotProperties(r.type(), r.radiusMm(), 1, 1, List.of());
    }

    /** Under the lock: tells every viewer the run now runs or is held (pause, resume, start). */
    private void announce(RunState.Phase phase) {
        RunState s = new RunState(stepsReleased, phase);
        for (ViewerClientWorker v : viewers) {
            v.state(s);
        }
    }

    void removeViewer(ViewerClientWorker viewer, String why) {
        if (viewers.remove(viewer)) {
            LOG.info("{} disconnected: {}", viewer.name(), why);
        }
    }

    // ---- the end -------------------------------------------------------------------------------

    /**
     * Ends the simulation (idempotent): robots, viewers and Geometry are told why. If a step holds
     * the lock for more than {@link #STOP_GRACE_MS} (Geometry hung, a recording viewer stopped reading),
     * their connections are closed first so the step fails and lets go.
     */
    public void stop(String reason) {
        boolean locked;
        try {
            locked = lock.tryLock(STOP_GRACE_MS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            locked = false;
        }
        if (!locked) {
            LOG.warn("the step in progress is stuck; closing the Geometry and viewer connections to stop");
            GeometryClientWorker g = geometry;
            if (g != null) {
                g.drop();
            }
            GeometryClientWorker a = attaching;
            if (a != null) {
                a.drop();
            }
            for (ViewerClientWorker v : viewers) {
                v.drop();
            }
            for (RobotClientWorker r : robots) {
                if (r != null) {
                    r.drop(); // a write to a robot that stopped reading holds the step too
                }
            }
            lock.lock();
        }
        try {
            finish(reason, false);
        } finally {
            lock.unlock();
        }
    }

    private static final long STOP_GRACE_MS = 2000;

    /**
     * After the end: waits up to {@code timeoutMs} for viewer workers to send what they hold (a
     * recording viewer may still be writing its backlog), so a process that exits next loses nothing.
     */
    public void awaitViewersDone(long timeoutMs) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        for (ViewerClientWorker v : List.copyOf(viewers)) {
            if (!v.awaitDone(Math.max(0, deadline - System.nanoTime()))) {
                LOG.warn("{} did not take the end of the simulation within {} ms", v.name(), timeoutMs);
            }
        }
    }

    private void finish(String reason, boolean asPlanned) {
        if (state == State.ENDED) {
            return;
        }
        boolean started = state == State.RUNNING;
        state = State.ENDED;
        endReason = reason;
        completed = asPlanned;
        endNanos = System.nanoTime();
        SimulationEnd end = endMessage();
        if (!robotsTold) {
            robotsTold = true;
            for (int i = 0; i < robotCount; i++) {
                if (robots[i] != null && (!started || active[i])) {
                    robots[i].end(end, begun[i]);
                }
            }
        }
        for (ViewerClientWorker v : viewers) {
            v.end(end);
        }
        if (geometry != null) {
            geometry.sendEnd(end);
        }
        closeServers();
        geometryChanged.signalAll();
        pauseChanged.signalAll();
        if (watchdog != null) {
            watchdog.shutdownNow();
        }
        LOG.info("simulation over after {} steps: {}", stepsDone, reason);
        endedLatch.countDown();
        startedLatch.countDown();
    }

    SimulationEnd endMessage() {
        lock.lock();
        try {
            return new SimulationEnd(stepsDone - 1, endReason);
        } finally {
            lock.unlock();
        }
    }

    /**
     * Waits until at least {@code losses} Geometry processes have been lost and {@code attaches} new
     * ones attached during the run; false on timeout.
     */
    public boolean awaitGeometry(int losses, int attaches, long timeout, TimeUnit unit) throws InterruptedException {
        long nanos = unit.toNanos(timeout);
        lock.lock();
        try {
            while (geometryLosses < losses || geometryAttaches < attaches) {
                if (nanos <= 0) {
                    return false;
                }
                nanos = geometryChanged.awaitNanos(nanos);
            }
            return true;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Waits until every client is there and the run has begun; true if it began (false when it ended
     * first, or on timeout).
     */
    public boolean awaitStart(long timeout, TimeUnit unit) throws InterruptedException {
        return startedLatch.await(timeout, unit) && startNanos != 0;
    }

    /** {@code text} with every control character (a line break from the network) shown as '?'. */
    private static String printable(String text) {
        return text == null ? "" : text.codePoints().map(c -> Character.isISOControl(c) ? '?' : c)
                .collect(StringBuilder::new, StringBuilder::appendCodePoint, StringBuilder::append).toString();
    }

    /** Blocks until the simulation is over. */
    public void awaitEnd() throws InterruptedException {
        endedLatch.await();
    }

    public boolean awaitEnd(long timeout, TimeUnit unit) throws InterruptedException {
        return endedLatch.await(timeout, unit);
    }

    public Summary summary() {
        lock.lock();
        try {
            double wall = startNanos == 0 ? 0 : ((endNanos == 0 ? System.nanoTime() : endNanos) - startNanos) / 1e9;
            return new Summary(stepsDone, robotCount, wall, endReason, completed,
                    core == null ? 0 : core.messagesDelivered(), core == null ? 0 : core.messagesOutOfRange(),
                    core == null ? 0 : core.messagesUndeliverable(), robotsLeft, geometryLosses, geometryAttaches,
                    List.copyOf(departures));
        } finally {
            lock.unlock();
        }
    }

    /** The most updates any connected live viewer has ever had waiting (bounded: 1). */
    public int maxLiveViewerBacklog() {
        int max = 0;
        for (ViewerClientWorker v : viewers) {
            if (!v.recording()) {
                max = Math.max(max, v.maxPending());
            }
        }
        return max;
    }

    /** Viewers connected now. */
    public int viewerCount() {
        return viewers.size();
    }

    private void closeServers() {
        for (ServerSocket s : servers) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
    }

    @Override
    public void close() {
        stop("the Environment was shut down");
        closeServers();
        for (ViewerClientWorker v : viewers) {
            v.drop();
        }
    }
}
