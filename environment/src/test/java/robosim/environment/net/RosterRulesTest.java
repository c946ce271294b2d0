package robosim.environment.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.Arena;

/**
 * The roster's rules against the loop itself, with {@link Bot}s and in-process geometry: no sockets, no
 * worker threads, milliseconds a test. Every robot answers on the loop thread as it is given a step, and
 * whatever a test does next is posted from a listener, also on the loop thread, so each step at which
 * something happens is known exactly.
 */
class RosterRulesTest {
    private static final long LONG_S = 60;
    private static final long NEVER = Long.MAX_VALUE;
    private static final RobotSpec D = new RobotSpec("d", "ArRobot", "", 14_000, 2000, 0);
    private static final WorldSpec WORLD = new WorldSpec("mem", "roster", 500, 1, new Arena(0, 0, 20_000, 20_000),
            List.of(), List.of(new RobotSpec("a", "ArRobot", "", 2000, 2000, 0),
                    new RobotSpec("b", "ArRobot", "", 2000, 6000, 0),
                    new RobotSpec("c", "ArRobot", "", 2000, 10_000, 0)), 0, 8192, List.of(),
            WorldSpec.DEFAULT_TAG_RANGE_MM, java.util.Set.of(), List.of(new JoinRule("d", D, null, 1)));

    /** What the loop told its listener, and what a test does when it is told a robot is held. */
    private static final class Heard implements RunListener {
        final List<String> events = new CopyOnWriteArrayList<>();
        volatile Runnable onHeld = () -> { };
        volatile Runnable onReturned = () -> { };

        @Override
        public void robotHeld(String robot, long step, String why) {
            events.add("held " + robot + " " + step);
            onHeld.run();
        }

        @Override
        public void robotReturned(String robot, long step) {
            events.add("returned " + robot + " " + step);
            onReturned.run();
        }

        @Override
        public void robotLeft(Departure d) {
            events.add("left " + d.robot() + " " + d.step());
        }
    }

    private final Heard heard = new Heard();
    private final List<Bot> bots = new ArrayList<>();
    private ClientWorkerCoordinator coordinator;

    /** The file's three robots said hello (c leaves when given step {@code cLeavesAt}); the run begins. */
    private void start(UnaryOperator<Settings.Builder> settings, long cLeavesAt, boolean paused) throws Exception {
        coordinator = new ClientWorkerCoordinator(WORLD, settings.apply(Settings.builder().inProcessGeometry(true))
                .build());
        coordinator.listen(heard);
        if (paused) {
            coordinator.startPaused();
        }
        coordinator.startLoop();
        for (int i = 0; i < 3; i++) {
            Bot b = new Bot(coordinator, WORLD.robots().get(i).name(), i == 2 ? cLeavesAt : NEVER);
            assertNull(b.hello(i).get(LONG_S, TimeUnit.SECONDS), "accepted");
            bots.add(b);
        }
    }

    @AfterEach
    void stop() {
        if (coordinator != null) {
            coordinator.stop("the test is over");
        }
    }

    private RobotState state(int i) {
        return coordinator.status().states().get(i);
    }

    @Test
    void underRemoveALostRobotLeavesTheWorldAtTheStepItWasLostAndTheOthersGoOn() throws Exception {
        start(s -> s.maxSteps(20), 5, false);
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS));
        RunSummary s = coordinator.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(1, s.robotsLeft());
        assertEquals(new Departure("c", 5, "its connection closed at step 5"), s.departures().get(0));
        assertEquals(new RobotState("c", "gone", 5), state(2));
        assertEquals(20, bots.get(0).responses.size());
        assertEquals(5, bots.get(2).responses.size(), "steps 0 to 4");
    }

    @Test
    void underHoldALostRobotStandsWhereItWasUntilANewConnectionTakesItOverAtTheNextStep() throws Exception {
        CompletableFuture<Bot> takeover = new CompletableFuture<>();
        CompletableFuture<String> verdict = new CompletableFuture<>();
        heard.onHeld = () -> { // (on the loop thread, as c is held)
            Bot c2 = new Bot(coordinator, "c", NEVER);
            takeover.complete(c2);
            c2.hello(2).thenAccept(verdict::complete);
        };
        start(s -> s.maxSteps(20).onRobotLoss(RobotLoss.HOLD), 5, false);
        Bot c2 = takeover.get(LONG_S, TimeUnit.SECONDS);
        assertNull(verdict.get(LONG_S, TimeUnit.SECONDS), "the new connection takes it over");
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS));
        assertEquals(List.of("held c 5", "returned c 6"), heard.events, "the others stepped on while it was held");
        assertEquals(6, c2.firstStep);
        double stoodAt = new ArrayList<>(bots.get(2).responses).get(4).xMm();
        assertEquals(stoodAt, c2.welcome.xMm(), 1e-9, "welcomed where it stood");
        assertEquals(14, c2.responses.size(), "steps 6 to 19");
        assertEquals(0, coordinator.summary().robotsLeft());
        assertEquals(new RobotState("c", "running", -1), state(2));
    }

    @Test
    void underWaitTheWorldWaitsForALostRobotUntilItIsBack() throws Exception {
        List<Integer> aHeard = new CopyOnWriteArrayList<>();
        heard.onHeld = () -> {
            aHeard.add(bots.get(0).responses.size());
            new Bot(coordinator, "c", NEVER).hello(2);
        };
        heard.onReturned = () -> aHeard.add(bots.get(0).responses.size());
        start(s -> s.maxSteps(20).onRobotLoss(RobotLoss.WAIT), 5, false);
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS));
        assertEquals(List.of("held c 5", "returned c 5"), heard.events);
        assertEquals(List.of(5, 5), aHeard, "robot a got no step while c was away");
        assertTrue(coordinator.summary().completed());
    }

    @Test
    void underWaitARobotNotBackWithinTheStepTimeoutIsRemovedAndTheWorldGoesOn() throws Exception {
        start(s -> s.maxSteps(20).onRobotLoss(RobotLoss.WAIT).stepTimeoutMs(200), 5, false);
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS));
        RunSummary s = coordinator.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(List.of("held c 5", "left c 5"), heard.events);
        assertEquals("did not come back within 200 ms (step timeout)", s.departures().get(0).why());
        assertEquals(20, bots.get(0).responses.size());
    }

    @Test
    void aRobotLostWhileAComputedStepIsHeldLeavesAtThatStepsEnd() throws Exception {
        start(s -> s, NEVER, true);
        assertEquals(3, coordinator.step(3, LONG_S, TimeUnit.SECONDS)); // (step 3 is computed and held)
        bots.get(2).leave("its connection closed mid-step");
        coordinator.pause(LONG_S, TimeUnit.SECONDS); // (after the loss: the status has seen it)
        assertEquals(new RobotState("c", "running", -1), state(2), "it takes part in the step it was lost in");
        assertEquals(4, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        assertEquals(new RobotState("c", "gone", 4), state(2), "gone from the step after");
        assertEquals(3, bots.get(2).responses.size(), "the held step's response was not sent to it");
        assertEquals(4, bots.get(0).responses.size());
    }

    @Test
    void aRobotTheFileLetsJoinTakesPartFromTheNextStepAndOthersAreRefused() throws Exception {
        start(s -> s, NEVER, true);
        assertEquals(2, coordinator.step(2, LONG_S, TimeUnit.SECONDS));
        Bot d = new Bot(coordinator, "d", NEVER);
        assertNull(d.hello(-1).get(LONG_S, TimeUnit.SECONDS));
        assertEquals(14_000, d.welcome.xMm(), 1e-9, "at its start pose");
        assertEquals(List.of("a", "b", "c", "d"), d.welcome.robotNames());
        assertEquals(new RobotState("d", "joining", 3), state(3));
        assertEquals("robot d is already connected (a new process takes over only once the old connection has "
                + "closed)", new Bot(coordinator, "d", NEVER).hello(-1).get(LONG_S, TimeUnit.SECONDS));
        assertTrue(new Bot(coordinator, "x", NEVER).hello(-1).get(LONG_S, TimeUnit.SECONDS)
                .startsWith("no robot named \"x\" in mem may join"));
        assertEquals(3, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        coordinator.pause(LONG_S, TimeUnit.SECONDS); // (returns once step 3 is computed and held)
        assertEquals(3, d.firstStep, "the step after the one held when it joined");
        assertEquals(new RobotState("d", "running", -1), state(3));
    }

    @Test
    void anAddedRobotJoinsAtItsPoseAndRemoveTakesItOutForGood() throws Exception {
        start(s -> s, NEVER, true);
        assertEquals(1, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        RobotRoster roster = coordinator.roster();
        assertTrue(roster.add("f", "ArRobot", 2, 2, 0, "").startsWith("(2.0, 2.0) m is taken"));
        int before = coordinator.status().states().size();
        assertNull(roster.add("e", "ArRobot", 10, 10, 90, ""));
        assertNull(roster.add("d", "ArRobot", 14, 14, 0, ""));
        assertEquals(List.of(new RobotState("d", "added", -1), new RobotState("e", "added", -1)),
                coordinator.status().states().subList(before, before + 2), "listed until they say hello, by name");
        assertNull(roster.remove("d"));
        assertEquals(before + 1, coordinator.status().states().size(), "d is no longer let in, nor listed");
        assertEquals("a robot named e is added already", roster.add("e", "ArRobot", 12, 12, 0, ""));
        Bot e = new Bot(coordinator, "e", NEVER);
        assertNull(e.hello(-1).get(LONG_S, TimeUnit.SECONDS));
        assertEquals(10_000, e.welcome.yMm(), 1e-9);
        assertEquals(2, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        coordinator.pause(LONG_S, TimeUnit.SECONDS); // (returns once step 2, its first, is computed and held)
        assertEquals(2, e.firstStep);
        assertNull(roster.remove("e"));
        assertEquals("removed from the simulation from the control port",
                e.end.get(LONG_S, TimeUnit.SECONDS).reason());
        assertEquals(3, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        assertEquals(new RobotState("e", "gone", 3), state(3));
        assertEquals("robot \"e\" has already left", roster.remove("e"));
    }

    @Test
    void aNewConnectionThatSaysHelloWhileTheOldOnesDepartureWaitsForTheStepsEndTakesOverRightAfter() throws Exception {
        start(s -> s.onRobotLoss(RobotLoss.HOLD), NEVER, true);
        assertEquals(3, coordinator.step(3, LONG_S, TimeUnit.SECONDS)); // (step 3 is computed and held)
        bots.get(2).leave("its connection closed mid-step");
        Bot c2 = new Bot(coordinator, "c", NEVER);
        assertNull(c2.hello(2).get(LONG_S, TimeUnit.SECONDS), "welcomed while the old connection's departure waits");
        assertEquals(new RobotState("c", "running", -1), state(2), "it still takes part in the held step");
        assertEquals(4, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        coordinator.pause(LONG_S, TimeUnit.SECONDS); // (returns once step 4 is computed and held)
        assertEquals(List.of("held c 4", "returned c 4"), heard.events, "held at the step's end, back at once");
        assertEquals(4, c2.firstStep);
        assertEquals(3, bots.get(2).responses.size(), "the held step's response went to neither connection");
    }

    @Test
    void aRobotRemovedWhileAStepIsHeldCannotBeTakenOverBeforeItGoes() throws Exception {
        start(s -> s.onRobotLoss(RobotLoss.HOLD), NEVER, true);
        assertEquals(2, coordinator.step(2, LONG_S, TimeUnit.SECONDS));
        assertNull(coordinator.roster().remove("c"));
        bots.get(2).leave("it was told the end");
        assertEquals("robot c has been removed from the simulation",
                new Bot(coordinator, "c", NEVER).hello(2).get(LONG_S, TimeUnit.SECONDS));
        assertEquals(3, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        assertEquals(new RobotState("c", "gone", 3), state(2));
    }

    @Test
    void aJoinedRobotLostBeforeItsFirstStepIsLostLikeAnyRobot() throws Exception {
        start(s -> s.onRobotLoss(RobotLoss.HOLD), NEVER, true);
        assertEquals(2, coordinator.step(2, LONG_S, TimeUnit.SECONDS));
        Bot d = new Bot(coordinator, "d", NEVER);
        assertNull(d.hello(-1).get(LONG_S, TimeUnit.SECONDS));
        d.leave("gone before its first step");
        coordinator.pause(LONG_S, TimeUnit.SECONDS);
        assertEquals(3, coordinator.step(1, LONG_S, TimeUnit.SECONDS));
        assertEquals(List.of("held d 3"), heard.events);
        assertEquals(new RobotState("d", "held", 3), state(3), "it stands where it joined, for its return");
        assertEquals(-1, d.firstStep, "it never took part");
    }
}
