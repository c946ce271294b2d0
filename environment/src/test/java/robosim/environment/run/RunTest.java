package robosim.environment.run;

import robosim.environment.net.RobotRoster;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.Arena;
import robosim.protocol.StepResponse;

/**
 * A {@link Run} driven by hand ({@link Hand}) with {@link Bot}s and in-process geometry: no coordinator, no loop
 * thread, no socket, no sleep, and a clock of the test's own; milliseconds a test. Every robot answers as it is
 * given a step, and whatever a test does next is posted at the moment it chooses (a paused run, step N, a listener),
 * so each step at which something happens is known exactly: joins, a loss under each policy, take-overs, add and
 * remove, the end.
 */
class RunTest {
    private static final long NEVER = Bot.NEVER;
    private static final RobotSpec D = new RobotSpec("d", "ArRobot", "", 14_000, 2000, 0);
    private static final WorldSpec WORLD = new WorldSpec("mem", "roster", 500, 1, new Arena(0, 0, 20_000, 20_000),
            List.of(), List.of(new RobotSpec("a", "ArRobot", "", 2000, 2000, 0),
                    new RobotSpec("b", "ArRobot", "", 2000, 6000, 0),
                    new RobotSpec("c", "ArRobot", "", 2000, 10_000, 0)), 0, 8192, List.of(),
            WorldSpec.DEFAULT_TAG_RANGE_MM, java.util.Set.of(), List.of(new JoinRule("d", D, null, 1)));

    private final List<Bot> bots = new ArrayList<>();
    private Hand hand;

    /**
     * The file's three robots say hello (c leaves when given step {@code cLeavesAt}, and says nothing from step
     * {@code cSilentFrom}); the run begins, unless paused, and runs as far as it can.
     */
    private void start(UnaryOperator<Settings.Builder> settings, long cLeavesAt, long cSilentFrom, boolean paused) {
        hand = new Hand(WORLD, settings.apply(Settings.builder().inProcessGeometry(true)).build());
        if (paused) {
            hand.run.startPaused();
        }
        List<CompletableFuture<String>> verdicts = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            Bot b = new Bot(hand, WORLD.robots().get(i).name(), i == 2 ? cLeavesAt : NEVER, i == 2 ? cSilentFrom : NEVER);
            verdicts.add(b.hello(i));
            bots.add(b);
        }
        hand.drain();
        for (CompletableFuture<String> v : verdicts) {
            assertNull(v.getNow("unanswered"), "accepted");
        }
    }

    private void start(UnaryOperator<Settings.Builder> settings, long cLeavesAt, boolean paused) {
        start(settings, cLeavesAt, NEVER, paused);
    }

    /** The control port's step N: runs {@code n} more steps and holds; the steps released then. */
    private long step(long n) {
        CompletableFuture<Long> done = new CompletableFuture<>();
        hand.apply(new LoopEvent.StepN(n, done));
        return done.getNow(-1L);
    }

    private void pause() {
        CompletableFuture<Void> held = new CompletableFuture<>();
        hand.apply(new LoopEvent.Pause(held));
        assertTrue(held.isDone(), "the pause holds at once");
    }

    private String add(String name, double xM, double yM, double headingDeg) {
        CompletableFuture<String> verdict = new CompletableFuture<>();
        hand.apply(new LoopEvent.AddRobot(RobotRoster.rule(name, "ArRobot", xM, yM, headingDeg, ""), verdict));
        return verdict.getNow("unanswered");
    }

    private String remove(String name) {
        CompletableFuture<String> verdict = new CompletableFuture<>();
        hand.apply(new LoopEvent.RemoveRobot(name, verdict));
        return verdict.getNow("unanswered");
    }

    private String hello(Bot b, int fileIndex) {
        CompletableFuture<String> verdict = b.hello(fileIndex);
        hand.drain();
        return verdict.getNow("unanswered");
    }

    // ---- the run's life ------------------------------------------------------------------------------------

    @Test
    void everyRobotGetsEveryResponseInOrderAndTheEnd() {
        start(s -> s.maxSteps(20), NEVER, false);
        assertTrue(hand.run.ended());
        for (Bot r : bots) {
            assertEquals(20, r.responses.size());
            for (int k = 0; k < 20; k++) {
                StepResponse response = r.responses.get(k);
                assertEquals(k, response.step());
                assertEquals(100, response.movedMm(), 1e-9, "nothing in the way");
            }
            assertEquals("completed 20 steps", r.end.reason());
        }
        RunSummary s = hand.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(20, s.steps());
        assertEquals(RunStatus.State.ENDED, hand.status().state());
        assertEquals(List.of("ended"), hand.heard);
    }

    @Test
    void aSilentRobotIsDroppedByTheStepTimeoutAndTheOthersGoOn() {
        start(s -> s.maxSteps(30).stepTimeoutMs(100), NEVER, 5, false);
        assertEquals(5, hand.status().step(), "the world waits for c's request for step 5");
        hand.later(100);
        assertFalse(hand.run.ended(), "not late at the step timeout itself");
        hand.later(1);
        assertTrue(hand.run.ended());
        RunSummary s = hand.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(30, s.steps());
        assertEquals(1, s.departures().size());
        Departure d = s.departures().get(0);
        assertEquals("c", d.robot());
        assertEquals(5, d.step());
        assertTrue(d.why().contains("step timeout"), d.why());
        assertTrue(bots.get(2).dropped(), "its connection was closed");
        assertFalse(bots.get(0).dropped());
    }

    @Test
    void stepNRunsExactlyNStepsPauseHoldsAndStopEndsAtOnce() {
        start(s -> s, NEVER, true);
        assertEquals(RunStatus.State.PAUSED, hand.status().state(), "held before step 1");
        assertEquals(3, step(3));
        assertEquals(RunStatus.State.PAUSED, hand.status().state());
        assertEquals(3, hand.status().step());
        assertEquals(3, bots.get(0).responses.size(), "three responses out, the fourth step held");
        assertEquals(7, step(4));
        CompletableFuture<Void> resumed = new CompletableFuture<>();
        CompletableFuture<Void> held = new CompletableFuture<>();
        hand.post(new LoopEvent.Resume(resumed));
        hand.post(new LoopEvent.Pause(held));
        hand.drain();
        assertTrue(resumed.isDone() && held.isDone());
        assertEquals(RunStatus.State.PAUSED, hand.status().state());
        long at = hand.status().step();
        assertEquals(8, at, "the resume let the held step out, and the pause, queued next, held the one after");
        hand.apply(new LoopEvent.Stop("stopped by the test"));
        assertEquals(RunStatus.State.ENDED, hand.status().state());
        assertEquals("stopped by the test", bots.get(1).end.reason());
        assertEquals(at, bots.get(1).responses.size(), "nothing went out after the pause held");
    }

    // ---- losses, under each policy -------------------------------------------------------------------------

    @Test
    void underRemoveALostRobotLeavesTheWorldAtTheStepItWasLostAndTheOthersGoOn() {
        start(s -> s.maxSteps(20), 5, false);
        assertTrue(hand.run.ended());
        RunSummary s = hand.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(1, s.robotsRemoved());
        assertEquals(new Departure("c", 5, "its connection closed at step 5"), s.departures().get(0));
        assertEquals(new RobotState("c", "gone", 5), hand.state(2));
        assertEquals(20, bots.get(0).responses.size());
        assertEquals(5, bots.get(2).responses.size(), "steps 0 to 4");
    }

    @Test
    void underHoldALostRobotStandsWhereItWasUntilANewConnectionTakesItOverAtTheNextStep() {
        List<Bot> takeover = new ArrayList<>();
        List<CompletableFuture<String>> verdict = new ArrayList<>();
        start(s -> s.maxSteps(20).onRobotLoss(RobotLoss.HOLD), 5, true);
        hand.onHeld = () -> { // (as the run tells it c is held)
            Bot c2 = new Bot(hand, "c");
            takeover.add(c2);
            verdict.add(c2.hello(2));
        };
        hand.apply(new LoopEvent.Resume(new CompletableFuture<>()));
        Bot c2 = takeover.get(0);
        assertNull(verdict.get(0).getNow("unanswered"), "the new connection takes it over");
        assertTrue(hand.run.ended());
        assertEquals(List.of("held c 5", "returned c 6", "ended"), hand.heard, "the others stepped on while it was held");
        assertEquals(6, c2.firstStep);
        double stoodAt = bots.get(2).responses.get(4).xMm();
        assertEquals(stoodAt, c2.welcome.xMm(), 1e-9, "welcomed where it stood");
        assertEquals(14, c2.responses.size(), "steps 6 to 19");
        assertEquals(0, hand.summary().robotsRemoved());
        assertEquals(new RobotState("c", "running", -1), hand.state(2));
    }

    @Test
    void underWaitTheWorldWaitsForALostRobotUntilItIsBack() {
        List<Integer> aHeard = new ArrayList<>();
        start(s -> s.maxSteps(20).onRobotLoss(RobotLoss.WAIT), 5, true);
        hand.onHeld = () -> {
            aHeard.add(bots.get(0).responses.size());
            new Bot(hand, "c").hello(2);
        };
        hand.onReturned = () -> aHeard.add(bots.get(0).responses.size());
        hand.apply(new LoopEvent.Resume(new CompletableFuture<>()));
        assertTrue(hand.run.ended());
        assertEquals(List.of("held c 5", "returned c 5", "ended"), hand.heard);
        assertEquals(List.of(5, 5), aHeard, "robot a got no step while c was away");
        assertTrue(hand.summary().completed());
    }

    @Test
    void underWaitARobotNotBackWithinTheStepTimeoutIsRemovedAndTheWorldGoesOn() {
        start(s -> s.maxSteps(20).onRobotLoss(RobotLoss.WAIT).stepTimeoutMs(200), 5, false);
        assertFalse(hand.run.ended(), "the world waits for c");
        assertEquals(new RobotState("c", "waiting", 5), hand.state(2));
        hand.later(201);
        assertTrue(hand.run.ended());
        RunSummary s = hand.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(List.of("held c 5", "left c 5", "ended"), hand.heard);
        assertEquals("did not come back within 200 ms (step timeout)", s.departures().get(0).why());
        assertEquals(20, bots.get(0).responses.size());
    }

    @Test
    void aRobotLostWhileAComputedStepIsHeldLeavesAtThatStepsEnd() {
        start(s -> s, NEVER, true);
        assertEquals(3, step(3)); // (step 3 is computed and held)
        bots.get(2).leave("its connection closed mid-step");
        pause();
        assertEquals(new RobotState("c", "running", -1), hand.state(2), "it takes part in the step it was lost in");
        assertEquals(4, step(1));
        assertEquals(new RobotState("c", "gone", 4), hand.state(2), "gone from the step after");
        assertEquals(3, bots.get(2).responses.size(), "the held step's response was not sent to it");
        assertEquals(4, bots.get(0).responses.size());
    }

    @Test
    void underSequentialOnlyTheRobotItsReaderWaitsForIsLateAndNoRobotJoins() {
        hand = new Hand(WORLD, Settings.builder().inProcessGeometry(true).design(CoordinatorDesign.SEQUENTIAL)
                .stepTimeoutMs(100).maxSteps(20).build());
        hand.run.startPaused();
        for (int i = 0; i < 3; i++) {
            Bot b = new Bot(hand, WORLD.robots().get(i).name(), NEVER, i == 0 ? NEVER : 5);
            b.hello(i);
            bots.add(b);
        }
        hand.drain();
        assertEquals(2, step(2));
        assertEquals(CoordinatorDesign.SEQUENTIAL.refusesJoins(), hello(new Bot(hand, "d"), -1), "no robot joins");
        assertEquals(CoordinatorDesign.SEQUENTIAL.refusesJoins(), add("e", 10, 10, 0), "nor is one added");
        hand.apply(new LoopEvent.Resume(new CompletableFuture<>()));
        assertEquals(5, hand.status().step(), "b and c say nothing from step 5");
        hand.later(101);
        assertTrue(bots.get(1).dropped(), "b, the first the reader waits for, is late");
        assertFalse(bots.get(2).dropped(), "c is not judged while the reader waits for b");
        hand.later(101);
        assertTrue(bots.get(2).dropped(), "then c");
        assertTrue(hand.summary().completed(), "a ran on alone");
        assertEquals(List.of("left b 5", "left c 5", "ended"), hand.heard);
    }

    // ---- joins, take-overs, add and remove -----------------------------------------------------------------

    @Test
    void aRobotTheFileLetsJoinTakesPartFromTheNextStepAndOthersAreRefused() {
        start(s -> s, NEVER, true);
        assertEquals(2, step(2));
        Bot d = new Bot(hand, "d");
        assertNull(hello(d, -1));
        assertEquals(14_000, d.welcome.xMm(), 1e-9, "at its start pose");
        assertEquals(List.of("a", "b", "c", "d"), d.welcome.robotNames());
        assertEquals(new RobotState("d", "joining", 3), hand.state(3));
        assertEquals("robot d is already connected (a new process takes over only once the old connection has "
                + "closed)", hello(new Bot(hand, "d"), -1));
        assertTrue(hello(new Bot(hand, "x"), -1).startsWith("no robot named \"x\" in mem may join"));
        assertEquals(3, step(1));
        pause();
        assertEquals(3, d.firstStep, "the step after the one held when it joined");
        assertEquals(new RobotState("d", "running", -1), hand.state(3));
        assertEquals(List.of("joined d 3"), hand.heard);
    }

    @Test
    void anAddedRobotJoinsAtItsPoseAndRemoveTakesItOutForGood() {
        start(s -> s, NEVER, true);
        assertEquals(1, step(1));
        assertTrue(add("f", 2, 2, 0).startsWith("(2.0, 2.0) m is taken"));
        int before = hand.status().states().size();
        assertNull(add("e", 10, 10, 90));
        assertNull(add("d", 14, 14, 0));
        assertEquals(List.of(new RobotState("d", "added", -1), new RobotState("e", "added", -1)),
                hand.status().states().subList(before, before + 2), "listed until they say hello, by name");
        assertNull(remove("d"));
        assertEquals(before + 1, hand.status().states().size(), "d is no longer let in, nor listed");
        assertEquals("a robot named e is added already", add("e", 12, 12, 0));
        Bot e = new Bot(hand, "e");
        assertNull(hello(e, -1));
        assertEquals(10_000, e.welcome.yMm(), 1e-9);
        assertEquals(2, step(1));
        pause(); // (step 2, its first, is computed and held)
        assertEquals(2, e.firstStep);
        assertNull(remove("e"));
        assertEquals("removed from the simulation from the control port", e.end.reason());
        assertEquals(3, step(1));
        assertEquals(new RobotState("e", "gone", 3), hand.state(3));
        assertEquals("robot \"e\" has already left", remove("e"));
    }

    @Test
    void aNewConnectionThatSaysHelloWhileTheOldOnesDepartureWaitsForTheStepsEndTakesOverRightAfter() {
        start(s -> s.onRobotLoss(RobotLoss.HOLD), NEVER, true);
        assertEquals(3, step(3)); // (step 3 is computed and held)
        bots.get(2).leave("its connection closed mid-step");
        Bot c2 = new Bot(hand, "c");
        assertNull(hello(c2, 2), "welcomed while the old connection's departure waits");
        assertEquals(new RobotState("c", "running", -1), hand.state(2), "it still takes part in the held step");
        assertEquals(4, step(1));
        pause(); // (step 4 is computed and held)
        assertEquals(List.of("held c 4", "returned c 4"), hand.heard, "held at the step's end, back at once");
        assertEquals(4, c2.firstStep);
        assertEquals(3, bots.get(2).responses.size(), "the held step's response went to neither connection");
    }

    @Test
    void aRobotRemovedWhileAStepIsHeldCannotBeTakenOverBeforeItGoes() {
        start(s -> s.onRobotLoss(RobotLoss.HOLD), NEVER, true);
        assertEquals(2, step(2));
        assertNull(remove("c"));
        bots.get(2).leave("it was told the end");
        assertEquals("robot c has been removed from the simulation", hello(new Bot(hand, "c"), 2));
        assertEquals(3, step(1));
        assertEquals(new RobotState("c", "gone", 3), hand.state(2));
    }

    @Test
    void aJoinedRobotLostBeforeItsFirstStepIsLostLikeAnyRobot() {
        start(s -> s.onRobotLoss(RobotLoss.HOLD), NEVER, true);
        assertEquals(2, step(2));
        Bot d = new Bot(hand, "d");
        assertNull(hello(d, -1));
        d.leave("gone before its first step");
        pause();
        assertEquals(3, step(1));
        assertEquals(List.of("joined d 3", "held d 3"), hand.heard);
        assertEquals(new RobotState("d", "held", 3), hand.state(3), "it stands where it joined, for its return");
        assertEquals(-1, d.firstStep, "it never took part");
    }
}
