package robosim.environment.net;

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
 * state to their {@link ViewerQueue}s and never waits on one. A viewer whose worker has not finished a
 * write within the viewer write timeout is dropped with a logged reason. Joins, publication and drops
 * happen on the loop thread; a viewer whose worker ends removes itself (also after the run); the list is
 * safe for both.
 */
public final class Viewers {
    private static final Logger LOG = LoggerFactory.getLogger(Viewers.class);

    private final List<ViewerSink> viewers = new CopyOnWriteArrayList<>();
    private final long writeTimeoutNanos;
    private final RunListener listener;

    /** {@code writeTimeoutMs}: a write longer than this drops its viewer (0: never); {@code listener} hears of drops. */
    public Viewers(long writeTimeoutMs, RunListener listener) {
        this.writeTimeoutNanos = writeTimeoutMs <= 0 ? Long.MAX_VALUE : writeTimeoutMs * 1_000_000L;
        this.listener = listener;
    }

    public void add(ViewerSink viewer) {
        viewers.add(viewer);
        LOG.info("{} connected ({} viewer(s))", viewer.viewerName(), viewers.size());
    }

    public void remove(ViewerSink viewer, String why) {
        if (viewers.remove(viewer)) {
            LOG.info("{} disconnected: {}", viewer.viewerName(), Printable.of(why));
        }
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

    /** Drops every viewer stuck in one write for longer than the write timeout. */
    public void dropStuck(long now) {
        for (ViewerSink v : viewers) {
            long writing = v.writingFor(now);
            if (writing > writeTimeoutNanos && viewers.remove(v)) {
                String why = "did not take a write within " + writeTimeoutNanos / 1_000_000 + " ms";
                LOG.warn("{} dropped: {}", v.viewerName(), why);
                v.queue().close();
                v.drop();
                listener.viewerDropped(v.viewerName(), why);
            }
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
