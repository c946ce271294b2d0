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
import robosim.environment.net.Settings;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotModels;
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
                try (RawRobot r = new RawRobot(name, name.equals("r3") ? RobotModels.SCOUT : RobotModels.AR_ROBOT,
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
            out.writeObject(new RobotHello("r1", RobotModels.AR_ROBOT)); // (running: it passes the file's check)
            String filler = "x".repeat(NAME_CHARS);
            for (int i = 1; i < HELLOS; i++) {
                out.writeObject(new RobotHello(i + filler, RobotModels.AR_ROBOT));
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
}
