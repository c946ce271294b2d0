package robosim.environment.run;

import java.util.ArrayDeque;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import robosim.environment.core.WorldSpec;

/**
 * Test fixture: drives a {@link Run} by hand, on the test's thread, as the {@link SimulationLoop} does on its own:
 * events wait in a queue until {@link #drain}, which applies each and lets the run move on after it (hellos held
 * while a step was resolved are answered as soon as it is complete), and the deadlines are judged when the test
 * moves the clock on ({@link #later}). No thread, no socket, no sleep: the clock is this fixture's, and nothing
 * happens between two calls of the test.
 */
final class Hand {
    /** What the run told its listener, one line each: "held c 5", "returned c 6", "left c 5", "joined d 3", "ended". */
    final List<String> heard = new CopyOnWriteArrayList<>();
    /** What the test does when it is told a robot is held, or back (on this thread, as the loop tells it). */
    Runnable onHeld = () -> { };
    Runnable onReturned = () -> { };
    final Run run;
    private final WorldSpec spec;
    /** Events one drain takes at most: far more than any test's run, far fewer than a run that never holds. */
    private static final int EVENTS = 1_000_000;
    private final ArrayDeque<LoopEvent> queue = new ArrayDeque<>();
    private long now = 1_000_000_000L;

    Hand(WorldSpec spec, Settings settings, ReleaseListener... outputs) {
        this.spec = spec;
        this.run = new Run(spec, settings, new HelloCheck(spec), () -> now, new RunListener() {
            @Override
            public void robotHeld(String robot, long step, String why) {
                heard.add("held " + robot + " " + step);
                onHeld.run();
            }

            @Override
            public void robotReturned(String robot, long step) {
                heard.add("returned " + robot + " " + step);
                onReturned.run();
            }

            @Override
            public void robotLeft(Departure d) {
                heard.add("left " + d.robot() + " " + d.step());
            }

            @Override
            public void robotJoined(String robot, long step) {
                heard.add("joined " + robot + " " + step);
            }

            @Override
            public void ended(RunSummary summary) {
                heard.add("ended");
            }
        }, List.of(outputs));
    }

    /** Queues an event, as another thread posts one to the loop. */
    void post(LoopEvent event) {
        queue.add(event);
    }

    /**
     * Takes every event queued (and every one they lead to) as the loop does; then the run's status is published.
     * A run whose robots never stop answering (a test without an end, pause or silence) fails, not hangs.
     */
    void drain() {
        settle();
        int taken = 0;
        for (LoopEvent e; (e = queue.poll()) != null; ) {
            if (++taken > EVENTS) {
                throw new AssertionError("more than " + EVENTS + " events in one drain: the run never holds");
            }
            if (run.ended()) {
                e.refuse();
                continue;
            }
            e.apply(run);
            settle();
        }
        run.publish();
    }

    /** Posts {@code event} and drains. */
    void apply(LoopEvent event) {
        post(event);
        drain();
    }

    /** The clock moves on by {@code ms}: the deadlines are judged, as the loop judges them, and the run moves on. */
    void later(long ms) {
        now += ms * 1_000_000L;
        drain();
        run.tick(now);
        drain();
    }

    private void settle() {
        run.advance(now);
        while (run.answerHeldHellos()) {
            run.advance(now);
        }
    }

    /** What the control port's status would say now. */
    RunStatus status() {
        return run.published().status(spec.robots().stream().map(WorldSpec.RobotSpec::name).toList(), 0);
    }

    /** Robot {@code i}'s state as the control port lists it. */
    RobotState state(int i) {
        return status().states().get(i);
    }

    RunSummary summary() {
        return run.published().summary(Math.max(spec.robots().size(), status().states().size()));
    }
}
