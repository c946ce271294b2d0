package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.api.RobotControl;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Departure;
import robosim.environment.run.Settings;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.ObjectConnection;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.StepRequest;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * A robot that sends its requests but stops reading its responses, while the others send it 8 KB
 * every step: the simulation loop, which writes every response itself in the default design, would
 * block in that write for ever. The write watchdog cuts the robot off past the write timeout, the
 * loop's write fails with that reason, the robot is removed, and the others go on.
 */
class SlowReaderTest {
    private static final long LONG_S = 60;
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml");

    /** Broadcasts 8,000 characters every step. */
    private static final RobotControl SHOUTER = robot -> {
        String big = "x".repeat(8000);
        while (true) {
            robot.broadcast(big);
            robot.sleep(1);
        }
    };

    @Test
    void aRobotThatStopsReadingIsCutOffAfterTheWriteTimeoutAndTheOthersGoOn() throws Exception {
        RunEvents events = new RunEvents();
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(new EnvironmentLoader().load(THREE),
                Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                        .writeTimeoutMs(500).build());
        env.listen(events);
        env.start();
        try (env) {
            int[] ports = env.ports();
            BlockingQueue<PoseUpdate> seen = new LinkedBlockingQueue<>();
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", ports[1], false, 10_000);
            viewer.start(new ViewerClient.Listener() {
                @Override
                public void snapshot(WorldSnapshot snapshot) {
                }

                @Override
                public void update(PoseUpdate update) {
                    seen.add(update);
                }
            });
            Socket s = new Socket();
            s.setReceiveBufferSize(4096);
            s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), ports[0]));
            ObjectConnection slow = new ObjectConnection(s, 64);
            slow.write(new RobotHello("r1", robosim.devices.RobotTypes.properties("ArRobot")));
            slow.flush();
            assertTrue(slow.read(RobotWelcome.class).isAccepted());
            List<CompletableFuture<String>> others = new ArrayList<>();
            for (String name : List.of("r2", "r3")) {
                HardwareSimulator sim = new HardwareSimulator(name, robosim.devices.RobotTypes.byName(name.equals("r3") ? "Scout" : "ArRobot"));
                sim.connect(new Socket(InetAddress.getLoopbackAddress(), ports[0]), 64);
                others.add(CompletableFuture.supplyAsync(() -> {
                    try {
                        return sim.run(SHOUTER);
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                }, TestThreads.ROBOTS));
            }
            assertEquals(0, slow.readStep()); // the last thing it ever reads
            // it asks for step k once step k-1 is out (a viewer saw it), never reading a response
            long k = 0;
            long lastSeen = -1;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(LONG_S);
            while (events.robotLeft.getCount() > 0 && System.nanoTime() < deadline) {
                if (lastSeen >= k - 1) {
                    slow.write(new StepRequest(k, 0, 0, false, List.of()));
                    slow.flush();
                    k++;
                }
                PoseUpdate u = seen.poll(100, TimeUnit.MILLISECONDS);
                if (u != null) {
                    lastSeen = Math.max(lastSeen, u.step());
                }
            }
            assertTrue(events.robotLeft.await(0, TimeUnit.SECONDS), "the robot that stopped reading was removed");
            Departure d = events.departures.get(0);
            assertEquals("r1", d.robot());
            assertTrue(d.why().contains("did not take a write within 500 ms"), d.why());
            long leftAt = d.step();
            PoseUpdate later;
            do {
                later = seen.poll(LONG_S, TimeUnit.SECONDS);
                assertTrue(later != null, "the others went on");
            } while (later.step() < leftAt + 50);
            env.stop("enough");
            for (CompletableFuture<String> r : others) {
                assertEquals("enough", r.get(LONG_S, TimeUnit.SECONDS));
            }
            viewer.close();
            slow.close();
        }
    }
}
