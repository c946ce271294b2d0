package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.EnumSource;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.GeometryLoss;
import robosim.environment.run.CoordinatorDesign;
import robosim.environment.run.RunSummary;
import robosim.environment.run.Settings;
import robosim.examples.BackAndForth;
import robosim.geometry.GeometryClient;
import robosim.devices.ArRobot;
import robosim.hardware.HardwareSimulator;
import robosim.devices.Scout;
import robosim.protocol.GeometryHello;
import robosim.protocol.ObjectConnection;
import robosim.protocol.PoseUpdate;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * The faults of the reliability work, each over real sockets: robots that leave or fall silent
 * mid-run, a Geometry process that dies, viewers that leave, and garbage, truncated frames, wrong
 * versions and silence on every port. After each, the simulation goes on.
 */
class FaultsTest {
    private static final long LONG = 60;
    /**
     * The step timeout where a test needs one: long enough that a robot which answers is never late
     * on a loaded machine, short enough for the suite.
     */
    private static final long STEP_TIMEOUT_MS = 2000;

    private static WorldSpec three() throws Exception {
        return new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml"));
    }

    private static ClientWorkerCoordinator start(Settings settings) throws Exception {
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(three(), settings);
        env.start();
        return env;
    }

    private static Settings settings(boolean inProcessGeometry, long steps) {
        return builder(inProcessGeometry, steps).build();
    }

    private static Settings.Builder builder(boolean inProcessGeometry, long steps) {
        return Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(inProcessGeometry)
                .maxSteps(steps).resetEvery(64).handshakeTimeoutMs(10_000);
    }

    private static CompletableFuture<String> robot(String name, robosim.devices.RobotType type, int port) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                HardwareSimulator sim = new HardwareSimulator(name, type);
                sim.connect(new Socket(InetAddress.getLoopbackAddress(), port), 64);
                return sim.run(new BackAndForth());
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    /** A robot client by hand: hello, welcome, then {@code steps} steps standing still. */
    private static ObjectConnection rawRobot(String name, int port, int steps) throws IOException {
        ObjectConnection c = new ObjectConnection(new Socket(InetAddress.getLoopbackAddress(), port), 64);
        c.write(new RobotHello(name, robosim.devices.RobotTypes.properties("ArRobot")));
        c.flush();
        assertTrue(c.read(RobotWelcome.class).isAccepted());
        for (int k = 0; k < steps; k++) {
            assertEquals(k, c.readStep());
            c.write(new StepRequest(k, 0, 0, false, List.of()));
            c.flush();
            assertEquals(k, c.read(StepResponse.class).step());
        }
        return c;
    }

    /**
     * A recording viewer that keeps every update in {@code seen}, returned once the Environment has taken it in (its
     * snapshot came), so it sees every step of a run that starts after; its end is waited for with awaitEnd.
     */
    private static ViewerClient record(int viewerPort, List<PoseUpdate> seen) throws Exception {
        ViewerClient v = ViewerClient.connect("127.0.0.1", viewerPort, true, 10_000);
        java.util.concurrent.CountDownLatch joined = new java.util.concurrent.CountDownLatch(1);
        v.start(new ViewerClient.Listener() {
            @Override
            public void snapshot(WorldSnapshot snapshot) {
                joined.countDown();
            }

            @Override
            public void update(PoseUpdate update) {
                seen.add(update);
            }
        });
        assertTrue(joined.await(LONG, TimeUnit.SECONDS), "the recording viewer got no snapshot");
        return v;
    }

    @ParameterizedTest
    @EnumSource(CoordinatorDesign.class)
    void aRobotThatDisconnectsMidRunIsRemovedViewersAreToldAndTheOthersGoOn(CoordinatorDesign design)
            throws Exception {
        try (ClientWorkerCoordinator env = start(builder(true, 100).design(design).build())) {
            int[] ports = env.ports();
            List<PoseUpdate> seen = new CopyOnWriteArrayList<>();
            ViewerClient viewer = record(ports[1], seen);
            CompletableFuture<ObjectConnection> r1 = CompletableFuture.supplyAsync(() -> {
                try {
                    return rawRobot("r1", ports[0], 20);
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            CompletableFuture<String> r2 = robot("r2", new ArRobot(), ports[0]);
            CompletableFuture<String> r3 = robot("r3", new Scout(), ports[0]);
            r1.get(LONG, TimeUnit.SECONDS).close(); // gone after 20 steps, mid-run
            assertEquals("completed 100 steps", r2.get(LONG, TimeUnit.SECONDS));
            assertEquals("completed 100 steps", r3.get(LONG, TimeUnit.SECONDS));
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            RunSummary s = env.summary();
            assertTrue(s.completed(), s.reason());
            assertEquals(1, s.robotsRemoved());
            viewer.awaitEnd(LONG, TimeUnit.SECONDS); // every update sent has been taken by the listener
            PoseUpdate last = seen.get(seen.size() - 1);
            assertEquals(99, last.step());
            assertEquals(List.of("r1"), last.departed(), "viewers are told who left");
            assertEquals(List.of(), seen.get(10).departed(), "r1 was still there at step 10");
        }
    }

    @ParameterizedTest
    @EnumSource(CoordinatorDesign.class)
    @Execution(ExecutionMode.CONCURRENT) // (each waits out a step timeout on its own Environment and free ports)
    void aRobotThatFallsSilentIsDroppedAfterTheStepTimeout(CoordinatorDesign design) throws Exception {
        try (ClientWorkerCoordinator env = start(builder(true, 60).design(design).stepTimeoutMs(STEP_TIMEOUT_MS).build())) {
            int[] ports = env.ports();
            CompletableFuture<ObjectConnection> r1 = CompletableFuture.supplyAsync(() -> {
                try {
                    return rawRobot("r1", ports[0], 5);
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            CompletableFuture<String> r2 = robot("r2", new ArRobot(), ports[0]);
            CompletableFuture<String> r3 = robot("r3", new Scout(), ports[0]);
            try (ObjectConnection silent = r1.get(LONG, TimeUnit.SECONDS)) {
                // connected, answering nothing from step 5 on
                assertEquals("completed 60 steps", r2.get(LONG, TimeUnit.SECONDS));
                assertEquals("completed 60 steps", r3.get(LONG, TimeUnit.SECONDS));
                assertEquals(1, env.summary().robotsRemoved());
                assertTrue(env.summary().completed());
                assertTrue(closedByPeer(silent), "the silent robot's connection was closed");
            }
        }
    }

    /**
     * Robots sharing one exchange thread (the default for robots in one process): one control code that
     * stops yielding (stuck in a computation of its own) costs only its own robot; the others of the
     * same process keep stepping. Over TLS too, where what has come in but is not decrypted yet counts as
     * input (the exchange sees the Environment go on by it).
     */
    @org.junit.jupiter.params.ParameterizedTest(name = "tls={0}")
    @org.junit.jupiter.params.provider.ValueSource(booleans = {false, true})
    void aStuckControlCodeInASharedProcessCostsOnlyItsOwnRobot(boolean tls, @org.junit.jupiter.api.io.TempDir
            java.nio.file.Path dir) throws Exception {
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .exchange(InJvmSimulation.Exchange.SHARED).keys(tls ? TestKeys.keys(dir, "keys") : null)
                .settings(s -> s.stepTimeoutMs(STEP_TIMEOUT_MS))
                .run(200, true, () -> robot -> {
                    if (robot.name().equals("robot3")) {
                        for (int i = 0; i < 20; i++) {
                            robot.move(250);
                        }
                        new CountDownLatch(1).await(); // never yields again (until the end interrupts it)
                    }
                    new BackAndForth().run(robot);
                });
        assertTrue(sim.summary.completed(), sim.summary.reason());
        assertEquals(200, sim.summary.steps());
        assertEquals(1, sim.summary.robotsRemoved(), "only the stuck robot was dropped");
        assertEquals(List.of("robot3"), sim.updates.get(199).departed());
    }

    /** Reads until the peer closes; true if it did within the timeout (an object or step may come first). */
    private static boolean closedByPeer(ObjectConnection c) {
        try {
            c.setReadTimeoutMs((int) TimeUnit.SECONDS.toMillis(LONG));
            while (true) {
                c.readStep();
            }
        } catch (SocketTimeoutException e) {
            return false;
        } catch (java.io.EOFException | java.net.SocketException e) {
            return true;
        } catch (IOException e) {
            throw new AssertionError("expected the connection to close, got " + e);
        }
    }

    @Test
    void whenGeometryDiesTheRunGoesOnInProcessWithTheSamePosesAndANewGeometryTakesOver() throws Exception {
        // paced at 200x real time, so the run is still going when the new Geometry process attaches
        geometryKilledAtStep50(400, s -> s.speed(200).onGeometryLoss(GeometryLoss.IN_PROCESS),
                (env, ports, events) -> {
                    CompletableFuture<String> second = CompletableFuture.supplyAsync(() -> {
                        try {
                            return new GeometryClient(new Socket(InetAddress.getLoopbackAddress(), ports[2]), 64).run();
                        } catch (IOException e) {
                            throw new IllegalStateException(e);
                        }
                    }, TestThreads.ROBOTS);
                    assertTrue(events.geometryAttached.await(LONG, TimeUnit.SECONDS), "the new Geometry attached");
                    second.get(LONG, TimeUnit.SECONDS);
                });
    }

    @Test
    void withTheWaitSettingTheStepWaitsForANewGeometryProcess() throws Exception {
        geometryKilledAtStep50(300, s -> s.onGeometryLoss(GeometryLoss.WAIT),
                (env, ports, events) -> new GeometryClient(new Socket(InetAddress.getLoopbackAddress(), ports[2]), 64)
                        .run());
    }

    /** What a test does once the Environment has noticed the loss of its Geometry process. */
    private interface AfterLoss {
        void run(ClientWorkerCoordinator env, int[] ports, RunEvents events) throws Exception;
    }

    /**
     * Runs the paper benchmark with Geometry as a client, kills that client after step 50, waits until
     * the Environment has noticed, then does {@code afterLoss}; the run must complete with one loss,
     * one new Geometry attached, and the poses of a run without the fault.
     */
    private static void geometryKilledAtStep50(long steps,
            java.util.function.UnaryOperator<Settings.Builder> settings,
            AfterLoss afterLoss) throws Exception {
        InJvmSimulation reference = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .run(steps, false, Chatter::new);
        CountDownLatch atStep50 = new CountDownLatch(1);
        RunEvents events = new RunEvents();
        InJvmSimulation faulty = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).settings(settings)
                .listen(events)
                .onUpdate((u, port) -> {
                    if (u.step() == 50) {
                        atStep50.countDown();
                    }
                });
        faulty.sideline((env, ports) -> {
            assertTrue(atStep50.await(LONG, TimeUnit.SECONDS));
            faulty.geometryKilled = true;
            faulty.geometrySocket.close();
            assertTrue(events.geometryLost.await(LONG, TimeUnit.SECONDS), "the loss was noticed");
            afterLoss.run(env, ports, events);
        });
        InJvmSimulation sim = faulty.run(steps, false, Chatter::new);
        assertTrue(sim.summary.completed(), sim.summary.reason());
        assertEquals(1, sim.summary.geometryLosses());
        assertEquals(1, sim.summary.geometryAttaches());
        InJvmSimulation.assertSamePoses(reference, sim);
    }

    /** Runs three robots for 100 steps (geometry in-process, or from {@code geometry}); the last poses seen. */
    private static PoseUpdate lastPoses(boolean inProcess, java.util.function.IntFunction<CompletableFuture<?>> geometry,
            int[] losses) throws Exception {
        try (ClientWorkerCoordinator env = start(settings(inProcess, 100))) {
            int[] ports = env.ports();
            List<PoseUpdate> seen = new CopyOnWriteArrayList<>();
            ViewerClient viewer = record(ports[1], seen);
            CompletableFuture<?> g = inProcess ? CompletableFuture.completedFuture(null) : geometry.apply(ports[2]);
            List<CompletableFuture<String>> robots = List.of(robot("r1", new ArRobot(), ports[0]),
                    robot("r2", new ArRobot(), ports[0]), robot("r3", new Scout(), ports[0]));
            for (CompletableFuture<String> r : robots) {
                assertEquals("completed 100 steps", r.get(LONG, TimeUnit.SECONDS));
            }
            g.get(LONG, TimeUnit.SECONDS);
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            viewer.awaitEnd(LONG, TimeUnit.SECONDS);
            losses[0] = env.summary().geometryLosses();
            assertTrue(env.summary().completed(), env.summary().reason());
            return seen.get(seen.size() - 1);
        }
    }

    /** What a lying Geometry process answers at step 50. */
    enum Forgery { ROBOT_INDEX_OUT_OF_RANGE, NAN_MOTION, LONGER_THAN_ASKED }

    @ParameterizedTest
    @EnumSource(Forgery.class)
    void aGeometryProcessThatAnswersNonsenseIsLostAndTheStepIsResolvedAgainInProcess(Forgery forgery)
            throws Exception {
        int[] none = new int[1];
        PoseUpdate reference = lastPoses(true, null, none);
        int[] losses = new int[1];
        PoseUpdate faulty = lastPoses(false, port -> CompletableFuture.runAsync(() -> {
            // a Geometry process that answers truly until step 50, then lies
            try (ObjectConnection g = new ObjectConnection(new Socket(InetAddress.getLoopbackAddress(), port), 64)) {
                g.write(new GeometryHello());
                g.flush();
                robosim.environment.core.InProcessGeometry engine = new robosim.environment.core.InProcessGeometry(
                        g.read(robosim.protocol.GeometryWorld.class));
                while (true) {
                    robosim.protocol.GeometryStepRequest q = g.read(robosim.protocol.GeometryStepRequest.class);
                    robosim.protocol.GeometryStepResponse a = engine.resolve(q);
                    if (q.step() == 50) {
                        switch (forgery) {
                            case ROBOT_INDEX_OUT_OF_RANGE ->
                                a.setMotion(0, 0, 0, robosim.protocol.GeometryStepResponse.CONTACT_ROBOT, 99_999);
                            case NAN_MOTION -> a.setMotion(0, Double.NaN, 0, a.contactKind(0), a.contactIndex(0));
                            case LONGER_THAN_ASKED -> a.setMotion(0, 1e9, 0, a.contactKind(0), a.contactIndex(0));
                        }
                    }
                    g.write(a);
                    g.flush();
                }
            } catch (IOException e) {
                // dropped by the Environment after its bad answer: expected
            }
        }, TestThreads.ROBOTS), losses);
        assertEquals(1, losses[0], "the lying Geometry process was lost once");
        assertEquals(reference.step(), faulty.step());
        for (int i = 0; i < reference.count(); i++) {
            assertEquals(reference.xMm(i), faulty.xMm(i), 0, "the same poses, bit for bit");
            assertEquals(reference.yMm(i), faulty.yMm(i), 0);
            assertEquals(reference.headingDeg(i), faulty.headingDeg(i), 0);
        }
    }

    @Test
    void aViewerThatDisconnectsMidRunChangesNothing() throws Exception {
        InJvmSimulation reference = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .run(300, true, Chatter::new);
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .sideline((env, ports) -> {
                    CountDownLatch some = new CountDownLatch(20);
                    ViewerClient v = ViewerClient.connect("127.0.0.1", ports[1], false, 10_000);
                    v.start(new ViewerClient.Listener() {
                        @Override
                        public void snapshot(WorldSnapshot snapshot) {
                        }

                        @Override
                        public void update(PoseUpdate update) {
                            some.countDown();
                        }
                    });
                    some.await(LONG, TimeUnit.SECONDS);
                    v.close();
                })
                .run(300, true, Chatter::new);
        assertTrue(sim.summary.completed(), sim.summary.reason());
        InJvmSimulation.assertSamePoses(reference, sim);
    }

    // ---- bad input on every port ---------------------------------------------------------------

    /** What a bad client sends. */
    enum Bad { GARBAGE, TRUNCATED, WRONG_VERSION, NOTHING, GADGET, HUGE_ARRAY, DEEP }

    @ParameterizedTest(name = "{1} on the {0} port")
    @CsvSource({
        "robot, GARBAGE", "robot, TRUNCATED", "robot, WRONG_VERSION", "robot, NOTHING",
        "viewer, GARBAGE", "viewer, TRUNCATED", "viewer, WRONG_VERSION", "viewer, NOTHING",
        "geometry, GARBAGE", "geometry, TRUNCATED", "geometry, WRONG_VERSION", "geometry, NOTHING",
        "robot, GADGET", "robot, HUGE_ARRAY", "robot, DEEP",
        "viewer, GADGET", "viewer, HUGE_ARRAY", "viewer, DEEP",
        "geometry, GADGET", "geometry, HUGE_ARRAY", "geometry, DEEP",
    })
    // side by side (4 at a time, junit-platform.properties): each case has its own Environment on free ports and
    // its clients on threads of their own (TestThreads), and the NOTHING cases wait out the 5 s handshake deadline
    @Execution(ExecutionMode.CONCURRENT)
    void badInputIsRefusedAndTheSimulationRunsOn(String port, Bad bad) throws Exception {
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(false).maxSteps(30)
                .resetEvery(64).handshakeTimeoutMs(5000).build();
        try (ClientWorkerCoordinator env = start(s)) {
            int[] ports = env.ports();
            int p = switch (port) {
                case "robot" -> ports[0];
                case "viewer" -> ports[1];
                default -> ports[2];
            };
            try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), p)) {
                socket.setSoTimeout((int) TimeUnit.SECONDS.toMillis(LONG));
                byte[] reply = switch (bad) {
                    case GARBAGE -> send(socket, "GET / HTTP/1.1\r\nHost: robosim\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
                    case TRUNCATED -> {
                        byte[] hello = helloBytes(port, Protocol.VERSION);
                        yield send(socket, java.util.Arrays.copyOf(hello, hello.length - 3));
                    }
                    case WRONG_VERSION -> send(socket, helloBytes(port, Protocol.VERSION + 7));
                    case NOTHING -> readToEnd(socket.getInputStream());
                    // the shape of the URLDNS gadget chain: a HashMap keyed by a URL, outside the allow-list
                    case GADGET -> send(socket, objectBytes(new java.util.HashMap<>(
                            java.util.Map.of(new java.net.URL("http://gadget.invalid/"), "x"))));
                    case HUGE_ARRAY -> send(socket, objectBytes(new byte[1 << 17]));
                    case DEEP -> send(socket, objectBytes(new Object[] {new Object[] {new Object[] {new Object[] {}}}}));
                };
                if (bad == Bad.WRONG_VERSION) {
                    String text = new String(reply, StandardCharsets.ISO_8859_1);
                    assertTrue(text.contains("protocol version " + (Protocol.VERSION + 7) + " is not supported"),
                            "the refusal names the version: " + text);
                }
            }
            // the Environment is still there: a whole run goes through
            CompletableFuture<String> geometry = CompletableFuture.supplyAsync(() -> {
                try {
                    return new GeometryClient(new Socket(InetAddress.getLoopbackAddress(), ports[2]), 64).run();
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            List<CompletableFuture<String>> robots = new ArrayList<>(List.of(robot("r1", new ArRobot(), ports[0]),
                    robot("r2", new ArRobot(), ports[0]), robot("r3", new Scout(), ports[0])));
            for (CompletableFuture<String> r : robots) {
                assertEquals("completed 30 steps", r.get(LONG, TimeUnit.SECONDS));
            }
            geometry.get(LONG, TimeUnit.SECONDS);
            assertTrue(env.summary().completed());
        }
    }

    /** The hello of the client for {@code port}, as its stream would carry it, with the given version. */
    private static byte[] helloBytes(String port, int version) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeUnshared(switch (port) {
                case "robot" -> new RobotHello("r1", robosim.devices.RobotTypes.properties("ArRobot"));
                case "viewer" -> new ViewerHello(true);
                default -> new GeometryHello();
            });
        }
        byte[] data = bytes.toByteArray();
        if (version != Protocol.VERSION) {
            // the version is the first int of the hello's data: block data (TC_BLOCKDATA, length) 00 00 00 VERSION
            int at = -1;
            // (TC_BLOCKDATA has a 1-byte length, TC_BLOCKDATALONG a 4-byte one)
            for (int i = 0; i + 6 <= data.length && at < 0; i++) {
                int start = data[i] == 0x77 ? i + 2 : data[i] == 0x7A ? i + 5 : -1;
                if (start > 0 && start + 4 <= data.length && data[start] == 0 && data[start + 1] == 0 && data[start + 2] == 0
                        && data[start + 3] == Protocol.VERSION) {
                    at = start;
                }
            }
            assertTrue(at > 0, "version found");
            data[at + 3] = (byte) version;
        }
        return data;
    }

    /** One object as a fresh object stream would carry it. */
    private static byte[] objectBytes(Object o) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(o);
        }
        return bytes.toByteArray();
    }

    /**
     * Sends bytes, then reads everything until the Environment closes the connection. The Environment may
     * refuse and close before it has read everything (a reset on our write): that is a close too, and
     * whatever it answered before is still read.
     */
    private static byte[] send(Socket socket, byte[] bytes) throws IOException {
        try {
            socket.getOutputStream().write(bytes);
            socket.getOutputStream().flush();
            socket.shutdownOutput();
        } catch (SocketException closedWhileWriting) {
            // refused before the end of our bytes: read what was said before the close
        }
        return readToEnd(socket.getInputStream());
    }

    /** Everything the peer sends until it closes (a reset counts as closed); fails on timeout. */
    private static byte[] readToEnd(InputStream in) throws IOException {
        ByteArrayOutputStream got = new ByteArrayOutputStream();
        byte[] buffer = new byte[4096];
        try {
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                got.write(buffer, 0, n);
            }
        } catch (SocketTimeoutException e) {
            throw new AssertionError("the Environment never closed the connection");
        } catch (IOException reset) {
            // closed with unread data: a reset is a close too
        }
        return got.toByteArray();
    }

}
