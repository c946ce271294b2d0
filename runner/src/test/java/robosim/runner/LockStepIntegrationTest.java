package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.environment.run.CoordinatorDesign;
import robosim.examples.Wander;
import robosim.environment.core.WorldSpec;
import robosim.protocol.PoseUpdate;

/**
 * The paper benchmark over real sockets: 10 robots, 200 steps (2 BackAndForth cycles of 88 and 24 more, past
 * three stream resets, one every {@value #RESET_EVERY} messages), a message to the next robot every step. Every
 * pose after every step equals the hand-computed one, no two shapes overlap, every message arrives once and in
 * order, and in-process geometry gives the same poses bit for bit.
 */
class LockStepIntegrationTest {
    private static final int STEPS = 200;
    /** Messages between object-stream resets: a run this short passes several. */
    private static final int RESET_EVERY = 64;

    @Test
    void tenChattingRobotsFor200Steps() throws Exception {
        InJvmSimulation remote = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).resetEvery(RESET_EVERY)
                .run(STEPS, false, Chatter::new);
        check(remote);

        InJvmSimulation local = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).resetEvery(RESET_EVERY)
                .run(STEPS, true, Chatter::new);
        check(local);
        for (int k = 0; k < STEPS; k++) {
            PoseUpdate a = remote.updates.get(k);
            PoseUpdate b = local.updates.get(k);
            for (int i = 0; i < a.count(); i++) {
                assertArrayEquals(new double[] {a.xMm(i), a.yMm(i), a.headingDeg(i)},
                        new double[] {b.xMm(i), b.yMm(i), b.headingDeg(i)},
                        "--no-geometry differs at step " + k + " robot " + i);
            }
        }
    }

    /**
     * Every coordinator design and every setting of the performance work (step messages off, the
     * robots' exchange threading) against the default: the same pose for every robot at every step,
     * bit for bit, and every message delivered once and in order.
     */
    @ParameterizedTest(name = "{0} {1} stepMessages={2}")
    @CsvSource({
        "THREADS, ONE_THREAD, true",
        "TWO_THREADS, ONE_THREAD, true",
        "SEQUENTIAL, ONE_THREAD, false",
        "SEQUENTIAL, SEND_RECEIVE, true",
        "SEQUENTIAL, SHARED, true",
        "THREADS, SHARED, false",
        "TWO_THREADS, SEND_RECEIVE, false",
        "THREADS, ONE_CONNECTION, true",
        "TWO_THREADS, ONE_CONNECTION, false",
    })
    void everyDesignAndSettingGivesTheSamePosesAndMessages(CoordinatorDesign design,
            InJvmSimulation.Exchange exchange, boolean stepMessages) throws Exception {
        InJvmSimulation variant = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).resetEvery(RESET_EVERY)
                .design(design).exchange(exchange).stepMessages(stepMessages)
                .run(VARIANT_STEPS, false, Chatter::new);
        assertTrue(variant.summary.completed(), variant.summary.reason());
        InJvmSimulation.assertSamePoses(reference(), variant);
        for (Object o : variant.controls) {
            Chatter c = (Chatter) o;
            assertTrue(c.finished.await(30, java.util.concurrent.TimeUnit.SECONDS));
            assertEquals(List.of(), c.problems);
            assertEquals(VARIANT_STEPS, c.received);
        }
        assertEquals(10L * VARIANT_STEPS, variant.summary.messagesDelivered());
    }

    /** A sonar-driven workload (Wander in the maze, noisy sonar) under the least default combination. */
    @Test
    void wanderingRobotsTakeTheSamePathsUnderEveryThreading() throws Exception {
        InJvmSimulation a = new InJvmSimulation(InJvmSimulation.env("maze.xml")).resetEvery(RESET_EVERY)
                .run(STEPS, false, Wander::new);
        InJvmSimulation b = new InJvmSimulation(InJvmSimulation.env("maze.xml")).resetEvery(RESET_EVERY)
                .design(CoordinatorDesign.THREADS).exchange(InJvmSimulation.Exchange.SHARED)
                .stepMessages(false).run(STEPS, false, Wander::new);
        InJvmSimulation c = new InJvmSimulation(InJvmSimulation.env("maze.xml")).resetEvery(RESET_EVERY)
                .design(CoordinatorDesign.TWO_THREADS).exchange(InJvmSimulation.Exchange.SEND_RECEIVE)
                .run(STEPS, false, Wander::new);
        InJvmSimulation d = new InJvmSimulation(InJvmSimulation.env("maze.xml")).resetEvery(RESET_EVERY)
                .exchange(InJvmSimulation.Exchange.ONE_CONNECTION).run(STEPS, false, Wander::new);
        InJvmSimulation.assertSamePoses(a, b);
        InJvmSimulation.assertSamePoses(a, c);
        InJvmSimulation.assertSamePoses(a, d);
    }

    private static final int VARIANT_STEPS = STEPS; // (past the stream resets, as above)
    private static InJvmSimulation reference;

    private static synchronized InJvmSimulation reference() throws Exception {
        if (reference == null) {
            reference = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).resetEvery(RESET_EVERY)
                    .run(VARIANT_STEPS, false, Chatter::new);
        }
        return reference;
    }


    private static void check(InJvmSimulation sim) throws Exception {
        assertEquals(STEPS, sim.summary.steps());
        assertTrue(sim.summary.completed(), sim.summary.reason());
        assertEquals(STEPS, sim.updates.size(), "the recording viewer saw every step");
        List<WorldSpec.RobotSpec> robots = sim.spec.robots();
        for (int k = 0; k < STEPS; k++) {
            PoseUpdate u = sim.updates.get(k);
            assertEquals(k, u.step());
            double[] expected = BackAndForthMath.after(k);
            for (int i = 0; i < robots.size(); i++) {
                assertEquals(robots.get(i).xMm() + expected[0], u.xMm(i), 1e-6, "x of robot " + i + " at step " + k);
                assertEquals(robots.get(i).yMm(), u.yMm(i), 1e-6, "y of robot " + i + " at step " + k);
                assertEquals(expected[1], u.headingDeg(i), 1e-9, "heading of robot " + i + " at step " + k);
                for (int j = i + 1; j < robots.size(); j++) {
                    double d = Math.hypot(u.xMm(i) - u.xMm(j), u.yMm(i) - u.yMm(j));
                    assertTrue(d >= 500, "robots " + i + " and " + j + " overlap at step " + k);
                }
            }
        }
        PoseUpdate last = sim.updates.get(STEPS - 1);
        // 200 = 2 cycles of 88 + 24 steps forward: x = start + 24 x 250, heading 0
        assertEquals(1500 + 6000, last.xMm(0), 1e-6);
        assertEquals(0, last.headingDeg(0));
        for (Object o : sim.controls) {
            Chatter c = (Chatter) o;
            assertTrue(c.finished.await(30, java.util.concurrent.TimeUnit.SECONDS));
            assertEquals(List.of(), c.problems);
            assertEquals(STEPS, c.sent, "one message per step");
            assertEquals(STEPS, c.received, "every message received exactly once");
        }
        assertEquals(10L * STEPS, sim.summary.messagesDelivered());
    }
}
