package robosim.environment.server;

import robosim.protocol.Printable;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import java.util.function.IntFunction;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.WorldSnapshot;
import robosim.protocol.SimulationEnd;

/**
 * The viewers of a run, as the loop sees them: it offers each step's poses and every change of run
 * state to their {@link ViewerQueue}s and never waits on one (a viewer that does not take a write within
 * the write timeout is cut off by the {@link ConnectionWatch}, and its worker then removes it). Joins and
 * publication happen on the loop thread; a viewer whose worker ends removes itself (also after the run);
 * the list is safe for both.
 */
public final class Viewers {
    private static final Logger LOG = LoggerFactory.getLogger(Viewers.class);

    private final List<ViewerSink> viewers = new CopyOnWriteArrayList<>();

    public void add(ViewerSink viewer) {
        viewers.add(viewer);
        LOG.info("{} connected ({} viewer(s))", viewer.viewerName(), viewers.size());
    }

    /** {@code viewer}'s worker has ended, for {@code why}; true if it was one of these viewers. Any thread. */
    public boolean remove(ViewerSink viewer, String why) {
        if (viewers.remove(viewer)) {
            LOG.info("{} disconnected: {}", viewer.viewerName(), Printable.of(why));
            return true;
        }
        return false;
    }

    public boolean isEmpty() {
        return viewers.isEmpty();
    }

    public int count() {
        return viewers.size();
    }

    /** A copy of the viewers now, for waiting on them after the end (any thread). */
    public List<ViewerSink> all() {
        return List.copyOf(viewers);
    }

    /** True if every recording viewer can take one more update now (the others always can). */
    public boolean haveRoom() {
        for (ViewerSink v : viewers) {
            if (!v.queue().hasRoom()) {
                return false;
            }
        }
        return true;
    }

    /**
     * The step's poses to every viewer, and to one that watches a robot its view ({@code viewOf}); {@code roster}:
     * the world the poses are of when robots have joined since the last step, else null.
     */
    public void publish(WorldSnapshot roster, PoseUpdate update, IntFunction<RobotView> viewOf) {
        for (ViewerSink v : viewers) {
            ViewerQueue q = v.queue();
            int watched = q.watching();
            q.offer(roster, update, watched < 0 ? null : viewOf.apply(watched));
        }
    }

    public void announce(RunState state) {
        for (ViewerSink v : viewers) {
            v.queue().state(state);
        }
    }

    public void end(SimulationEnd end) {
        for (ViewerSink v : viewers) {
            v.queue().end(end);
        }
    }

    /** After the end: waits up to {@code timeoutMs} for every viewer worker to send what it holds. */
    public void awaitDone(long timeoutMs) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        for (ViewerSink v : all()) {
            if (!v.awaitDone(Math.max(0, deadline - System.nanoTime()))) {
                LOG.warn("{} did not take the end of the simulation within {} ms", v.viewerName(), timeoutMs);
            }
        }
    }
}
