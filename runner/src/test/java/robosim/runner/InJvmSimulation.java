package robosim.runner;

import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import robosim.api.RobotControl;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.CoordinatorDesign;
import robosim.environment.run.RunSummary;
import robosim.environment.run.RunListener;
import robosim.environment.run.Settings;
import robosim.geometry.GeometryClient;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.ObjectConnection;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationKeys;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * A whole simulation inside the test JVM but over real loopback sockets on ephemeral ports: the
 * Environment, a Geometry client (unless in-process), one Hardware Simulator thread per robot and a
 * recording viewer that keeps every step's poses (and watches the first robot: its views too).
 */
final class InJvmSimulation {
    final WorldSpec spec;
    final List<RobotControl> controls = new ArrayList<>();
    final List<PoseUpdate> updates = new ArrayList<>();
    /** What the recording viewer got besides the updates: the snapshot, the run states, the end. */
    volatile WorldSnapshot snapshot;
    final List<robosim.protocol.RunState> states = new java.util.concurrent.CopyOnWriteArrayList<>();
    robosim.protocol.SimulationEnd end;
    final List<robosim.protocol.RobotView> views = new java.util.concurrent.CopyOnWriteArrayList<>();
    /** The last update each extra live viewer saw. */
    final List<PoseUpdate> liveLast = new ArrayList<>();
    RunSummary summary;
    /** The run's built-in metrics at its end, as the run counted them live. */
    java.util.Map<String, Double> metrics;
    int viewersAtEnd;
    private int liveViewers;
    private int frozenViewers;
    /** Called on the recording viewer's thread with each update, and the viewer port. */
    private java.util.function.BiConsumer<PoseUpdate, Integer> onUpdate = (u, port) -> { };

    /** The coordinator design; null: the Environment's default. */
    private CoordinatorDesign design;
    private final List<RunListener> listeners = new ArrayList<>();

    /** Adds a listener to the Environment of the next run. */
    InJvmSimulation listen(RunListener listener) {
        listeners.add(listener);
        return this;
    }

    InJvmSimulation design(CoordinatorDesign d) {
        this.design = d;
        return this;
    }

    /** The robots' exchange threading; SHARED runs every robot's exchange on one thread. */
    enum Exchange { ONE_THREAD, SEND_RECEIVE, SHARED, ONE_CONNECTION }
    private Exchange exchange = Exchange.ONE_THREAD;
    private boolean stepMessages = true;
    private int resetEvery = ObjectConnection.DEFAULT_RESET_EVERY;

    InJvmSimulation exchange(Exchange e) {
        this.exchange = e;
        return this;
    }

    /** The simulation's keys, for the Environment and every client (null: none, the default). */
    private SimulationKeys keys;
    InJvmSimulation keys(SimulationKeys k) {
        this.keys = k;
        return this;
    }

    /** Messages between object-stream resets, on every connection of the run (default: the protocol's). */
    InJvmSimulation resetEvery(int messages) {
        this.resetEvery = messages;
        return this;
    }

    InJvmSimulation stepMessages(boolean on) {
        this.stepMessages = on;
        return this;
    }

    private java.util.function.UnaryOperator<Settings.Builder> settingsHook = x -> x;
    private Sideline sideline;
    /** The Geometry client's socket while it runs (a test may close it to kill Geometry). */
    volatile Socket geometrySocket;
    /** Set by a test that kills Geometry on purpose: that client's failure is then expected. */
    volatile boolean geometryKilled;

    /** Changes the Environment's settings for the next run. */
    InJvmSimulation settings(java.util.function.UnaryOperator<Settings.Builder> hook) {
        this.settingsHook = hook;
        return this;
    }

    /** Something a test does beside the run, on its own thread, once the Environment is listening. */
    interface Sideline {
        void run(ClientWorkerCoordinator env, int[] ports) throws Exception;
    }

    InJvmSimulation sideline(Sideline action) {
        this.sideline = action;
        return this;
    }

    InJvmSimulation onUpdate(java.util.function.BiConsumer<PoseUpdate, Integer> hook) {
        this.onUpdate = hook;
        return this;
    }

    /** Adds live viewers (reading every update) and frozen ones (never reading) to the next run. */
    InJvmSimulation withViewers(int live, int frozen) {
        this.liveViewers = live;
        this.frozenViewers = frozen;
        return this;
    }

    InJvmSimulation(Path file) throws Exception {
        this.spec = new EnvironmentLoader().load(file);
    }

    InJvmSimulation run(long steps, boolean inProcessGeometry, Supplier<RobotControl> control) throws Exception {
        Settings.Builder settings = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0)
                .inProcessGeometry(inProcessGeometry).maxSteps(steps).resetEvery(resetEvery)
                .handshakeTimeoutMs(10_000).stepMessages(stepMessages);
        if (design != null) {
            settings.design(design);
        }
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec, settingsHook.apply(settings.keys(keys)).build());
        for (RunListener l : listeners) {
            env.listen(l);
        }
        env.start();
        try {
            int[] ports = env.ports();
            ViewerHello hello = new ViewerHello(true, 0, spec.robots().isEmpty() ? "" : spec.robots().get(0).name());
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", ports[1], hello, 10_000, keys);
            java.util.concurrent.CountDownLatch joined = new java.util.concurrent.CountDownLatch(1);
            viewer.start(new ViewerClient.Listener() {
                @Override
                public void robotView(robosim.protocol.RobotView view) {
                    views.add(view);
                }

                @Override
                public void snapshot(WorldSnapshot first) {
                    snapshot = first;
                    joined.countDown();
                }

                @Override
                public void runState(robosim.protocol.RunState state) {
                    states.add(state);
                }

                @Override
                public void update(PoseUpdate update) {
                    updates.add(update);
                    onUpdate.accept(update, ports[1]);
                }
            });
            // (in the world before any robot comes: under load it could join after the run began and miss steps)
            if (!joined.await(60, java.util.concurrent.TimeUnit.SECONDS)) {
                throw new IllegalStateException("the recording viewer got no snapshot within 60 s");
            }
            List<ViewerClient> lives = new ArrayList<>();
            PoseUpdate[] lastSeen = new PoseUpdate[liveViewers];
            for (int v = 0; v < liveViewers; v++) {
                int slot = v;
                ViewerClient live = ViewerClient.connect("127.0.0.1", ports[1], new ViewerHello(false), 10_000, keys);
                live.start(new ViewerClient.Listener() {
                    @Override
                    public void snapshot(WorldSnapshot snapshot) {
                    }

                    @Override
                    public void update(PoseUpdate update) {
                        lastSeen[slot] = update;
                    }
                });
                lives.add(live);
            }
            List<Socket> frozen = new ArrayList<>();
            for (int v = 0; v < frozenViewers; v++) {
                frozen.add(ExtraViewers.frozen(ports[1]));
            }
            List<Thread> threads = new ArrayList<>();
            List<Throwable> failures = new ArrayList<>();
            if (!inProcessGeometry) {
                threads.add(thread("geometry", failures, () -> {
                    Socket g = new Socket(InetAddress.getLoopbackAddress(), ports[2]);
                    geometrySocket = g;
                    try {
                        return new GeometryClient(g, resetEvery, keys).run();
                    } catch (java.io.IOException e) {
                        if (geometryKilled) {
                            return null;
                        }
                        throw e;
                    }
                }));
            }
            if (sideline != null) {
                threads.add(thread("sideline", failures, () -> {
                    sideline.run(env, ports);
                    return null;
                }));
            }
            for (WorldSpec.RobotSpec r : spec.robots()) {
                controls.add(control.get());
            }
            if (exchange == Exchange.ONE_CONNECTION) {
                threads.add(thread("one-connection", failures, () -> {
                    robosim.hardware.ManyRobots.runOverOneConnection(spec.robots().stream().map(r ->
                            new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()))).toList(), controls,
                            new Socket(InetAddress.getLoopbackAddress(), ports[0]), resetEvery,
                            keys);
                    return null;
                }));
            } else if (exchange == Exchange.SHARED) {
                threads.add(thread("shared-exchange", failures, () -> {
                    List<HardwareSimulator> sims = new ArrayList<>();
                    for (WorldSpec.RobotSpec r : spec.robots()) {
                        HardwareSimulator sim = new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()));
                        sim.connect(new Socket(InetAddress.getLoopbackAddress(), ports[0]),
                                resetEvery, keys);
                        sims.add(sim);
                    }
                    robosim.hardware.ManyRobots.runShared(sims, controls);
                    return null;
                }));
            } else {
                HardwareSimulator.Exchange each = exchange == Exchange.SEND_RECEIVE
                        ? HardwareSimulator.Exchange.SEND_RECEIVE : HardwareSimulator.Exchange.ONE_THREAD;
                for (int i = 0; i < spec.robots().size(); i++) {
                    WorldSpec.RobotSpec r = spec.robots().get(i);
                    RobotControl c = controls.get(i);
                    threads.add(thread(r.name(), failures, () -> {
                        HardwareSimulator sim = new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()));
                        sim.connect(new Socket(InetAddress.getLoopbackAddress(), ports[0]),
                                resetEvery, keys);
                        return sim.run(c, each);
                    }));
                }
            }
            if (!env.awaitEnd(5, TimeUnit.MINUTES)) {
                throw new AssertionError("the simulation did not end");
            }
            end = viewer.awaitEnd(1, TimeUnit.MINUTES);
            for (ViewerClient live : lives) {
                live.awaitEnd(1, TimeUnit.MINUTES);
            }
            liveLast.addAll(java.util.Arrays.asList(lastSeen));
            // the viewers that took the end leave on their own; wait for their workers (the frozen one never
            // finishes, so this returns after the timeout at the latest)
            env.awaitOutputDone(frozenViewers > 0 ? 3000 : 30_000);
            viewersAtEnd = env.status().viewers();
            for (Socket f : frozen) {
                f.close();
            }
            for (Thread t : threads) {
                t.join(TimeUnit.MINUTES.toMillis(1));
            }
            if (!failures.isEmpty()) {
                throw new AssertionError("a client failed", failures.get(0));
            }
            summary = env.summary();
            metrics = env.metrics();
            return this;
        } finally {
            env.close();
        }
    }

    private interface Body {
        Object run() throws Exception;
    }

    private static Thread thread(String name, List<Throwable> failures, Body body) {
        Thread t = new Thread(() -> {
            try {
                body.run();
            } catch (Exception | AssertionError e) {
                synchronized (failures) {
                    failures.add(e);
                }
            }
        }, "test-" + name);
        t.start();
        return t;
    }

    /** Every robot's pose at every step of {@code actual} equals {@code expected}'s, bit for bit. */
    static void assertSamePoses(InJvmSimulation expected, InJvmSimulation actual) {
        org.junit.jupiter.api.Assertions.assertEquals(expected.updates.size(), actual.updates.size(), "steps seen");
        for (int k = 0; k < expected.updates.size(); k++) {
            PoseUpdate a = expected.updates.get(k);
            PoseUpdate b = actual.updates.get(k);
            for (int i = 0; i < a.count(); i++) {
                org.junit.jupiter.api.Assertions.assertArrayEquals(new double[] {a.xMm(i), a.yMm(i), a.headingDeg(i)},
                        new double[] {b.xMm(i), b.yMm(i), b.headingDeg(i)}, "step " + k + " robot " + i);
            }
        }
    }

    static Path env(String name) {
        return Path.of("..", "test-envs", name);
    }

}
