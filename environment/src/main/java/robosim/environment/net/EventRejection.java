package robosim.environment.net;

import java.io.IOException;
import java.util.concurrent.BlockingQueue;

/**
 * After the loop has ended: answers every event still queued, so no thread waits on an answer that
 * will not come (hellos are refused, pause and step N callers answered). Any thread; each event once.
 */
final class EventRejection {
    private EventRejection() {
    }

    static void drain(BlockingQueue<LoopEvent> events, StepCycle cycle) {
        LoopEvent e;
        while ((e = events.poll()) != null) {
            if (e instanceof LoopEvent.RobotJoins j) {
                j.verdict().complete("the simulation is over");
            } else if (e instanceof LoopEvent.SharedJoins s) {
                s.answered().complete(false); // (its worker refuses them: the loop never wrote to it)
            } else if (e instanceof LoopEvent.GeometryJoins g) {
                g.verdict().complete("the simulation is over");
            } else if (e instanceof LoopEvent.ViewerJoins v) {
                v.snapshot().completeExceptionally(new IOException("the simulation is over"));
            } else if (e instanceof LoopEvent.Pause p) {
                p.held().complete(null);
            } else if (e instanceof LoopEvent.StepN s) {
                s.done().complete(cycle.record().stepsReleased);
            } else if (e instanceof LoopEvent.AddRobot a) {
                a.verdict().complete("the simulation is over");
            } else if (e instanceof LoopEvent.RemoveRobot r) {
                r.verdict().complete("the simulation is over");
            }
        }
    }
}
