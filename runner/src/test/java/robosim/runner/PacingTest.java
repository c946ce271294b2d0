package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.runner.ControlPortTest.ok;

import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import robosim.control.ControlClient;

/**
 * A paced run (--speed) never releases a step early, does not rush to catch up after a pause, and
 * keeps answering the control port while it waits for the pace. Only lower bounds on time are
 * checked: they hold however slowly the machine runs.
 */
class PacingTest {
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml"); // 500 ms steps
    private static final double SPEED = 10; // 50 ms a step
    private static final long STEP_NANOS = TimeUnit.MILLISECONDS.toNanos(50);

    @Test
    void afterAPauseTheRunGoesOnAtItsPaceWithoutCatchingUp() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null, SPEED); ControlClient c = f.client(null)) {
            var robots = f.robots();
            assertEquals("paused at step 4", ok(c, "step 4").path("message").asText());
            // the scenario, not a wait for an event: a pause far longer than the steps that follow, which a
            // pace counted from the start would "catch up" at full speed
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(1500));
            long t0 = System.nanoTime();
            assertEquals("paused at step 14", ok(c, "step 10").path("message").asText());
            long took = System.nanoTime() - t0;
            // the held step goes out at once; each of the 9 after it waits for its 50 ms
            assertTrue(took >= 9 * STEP_NANOS, "10 steps after a pause took " + took / 1_000_000 + " ms");
            ok(c, "stop");
            for (CompletableFuture<String> r : robots) {
                r.get(ControlFixture.TIMEOUT_MS, TimeUnit.MILLISECONDS);
            }
        }
    }

    @Test
    void theControlPortAnswersAndPausesAtOnceWhileAStepWaitsForItsPace() throws Exception {
        // --speed 0.01: each 500 ms step waits 50 s for its pace
        try (ControlFixture f = new ControlFixture(THREE, null, 0.01); ControlClient c = f.client(null)) {
            var robots = f.robots();
            long t0 = System.nanoTime();
            ok(c, "resume");
            assertEquals("RUNNING", ok(c, "status").path("state").asText());
            assertEquals("paused at step 0", ok(c, "pause").path("message").asText());
            assertEquals("PAUSED", ok(c, "status").path("state").asText());
            ok(c, "stop");
            for (CompletableFuture<String> r : robots) {
                assertEquals("stopped from the control port", r.get(ControlFixture.TIMEOUT_MS, TimeUnit.MILLISECONDS));
            }
            long took = System.nanoTime() - t0;
            // a lock held across the pace would keep every request waiting for the 50 s step
            assertTrue(took < TimeUnit.SECONDS.toNanos(25), "the requests took " + took / 1_000_000 + " ms");
        }
    }
}
