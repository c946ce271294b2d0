package robosim.environment.run;

import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.server.ViewerQueue;
import robosim.protocol.RunState;

/**
 * The one point where a computed step may wait before its responses go out, and everything that may
 * hold it there: a pause (or the end of a step N budget), the pace ({@code --speed}), and a recording
 * viewer that is a whole backlog behind. Viewers are told when a hold by pause begins and ends; nothing
 * here waits - the loop asks again after its next event or deadline. Loop thread only.
 */
final class ReleasePoint {
    private static final Logger LOG = LoggerFactory.getLogger(ReleasePoint.class);

    private final RunControl control;
    private final List<ReleaseListener> outputs;
    private final PublishedRun record;
    private final RunListener listener;
    private final boolean paced;
    /** The computed step waits for a full recording viewer. */
    private boolean heldForViewer;

    ReleasePoint(RunControl control, List<ReleaseListener> outputs, PublishedRun record, RunListener listener,
            double speed) {
        this.control = control;
        this.outputs = outputs;
        this.record = record;
        this.listener = listener;
        this.paced = speed > 0;
    }

    /**
     * Judges computed step {@code steps - 1} at the release point now ({@code released}: the steps out so far):
     * true if it passes; false while a pause, the pace or a full recording viewer holds it. A hold that begins
     * or ends here is announced to the viewers (and a hold for a viewer to the listener), and the end of a
     * pause restarts the pace and the rate.
     */
    boolean pass(long now, long steps, long released) {
        if (control.holdWanted()) {
            if (!control.holding()) {
                control.held(released);
                announce(new RunState(released, RunState.Phase.PAUSED));
            }
            return false;
        }
        if (control.holding()) {
            control.unheld(now, steps - 1); // pace on from here: no rush to catch up the pause
            record.resumed(now);
            announce(new RunState(released, RunState.Phase.RUNNING));
        }
        if (!heldForViewer && paced && control.paceDue(steps) - now > 0) {
            return false;
        }
        if (!haveRoom()) {
            if (!heldForViewer) {
                heldForViewer = true;
                LOG.debug("step {} waits for a recording viewer that is {} updates behind", steps - 1,
                        ViewerQueue.RECORDING_BACKLOG);
                listener.heldForViewer(steps - 1);
            }
            return false; // the viewer's worker posts when it has room: nothing to time meanwhile
        }
        if (heldForViewer) {
            heldForViewer = false;
            control.restartPace(now, steps - 1); // no rush to catch up the time held
        }
        return true;
    }

    private void announce(RunState state) {
        for (int i = 0; i < outputs.size(); i++) {
            outputs.get(i).state(state);
        }
    }

    /** True if every listener can take one more step now (a recording viewer a whole backlog behind cannot). */
    private boolean haveRoom() {
        for (int i = 0; i < outputs.size(); i++) {
            if (!outputs.get(i).hasRoom()) {
                return false;
            }
        }
        return true;
    }

    /**
     * When step {@code steps - 1} may go out by the pace (ns), if it waits for the pace; else far in the
     * future (not paced, paused, or held for a viewer, which says itself when it has room).
     */
    long paceDue(long steps) {
        return paced && !control.holdWanted() && !heldForViewer ? control.paceDue(steps) : Long.MAX_VALUE;
    }
}
