package robosim.runner;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import robosim.protocol.CommandLines;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * The soak: N {@code RingChatter} robots (in several robot processes), an Environment and a Geometry
 * process, run for many steps while faults are injected at random steps drawn from a seeded
 * generator: a robot process killed, robots that fall silent, the Geometry process killed and a new
 * one started, viewers that come and go or never read, garbage on every port. Afterwards it checks
 * that every step ran, that every message between robots that were both still there arrived exactly
 * once and in order, that the faults were seen as faults, and that the Environment's heap after a
 * full GC near the end is within 10% of its heap near the start. Prints a report; exit 0 if all hold.
 */
@Command(name = "soak.sh", mixinStandardHelpOptions = true,
        description = "Runs a long simulation with faults injected at random (seeded) and checks what survived.")
public final class Soak implements Callable<Integer> {
    /**
     * The soak's own clients and fault injectors, each on a thread of its own ({@code soak-client-n}, daemon):
     * they block in socket reads and waits, which must never hold the JVM's common pool (on JDK 21+ it runs
     * {@code runAsync} tasks even at parallelism 1, so a second blocking task would never start).
     */
    private final ExecutorService clients = Executors.newCachedThreadPool(new ThreadFactory() {
        private final AtomicInteger serial = new AtomicInteger();

        @Override
        public Thread newThread(Runnable r) {
            Thread t = new Thread(r, "soak-client-" + serial.incrementAndGet());
            t.setDaemon(true);
            return t;
        }
    });

    @Option(names = "--robots", defaultValue = "100", description = "Ring robots (default: ${DEFAULT-VALUE}).")
    int robots;

    @Option(names = "--steps", defaultValue = "100000", description = "Steps (default: ${DEFAULT-VALUE}).")
    long steps;

    @Option(names = "--seed", defaultValue = "1", description = "Seed of the fault schedule (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--robot-processes", defaultValue = "5",
            description = "Robot processes the ring robots are spread over (default: ${DEFAULT-VALUE}).")
    int robotProcesses;

    @Option(names = "--silent-robots", defaultValue = "3",
            description = "Extra robots that fall silent at random steps (default: ${DEFAULT-VALUE}).")
    int silentRobots;

    @picocli.CommandLine.Mixin
    robosim.environment.GeometryLossOption geometryLoss; // (WAIT: even a short soak sees the new one attach)

    @Option(names = "--step-timeout-ms", defaultValue = "2000",
            description = "The Environment's step timeout (default: ${DEFAULT-VALUE}).")
    long stepTimeoutMs;

    private final AtomicLong step = new AtomicLong(-1);
    private final Object stepChanged = new Object();
    private final Map<String, String> ringLines = new ConcurrentHashMap<>();
    private final List<String> faults = java.util.Collections.synchronizedList(new ArrayList<>());
    /** The Environment's control port, once it listens (the heap is read while the run is paused). */
    private volatile int controlPort;

    @Override
    public Integer call() throws Exception {
        if (robots < 3 || steps < 1000 || robotProcesses < 2 || robotProcesses > robots || silentRobots < 0) {
            System.err.println("soak: need --robots >= 3, --steps >= 1000, 2 <= --robot-processes <= --robots");
            return 2;
        }
        Path dir = Files.createTempDirectory("robosim-soak");
        Path env = writeEnvironment(dir.resolve("soak.xml"));
        Random random = new Random(seed);
        try (ChildProcesses children = new ChildProcesses(List.of())) {
            CompletableFuture<Map<String, String>> listening = new CompletableFuture<>();
            CompletableFuture<String> summary = new CompletableFuture<>();
            Process environment = children.start("environment", List.of("-XX:+UseSerialGC"),
                    "robosim.environment.EnvironmentMain", List.of(env.toString(), "--steps", Long.toString(steps),
                            "--robot-port", "0", "--viewer-port", "0", "--geometry-port", "0",
                            "--step-timeout-ms", Long.toString(stepTimeoutMs), "--control-port", "0",
                            "--on-geometry-loss", geometryLoss.policy().name()), line -> {
                        if (line.startsWith("listening ")) {
                            listening.complete(HeadlessRunner.fields(line));
                        } else if (line.startsWith("summary ")) {
                            summary.complete(line);
                        }
                    });
            Map<String, String> ports = listening.get(60, TimeUnit.SECONDS);
            int robotPort = Integer.parseInt(ports.get("robots"));
            int viewerPort = Integer.parseInt(ports.get("viewers"));
            int geometryPort = Integer.parseInt(ports.get("geometry"));
            controlPort = Integer.parseInt(ports.get("control"));
            children.start("geometry", List.of("-XX:+UseSerialGC"), "robosim.geometry.GeometryMain",
                    List.of("127.0.0.1", Integer.toString(geometryPort)), null);
            watch(viewerPort);
            List<Process> robotJvms = new ArrayList<>();
            int per = (robots + robotProcesses - 1) / robotProcesses;
            for (int p = 0; p < robotProcesses; p++) {
                List<String> args = new ArrayList<>(List.of("127.0.0.1", Integer.toString(robotPort)));
                for (int i = p * per; i < Math.min(robots, (p + 1) * per); i++) {
                    args.add("--robot");
                    args.add("ring" + i + ":ArRobot:robosim.examples.RingChatter");
                }
                robotJvms.add(children.start("robots-" + p, List.of("-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1"),
                        "robosim.hardware.MultiRobotMain", args, this::robotLine));
            }
            List<CompletableFuture<Void>> silent = new ArrayList<>();
            for (int v = 0; v < silentRobots; v++) {
                long at = between(random, 0.05, 0.95);
                String name = "silent" + v;
                silent.add(CompletableFuture.runAsync(() -> SoakClients.silentRobot(name, robotPort, at, faults::add),
                        clients));
                faults.add(String.format(Locale.ROOT, "robot %s falls silent at step %d", name, at));
            }
            Socket frozen = SoakClients.frozenViewer(viewerPort);
            faults.add("a viewer that never reads, connected for the whole run");
            int killed = random.nextInt(robotProcesses);
            long killAt = between(random, 0.2, 0.8);
            long geometryAt = between(random, 0.1, 0.9);
            List<long[]> viewerVisits = new ArrayList<>();
            for (int i = 0; i < 5; i++) {
                long from = between(random, 0.0, 0.9);
                viewerVisits.add(new long[] {from, Math.min(steps - 1, from + 1 + random.nextInt((int) (steps / 10)))});
            }
            List<long[]> garbage = new ArrayList<>();
            for (int i = 0; i < 9; i++) {
                garbage.add(new long[] {between(random, 0.0, 0.95), i % 3});
            }
            List<CompletableFuture<Void>> scheduled = new ArrayList<>();
            scheduled.add(at(killAt, () -> {
                robotJvms.get(killed).destroyForcibly();
                faults.add(String.format(Locale.ROOT, "robot process %d (%d robots) killed at step %d", killed,
                        Math.min(robots, (killed + 1) * per) - killed * per, step.get()));
            }));
            scheduled.add(at(geometryAt, () -> {
                children.kill("geometry");
                faults.add("Geometry process killed at step " + step.get() + "; a new one started");
                children.start("geometry-2", List.of("-XX:+UseSerialGC"), "robosim.geometry.GeometryMain",
                        List.of("127.0.0.1", Integer.toString(geometryPort)), null);
            }));
            for (long[] visit : viewerVisits) {
                scheduled.add(at(visit[0], () -> {
                    ViewerClient v = ViewerClient.connect("127.0.0.1", viewerPort, false, 10_000);
                    v.start(new ViewerClient.Listener() {
                        @Override
                        public void snapshot(WorldSnapshot snapshot) {
                        }

                        @Override
                        public void update(PoseUpdate update) {
                        }
                    });
                    awaitStep(visit[1]);
                    v.close();
                    faults.add("a live viewer connected at step " + visit[0] + " and left at step " + step.get());
                }));
            }
            for (long[] g : garbage) {
                int port = g[1] == 0 ? robotPort : g[1] == 1 ? viewerPort : geometryPort;
                scheduled.add(at(g[0], () -> {
                    try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                        OutputStream out = s.getOutputStream();
                        out.write("\u00ac\u00ed\u0000\u0005garbage".getBytes(StandardCharsets.ISO_8859_1));
                        out.flush();
                        s.shutdownOutput();
                        s.setSoTimeout(30_000);
                        while (s.getInputStream().read() >= 0) {
                            // until the Environment closes it
                        }
                    }
                    faults.add("garbage sent to the " + (g[1] == 0 ? "robot" : g[1] == 1 ? "viewer" : "geometry")
                            + " port at step " + step.get());
                }));
            }
            long early = heapAt((long) (steps * 0.1), environment.pid());
            long late = heapAt((long) (steps * 0.95), environment.pid());
            if (!environment.waitFor(6, TimeUnit.HOURS)) {
                System.out.println("FAIL the Environment did not end");
                return 1;
            }
            String sum = summary.get(30, TimeUnit.SECONDS);
            for (CompletableFuture<Void> f : scheduled) {
                f.get(60, TimeUnit.SECONDS);
            }
            frozen.close();
            children.awaitAll(60);
            return new SoakReport(robots, robotProcesses, silentRobots, steps, seed, List.copyOf(faults),
                    Map.copyOf(ringLines)).print(sum, early, late, killed, per);
        }
    }

    private long between(Random random, double from, double to) {
        return (long) (steps * (from + (to - from) * random.nextDouble()));
    }

    /** The soak's world: robots in rows 1 m apart, driving back and forth along x; 500 ms steps. */
    private Path writeEnvironment(Path file) throws IOException {
        StringBuilder b = new StringBuilder();
        int rows = robots + silentRobots;
        b.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<environment name=\"soak\" timeStepMs=\"500\">\n");
        b.append("  <arena width=\"13\" height=\"").append(rows + 1).append("\"/>\n  <robots>\n");
        for (int i = 0; i < rows; i++) {
            String name = i < robots ? "ring" + i : "silent" + (i - robots);
            b.append("    <robot name=\"").append(name).append("\" type=\"ArRobot\" control=\"")
                    .append(i < robots ? "robosim.examples.RingChatter" : "robosim.examples.BackAndForth")
                    .append("\" x=\"1.5\" y=\"").append(i + 1).append("\"/>\n");
        }
        b.append("  </robots>\n</environment>\n");
        Files.writeString(file, b.toString());
        return file;
    }

    private void robotLine(String line) {
        if (line.startsWith("ring ")) {
            ringLines.put(line.split(" ")[1], line);
        }
    }

    /** A live viewer that follows the step, for the fault schedule. */
    private void watch(int viewerPort) throws IOException, InterruptedException {
        ViewerClient v = ViewerClient.connect("127.0.0.1", viewerPort, new ViewerHello(false, 50), 10_000);
        v.start(new ViewerClient.Listener() {
            @Override
            public void snapshot(WorldSnapshot snapshot) {
            }

            @Override
            public void update(PoseUpdate update) {
                step.set(update.step());
                synchronized (stepChanged) {
                    stepChanged.notifyAll();
                }
            }

            @Override
            public void end(robosim.protocol.SimulationEnd end) {
                step.set(Long.MAX_VALUE);
                synchronized (stepChanged) {
                    stepChanged.notifyAll();
                }
            }
        });
    }

    private void awaitStep(long k) throws InterruptedException {
        synchronized (stepChanged) {
            while (step.get() < k) {
                stepChanged.wait();
            }
        }
    }

    private interface Fault {
        void run() throws Exception;
    }

    private CompletableFuture<Void> at(long k, Fault fault) {
        return CompletableFuture.runAsync(() -> {
            try {
                awaitStep(k);
                if (step.get() != Long.MAX_VALUE) {
                    fault.run();
                }
            } catch (Exception e) {
                faults.add("a fault could not be injected: " + e);
            }
        }, clients);
    }

    /** At step k: a full GC in the Environment and its old generation, KB (-1 if it could not be read). */
    private long heapAt(long k, long pid) throws Exception {
        awaitStep(k);
        if (step.get() == Long.MAX_VALUE) {
            return -1;
        }
        // the run is paused meanwhile (a short run would otherwise be over before jcmd has attached)
        try (robosim.control.ControlClient control = new robosim.control.ControlClient("127.0.0.1", controlPort, null,
                60_000)) {
            control.request("pause");
            long at = step.get();
            // (JDK 17: "tenured generation total NK, used NK"; JDK 21+: "Tenured total NK, used NK")
            Pattern tenured = Pattern.compile("(?i)tenured(?: generation)?\\s+total \\d+K, used (\\d+)K");
            String answer = "";
            for (int attempt = 1; attempt <= 3; attempt++) { // (jcmd's attach can time out on a loaded machine)
                SoakClients.run("jcmd", Long.toString(pid), "GC.run");
                answer = SoakClients.run("jcmd", Long.toString(pid), "GC.heap_info");
                Matcher m = tenured.matcher(answer);
                if (m.find()) {
                    long kb = Long.parseLong(m.group(1));
                    faults.add("Environment heap read at step " + at + " (paused): " + kb + " KB");
                    control.request("resume");
                    return kb;
                }
            }
            control.request("resume");
            faults.add("Environment heap not read at step " + at + ": jcmd said "
                    + answer.strip().lines().findFirst().orElse("nothing"));
            return -1;
        }
    }

    public static void main(String[] args) {
        CommandLines.exit("soak", new Soak(), args);
    }
}
