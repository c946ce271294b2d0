package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedOutputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.protocol.RobotHello;
import robosim.protocol.SharedHello;
import robosim.protocol.SharedReplies;

/**
 * What a stranger can cost the world: nothing. A shared hello for 1500 robots whose slot 0 names a robot
 * that is running and whose other names are 8 KB each, from a client that never reads, is answered by its
 * connection's own thread: the loop never writes to it, so the world goes on stepping meanwhile (the loop
 * once wrote that refusal itself, a 12 MB frame, and stood still for the write timeout). The refusals quote
 * the names cut short.
 */
class StrangersTest {
    private static final long LONG_S = 60;
    private static final int HELLOS = 1500;
    private static final int NAME_CHARS = 8 * 1024;

    @Test
    void aStrangerThatNamesARunningRobotAndNeverReadsCostsTheWorldNothing() throws Exception {
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                .build(); // (the default write timeout, 10 s: what the world once stood still for)
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), s);
        env.start();
        int port = env.ports()[0];
        List<CompletableFuture<Void>> robots = new ArrayList<>();
        for (String name : List.of("r1", "r2", "r3")) {
            robots.add(CompletableFuture.runAsync(() -> {
                try (RawRobot r = new RawRobot(name, name.equals("r3") ? robosim.devices.RobotTypes.properties("Scout") : robosim.devices.RobotTypes.properties("ArRobot"),
                        port)) {
                    while (r.next() && r.step(0, 0, false, List.of()) != null) {
                        // (until the end, between steps or mid-step)
                    }
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS));
        }
        try (Socket stranger = new Socket()) {
            assertTrue(env.awaitStart(LONG_S, TimeUnit.SECONDS), "the run began");
            stranger.setReceiveBufferSize(4096); // (before connecting: a window that never opens)
            stranger.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
            ObjectOutputStream out = new ObjectOutputStream(new BufferedOutputStream(stranger.getOutputStream()));
            out.writeObject(new SharedHello(HELLOS));
            out.writeObject(new RobotHello("r1", robosim.devices.RobotTypes.properties("ArRobot"))); // (running: it passes the file's check)
            String filler = "x".repeat(NAME_CHARS);
            for (int i = 1; i < HELLOS; i++) {
                out.writeObject(new RobotHello(i + filler, robosim.devices.RobotTypes.properties("ArRobot")));
                out.reset(); // (each name sent whole, as a stranger would)
            }
            out.flush();
            long before = env.status().step();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (env.status().step() < before + 500 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000); // (polls the status; the step count is what is waited for)
            }
            assertTrue(env.status().step() >= before + 500, "the world stepped on while the stranger held its answer "
                    + "unread: step " + before + " then " + env.status().step() + " within 5 s");
            ObjectInputStream in = new ObjectInputStream(stranger.getInputStream());
            assertEquals(0, ((SharedReplies) in.readObject()).count(), "the frame that asked for the hellos");
            SharedReplies answers = (SharedReplies) in.readObject();
            assertEquals(HELLOS, answers.count(), "every robot answered");
            for (int i = 0; i < answers.count(); i++) {
                String why = answers.welcome(i).reason();
                if (answers.slot(i) == 0) {
                    assertEquals("robot r1 is already connected (a new process takes over only once the old connection "
                            + "has closed)", why);
                } else {
                    assertTrue(why.startsWith("no robot named \"" + answers.slot(i) + "xxx") && why.length() < 300, why);
                }
            }
        } finally {
            env.stop("the test is over");
        }
        for (CompletableFuture<Void> r : robots) {
            r.get(LONG_S, TimeUnit.SECONDS);
        }
    }

    /** Strangers at once, each with a shared hello of the most robots and hellos of the most bytes. */
    private static final int STRANGERS = 16;
    private static final int STEPS = 400;

    @Test
    void sixteenStrangersOfTheLargestHellosLeaveA256MiBEnvironmentItsMemoryAndItsRun() throws Exception {
        List<String> clean = run(false);
        List<String> attacked = run(true);
        assertEquals(clean, attacked, "every robot's every pose, attacked and not");
    }

    /**
     * One run of three robots in an Environment of its own with a 256 MiB heap, started paused; with
     * {@code attack}, 16 strangers send their hellos, and until every one of them is done (dropped, or all
     * sent) the status is asked and the world stepped on, 5 steps at a time; then the run goes to its end.
     * Every robot's pose after every step, in order.
     */
    private static List<String> run(boolean attack) throws Exception {
        List<String> command = ProcessLines.java(List.of("-Xmx256m"), "robosim.environment.EnvironmentMain",
                "src/test/resources/three-robots.xml", "--steps", Integer.toString(STEPS), "--no-geometry", "--robot-port",
                "0", "--viewer-port", "0", "--control-port", "0", "--start-paused");
        try (ProcessLines env = new ProcessLines(attack ? "attacked" : "clean", new ProcessBuilder(command))) {
            java.util.Map<String, String> ports = HeadlessRunner.fields(env.await("listening robots=", LONG_S));
            int port = Integer.parseInt(ports.get("robots"));
            List<CompletableFuture<List<String>>> robots = new ArrayList<>();
            for (String name : List.of("r1", "r2", "r3")) {
                robots.add(CompletableFuture.supplyAsync(() -> drive(name, port), TestThreads.ROBOTS));
            }
            try (robosim.control.ControlClient control = new robosim.control.ControlClient("127.0.0.1",
                    Integer.parseInt(ports.get("control")), null, (int) TimeUnit.SECONDS.toMillis(LONG_S))) {
                env.await("paused before step 1", LONG_S);
                if (attack) {
                    List<Socket> strangers = new ArrayList<>();
                    List<CompletableFuture<Void>> sending = new ArrayList<>();
                    try {
                        for (int k = 0; k < STRANGERS; k++) {
                            Socket stranger = new Socket(InetAddress.getLoopbackAddress(), port);
                            strangers.add(stranger);
                            int serial = k;
                            sending.add(CompletableFuture.runAsync(() -> sendLargestHellos(stranger, serial),
                                    TestThreads.ROBOTS));
                        }
                        long stepped = 0;
                        while (!sending.stream().allMatch(CompletableFuture::isDone) && stepped < STEPS - 5) {
                            com.fasterxml.jackson.databind.JsonNode status = control.request("status");
                            assertTrue(status.path("ok").asBoolean(), status.toString());
                            assertTrue(control.request("step 5").path("ok").asBoolean());
                            stepped += 5;
                        }
                        CompletableFuture.allOf(sending.toArray(CompletableFuture[]::new)).get(LONG_S, TimeUnit.SECONDS);
                    } finally {
                        for (Socket s : strangers) {
                            s.close();
                        }
                    }
                }
                assertTrue(control.request("resume").path("ok").asBoolean());
                List<String> poses = new ArrayList<>();
                for (CompletableFuture<List<String>> r : robots) {
                    poses.addAll(r.get(LONG_S, TimeUnit.SECONDS));
                }
                env.await("summary steps=" + STEPS, LONG_S);
                assertEquals(0, env.exit(LONG_S), env.output());
                assertTrue(!env.output().contains("OutOfMemoryError"), env.output());
                return poses;
            }
        }
    }

    /** Robot {@code name} drives ahead (100 mm a step, a turn now and then) until the end; its poses. */
    private static List<String> drive(String name, int port) {
        List<String> poses = new ArrayList<>();
        try (RawRobot r = new RawRobot(name, name.equals("r3") ? robosim.devices.RobotTypes.properties("Scout") : robosim.devices.RobotTypes.properties("ArRobot"), port)) {
            while (r.next()) {
                robosim.protocol.StepResponse p = r.step(100, r.step % 50 == 0 ? 90 : 0, false, List.of());
                if (p == null) {
                    break;
                }
                poses.add(name + " " + p.step() + " " + p.xMm() + " " + p.yMm() + " " + p.headingDeg());
            }
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
        return poses;
    }

    /** A stranger's shared hello for the most robots a connection may carry, each name as long as a hello allows. */
    private static void sendLargestHellos(Socket stranger, int serial) {
        try {
            ObjectOutputStream out = new ObjectOutputStream(new BufferedOutputStream(stranger.getOutputStream()));
            out.writeObject(new SharedHello(robosim.protocol.Limits.MAX_ROBOTS_PER_CONNECTION));
            String filler = "y".repeat(14 * 1024);
            for (int i = 0; i < robosim.protocol.Limits.MAX_ROBOTS_PER_CONNECTION; i++) {
                out.writeObject(new RobotHello(serial + ":" + i + filler, robosim.devices.RobotTypes.properties("ArRobot")));
                out.reset();
            }
            out.flush();
        } catch (java.io.IOException e) {
            // dropped by the Environment (the budget, the deadline) or closed by the test: what a stranger gets
        }
    }
}
