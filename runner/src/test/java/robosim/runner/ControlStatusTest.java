package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.runner.ControlPortTest.ok;

import com.fasterxml.jackson.databind.JsonNode;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import robosim.control.ControlClient;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;

/** The control port's status tells the truth: where geometry is resolved, who is connected, who has left. */
class ControlStatusTest {
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml");

    @Test
    void underNoGeometryTheGeometryIsInProcessNotAttached() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            assertEquals("in-process", ok(c, "status").path("geometry").asText());
            f.robots();
            ok(c, "step 2");
            JsonNode s = ok(c, "status");
            assertEquals("in-process", s.path("geometry").asText());
            assertEquals(List.of("r1", "r2", "r3"), names(s.path("connected")));
            assertEquals(List.of(), names(s.path("left")));
        }
    }

    @Test
    void aRobotThatLeftMidRunIsListedAsLeftNotConnected() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            List<CompletableFuture<String>> robots = f.robots();
            ok(c, "step 3");
            f.sockets.get(1).close(); // r2's process goes away while the Environment holds step 3
            // the next steps read r2's request, find its connection gone and go on without it
            assertEquals("paused at step 5", ok(c, "step 2").path("message").asText());
            JsonNode s = ok(c, "status");
            assertEquals(List.of("r1", "r3"), names(s.path("connected")));
            assertEquals(List.of("r2"), names(s.path("left")));
            ok(c, "stop");
            for (int i : new int[] {0, 2}) {
                assertEquals("stopped from the control port", robots.get(i).get(ControlFixture.TIMEOUT_MS,
                        TimeUnit.MILLISECONDS));
            }
        }
    }

    @Test
    void afterTheEndNoRobotIsListedAsConnected() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            List<CompletableFuture<String>> robots = f.robots();
            ok(c, "step 4");
            ok(c, "stop");
            for (CompletableFuture<String> r : robots) {
                assertEquals("stopped from the control port", r.get(ControlFixture.TIMEOUT_MS, TimeUnit.MILLISECONDS));
            }
            // the robots have been told and have exited; their workers close on their own threads
            JsonNode s = statusWhen(c, n -> n.path("connected").isEmpty());
            assertEquals("ENDED", s.path("state").asText());
            assertEquals(List.of("r1", "r2", "r3"), names(s.path("left")));
            assertEquals("in-process", s.path("geometry").asText());
        }
    }

    @Test
    void withAGeometryPortTheStatusWaitsForTheProcessAndSaysNoneOnceEnded() throws Exception {
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(new EnvironmentLoader().load(THREE),
                Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(false).maxSteps(0)
                .resetEvery(64).handshakeTimeoutMs(10_000).build());
        try (env) {
            env.start();
            assertEquals("waiting", env.status().geometry());
            env.stop("test over");
            assertEquals("none", env.status().geometry());
        }
    }

    /** Polls the status until it matches (the condition is reached by other threads); fails after a minute. */
    private static JsonNode statusWhen(ControlClient c, java.util.function.Predicate<JsonNode> condition)
            throws Exception {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ControlFixture.TIMEOUT_MS);
        while (true) {
            JsonNode s = ok(c, "status");
            if (condition.test(s)) {
                return s;
            }
            assertTrue(System.nanoTime() < deadline, "the status never got there: " + s);
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
    }

    private static List<String> names(JsonNode array) {
        List<String> out = new ArrayList<>();
        array.forEach(n -> out.add(n.asText()));
        return out;
    }
}
