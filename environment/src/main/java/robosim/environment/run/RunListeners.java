package robosim.environment.run;

import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Every added {@link RunListener}, told in turn; one that throws is logged, not fatal. */
public final class RunListeners implements RunListener {
    private static final Logger LOG = LoggerFactory.getLogger(RunListeners.class);

    private final List<RunListener> all;

    public RunListeners(List<RunListener> all) {
        this.all = all;
    }

    private void each(java.util.function.Consumer<RunListener> call) {
        for (RunListener l : all) {
            try {
                call.accept(l);
            } catch (RuntimeException e) {
                LOG.error("a run listener failed", e);
            }
        }
    }

    @Override
    public void started(int robots) {
        each(l -> l.started(robots));
    }

    @Override
    public void robotLeft(Departure departure) {
        each(l -> l.robotLeft(departure));
    }

    @Override
    public void robotHeld(String robot, long step, String why) {
        each(l -> l.robotHeld(robot, step, why));
    }

    @Override
    public void robotJoined(String robot, long step) {
        each(l -> l.robotJoined(robot, step));
    }

    @Override
    public void robotReturned(String robot, long step) {
        each(l -> l.robotReturned(robot, step));
    }

    @Override
    public void geometryLost(long step) {
        each(l -> l.geometryLost(step));
    }

    @Override
    public void geometryAttached(long step) {
        each(l -> l.geometryAttached(step));
    }

    @Override
    public void viewerDropped(String viewer, String why) {
        each(l -> l.viewerDropped(viewer, why));
    }

    @Override
    public void heldForViewer(long step) {
        each(l -> l.heldForViewer(step));
    }

    @Override
    public void ended(RunSummary summary) {
        each(l -> l.ended(summary));
    }
}
