package robosim.rl;

import java.util.concurrent.CompletableFuture;
import robosim.environment.server.ViewerHost;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * World 0 of a learning batch as viewers see it ({@code --viewer-port}, {@code --web-port}): a viewer that joins gets
 * the world as it stands between two steps, then each step's poses (a new episode's world whole), through the
 * viewers' own bounded queues, so a slow viewer never holds the learner up. The stepping thread publishes after
 * each step; viewer threads join and leave; both under the batch's watch lock (never across a read or a write).
 */
final class WatchedWorld implements ViewerHost {
    private final BatchWorlds batch;
    private final Viewers viewers = new Viewers();

    WatchedWorld(BatchWorlds batch) {
        this.batch = batch;
    }

    @Override
    public String world() {
        return "this learning environment's world 0";
    }

    @Override
    public int robot(String name) {
        return batch.watched().robot(name);
    }

    @Override
    public CompletableFuture<WorldSnapshot> join(ViewerSink viewer) {
        synchronized (batch.watchLock()) {
            viewers.add(viewer);
            WorldSnapshot world = batch.watched().snapshot();
            viewer.queue().state(new RunState(world.poses().step() + 1, RunState.Phase.RUNNING));
            return CompletableFuture.completedFuture(world);
        }
    }

    @Override
    public void left(ViewerSink viewer, String why, boolean cutOff) {
        synchronized (batch.watchLock()) {
            viewers.remove(viewer, why);
        }
    }

    @Override
    public void roomFreed(ViewerSink viewer) {
        // (nothing is held for a viewer: a full queue coalesces)
    }

    /** After a step of the batch (the stepping thread): world 0's poses to every viewer. */
    void stepped() {
        synchronized (batch.watchLock()) {
            BatchWorld world = batch.watched();
            boolean whole = world.takeNewWorld();
            if (viewers.isEmpty()) {
                return;
            }
            viewers.publish(whole ? world.snapshot() : null, world.watchedUpdate(), world::view);
        }
    }

    /** The learner has gone: every viewer is told, and given {@code timeoutMs} to hear it. */
    void end(String why, long timeoutMs) throws InterruptedException {
        synchronized (batch.watchLock()) {
            viewers.end(new SimulationEnd(batch.watched().snapshot().poses().step(), why));
        }
        viewers.awaitDone(timeoutMs);
    }
}
