package robosim.environment.replay;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepNumbers;
import robosim.protocol.Traces;
import robosim.protocol.WorldSnapshot;

/**
 * Where a replay stands in its recording: the step shown (none before the first: the snapshot's), and
 * the world as a viewer joining now would get it. The {@code replay-clock} thread's own.
 */
final class RecordingCursor {
    private static final Logger LOG = LoggerFactory.getLogger(RecordingCursor.class);

    private final RecordingReader recording;
    private int steps;
    private int index = -1;
    private RecordingReader.Step shown;
    /** The update of the step shown as viewers get it (its piece of the replay's drawing). */
    private PoseUpdate shownUpdate;
    /** The world of the step shown (robots may have joined), and whether viewers have yet to get it. */
    private WorldSnapshot world;
    private boolean worldChanged;
    /** What the loop functions had drawn by the step shown, pieced together from the steps' pieces. */
    private final Traces.Log drawing = new Traces.Log();
    /** The last step (index) whose piece {@link #drawing} holds, -1 for none. */
    private int drawnTo = -1;
    /** The whole drawing at every {@link #KEPT_EVERY}-th step pieced together so far, by step index over it. */
    private final Map<Integer, Traces> kept = new HashMap<>();
    /** Steps between the drawings kept: a seek pieces the drawing together from the nearest kept before it. */
    static final int KEPT_EVERY = 256;
    /** The most drawings kept (each may hold arrays of its own): beyond it, every other one is let go. */
    static final int MAX_KEPT = 64;
    /** The whole drawing as of the step shown. */
    private Traces shownWhole = Traces.NONE;

    RecordingCursor(RecordingReader recording) {
        this.recording = recording;
        this.steps = recording.steps();
        this.world = recording.snapshot();
    }

    /**
     * Moves to the i-th recorded step; its update (what its loop functions drew, a piece of the replay's own
     * drawing: after a seek, the whole of it), or null if it cannot be read (the replay then ends before it).
     */
    PoseUpdate show(int i) {
        try {
            RecordingReader.Step next = recording.step(i);
            PoseUpdate u = next.update();
            if (u.lightsOn() != null) { // (a world with loop functions: what they drew, pieced together)
                drawTo(i, u);
                u = u.withPiece(drawing.since());
            }
            shown = next;
            shownUpdate = u;
            shownWhole = drawing.whole();
            index = i;
            WorldSnapshot w = recording.snapshotAt(i);
            if (w != world) {
                world = w;
                worldChanged = true;
            }
            return u;
        } catch (IOException e) {
            LOG.error("the recording cannot be read on: {}", e.getMessage());
            steps = i;
            drawnTo = -2; // (pieced together again, from a step kept, if a seek back shows one)
            return null;
        }
    }

    /** Pieces the drawing together up to step {@code i}, whose update is {@code u}: on from a seek's nearest kept. */
    private void drawTo(int i, PoseUpdate u) throws IOException {
        if (i != drawnTo + 1) {
            drawing.erase();
            drawnTo = -1;
            for (int k = i / KEPT_EVERY; k >= 0; k--) {
                Traces whole = kept.get(k * KEPT_EVERY);
                if (whole != null && k * KEPT_EVERY <= i) {
                    drawing.apply(whole);
                    drawnTo = k * KEPT_EVERY;
                    break;
                }
            }
            for (int k = drawnTo + 1; k < i; k++) {
                drawn(k, recording.step(k).update());
            }
        }
        drawn(i, u);
    }

    private void drawn(int k, PoseUpdate u) throws IOException {
        drawing.apply(u.traces());
        drawnTo = k;
        if (k % KEPT_EVERY == 0) {
            kept.put(k, drawing.whole());
            if (kept.size() > MAX_KEPT) { // (every other one let go: fewer, and as far apart as the recording allows)
                List<Integer> steps = new ArrayList<>(new TreeSet<>(kept.keySet()));
                for (int n = 1; n < steps.size(); n += 2) {
                    kept.remove(steps.get(n));
                }
            }
        }
    }

    /** The world of the step just shown if it is not the one before (robots joined, or a seek across a join), once; else null. */
    WorldSnapshot takeWorldChange() {
        boolean changed = worldChanged;
        worldChanged = false;
        return changed ? world : null;
    }

    /** Robot {@code robot}'s view of the step shown; null before the first or if it was not in that step. */
    RobotView view(int robot) {
        return shown == null ? null : shown.view(robot);
    }

    int index() {
        return index;
    }

    int steps() {
        return steps;
    }

    boolean atEnd() {
        return index >= steps - 1;
    }

    /** The step shown (the snapshot's before the first). */
    long step() {
        return index < 0 ? recording.snapshot().step() : recording.stepNumber(index);
    }

    /** The step shown as a person is shown it: steps completed ({@link StepNumbers}; 0 before the first). */
    long shown() {
        return StepNumbers.shown(step());
    }

    long firstStep() {
        return steps == 0 ? -1 : recording.stepNumber(0);
    }

    long lastStep() {
        return steps == 0 ? -1 : recording.stepNumber(steps - 1);
    }

    /**
     * The index of the last recorded step at or before the one shown as {@code shown} ({@link StepNumbers}), which
     * must be in the recording: from {@code shown(firstStep())} to {@code shown(lastStep())}.
     */
    int indexOf(long shown) {
        long k = StepNumbers.wire(shown);
        if (steps == 0 || k < firstStep() || k > lastStep()) {
            throw new IllegalArgumentException("step " + shown + " is not in the recording (" + (steps == 0
                    ? "it has no steps" : "steps " + StepNumbers.shown(firstStep()) + " to " + StepNumbers.shown(lastStep()))
                    + ")");
        }
        int lo = 0;
        int hi = steps - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (recording.stepNumber(mid) <= k) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /** The run's time step, ms (100 if the recording does not say). */
    long timeStepMs() {
        long ms = recording.snapshot().timeStepMs();
        return ms > 0 ? ms : 100;
    }

    /** The end to send after the last step: the recorded one, or one saying where the file stops. */
    SimulationEnd end() {
        SimulationEnd recorded = recording.end();
        return recorded != null && steps == recording.steps() ? recorded : new SimulationEnd(step(),
                "the recording stops at step " + shown() + (recording.cutShort() == null ? "" : ": " + recording.cutShort()));
    }

    /** The world as the replay shows it now. */
    WorldSnapshot snapshot() {
        WorldSnapshot s = world;
        return shown == null ? s : new WorldSnapshot(s.timeStepMs(), s.arena(), s.obstacles(), s.robotNames(),
                s.robots(), shownUpdate.withWholeDrawing(shownWhole), s.scenery());
    }
}
