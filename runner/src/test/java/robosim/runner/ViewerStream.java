package robosim.runner;

import java.io.Externalizable;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/** Everything one viewer connection got, in order, for a test to wait on (by event) and compare. */
final class ViewerStream implements ViewerClient.Listener {
    final List<Externalizable> messages = new CopyOnWriteArrayList<>();
    private volatile IOException lost;

    @Override
    public void snapshot(WorldSnapshot snapshot) {
        got(snapshot);
    }

    @Override
    public void update(PoseUpdate update) {
        got(update);
    }

    @Override
    public void robotView(RobotView view) {
        got(view);
    }

    @Override
    public void runState(RunState state) {
        got(state);
    }

    @Override
    public void end(SimulationEnd end) {
        got(end);
    }

    @Override
    public void lost(IOException cause) {
        lost = cause;
        synchronized (this) {
            notifyAll();
        }
    }

    private synchronized void got(Externalizable m) {
        messages.add(m);
        notifyAll();
    }

    /** The first update of {@code step} after the first {@code after} messages, waiting up to {@code seconds}. */
    PoseUpdate awaitStep(long step, int after, long seconds) throws InterruptedException {
        return awaitStep(step, step, after, seconds);
    }

    /** The first update of a step from {@code from} to {@code to} after the first {@code after} messages. */
    synchronized PoseUpdate awaitStep(long from, long to, int after, long seconds) throws InterruptedException {
        long step = from;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (true) {
            for (int i = after; i < messages.size(); i++) {
                if (messages.get(i) instanceof PoseUpdate u && u.step() >= from && u.step() <= to) {
                    return u;
                }
            }
            long left = deadline - System.nanoTime();
            if (left <= 0 || lost != null || end() != null) {
                throw new AssertionError("no update of step " + step + " within " + seconds + " s (lost: " + lost
                        + ", end: " + end() + "); got " + messages.size() + " messages");
            }
            wait(TimeUnit.NANOSECONDS.toMillis(left) + 1);
        }
    }

    /** Waits up to {@code seconds} for the snapshot (the viewer has joined). */
    synchronized WorldSnapshot awaitSnapshot(long seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (messages.isEmpty()) {
            long left = deadline - System.nanoTime();
            if (left <= 0 || lost != null) {
                throw new AssertionError("no snapshot within " + seconds + " s (lost: " + lost + ")");
            }
            wait(TimeUnit.NANOSECONDS.toMillis(left) + 1);
        }
        return snapshot();
    }

    WorldSnapshot snapshot() {
        return messages.isEmpty() ? null : (WorldSnapshot) messages.get(0);
    }

    List<PoseUpdate> updates() {
        return only(PoseUpdate.class);
    }

    List<RobotView> views() {
        return only(RobotView.class);
    }

    List<RunState> states() {
        return only(RunState.class);
    }

    SimulationEnd end() {
        List<SimulationEnd> e = only(SimulationEnd.class);
        return e.isEmpty() ? null : e.get(0);
    }

    private <T> List<T> only(Class<T> type) {
        List<T> out = new ArrayList<>();
        for (Externalizable m : messages) {
            if (type.isInstance(m)) {
                out.add(type.cast(m));
            }
        }
        return out;
    }
}
