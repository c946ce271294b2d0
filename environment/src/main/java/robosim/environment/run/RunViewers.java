package robosim.environment.run;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.IntFunction;
import java.util.function.Supplier;
import robosim.environment.core.WorldSpec;
import robosim.environment.server.ViewerHost;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * The live run's viewers: a {@link ReleaseListener} of the run that offers every released step (and every change
 * of the run's state) to each viewer's queue, with the view of the robot it watches, never waiting on one; and the
 * {@link ViewerHost} a viewer worker joins through, which hands every join, departure and room to the loop as an
 * event (the list changes on the loop thread, and, once the run is over, on the worker's).
 */
public final class RunViewers implements ViewerHost, ReleaseListener {
    private final Viewers viewers = new Viewers();
    private final Consumer<LoopEvent> loop;
    private final WorldSpec spec;
    private final Supplier<RunStatus> status;
    /** The step being published and the world after it, for {@link #view} (loop thread, during a release). */
    private ReleaseListener.Step step;
    private ReleasedWorld world;
    private final IntFunction<RobotView> view = this::view;

    /** {@code loop}: posts an event to the loop; {@code status}: what the loop has published (robots that joined). */
    public RunViewers(Consumer<LoopEvent> loop, WorldSpec spec, Supplier<RunStatus> status) {
        this.loop = loop;
        this.spec = spec;
        this.status = status;
    }

    /** The viewers now (the loop publishes to them; any thread may count them or wait for them). */
    public Viewers list() {
        return viewers;
    }

    // ---- what the run releases -----------------------------------------------------------------------------

    @Override
    public void released(ReleasedWorld released, ReleaseListener.Step s) {
        if (viewers.isEmpty()) {
            return;
        }
        world = released;
        step = s;
        viewers.publish(released.grown() ? released.snapshot() : null, released.update(), view);
        step = null;
    }

    /** Robot i's view of the step just released, for a viewer that watches it; null if it did not take part. */
    private RobotView view(int i) {
        if (i >= world.robots() || !step.tookPart(i)) {
            return null;
        }
        return RobotView.of(world.update().step(), i, world.name(i), step.request(i), step.response(i));
    }

    @Override
    public void state(RunState state) {
        viewers.announce(state);
    }

    @Override
    public void ended(SimulationEnd end) {
        viewers.end(end);
    }

    @Override
    public boolean hasRoom() {
        return viewers.haveRoom();
    }

    // ---- viewer workers --------------------------------------------------------------------------------------

    @Override
    public String world() {
        return "this simulation";
    }

    @Override
    public int robot(String name) {
        int i = spec.indexOf(name);
        if (i < 0) { // (a robot that joined the running world: the loop's published list has it)
            List<RobotState> now = status.get().states();
            for (int k = 0; k < now.size() && i < 0; k++) { // (an added robot not there yet has no place)
                i = now.get(k).name().equals(name) && !RobotState.ADDED.equals(now.get(k).state()) ? k : -1;
            }
        }
        return i;
    }

    @Override
    public CompletableFuture<WorldSnapshot> join(ViewerSink viewer) {
        CompletableFuture<WorldSnapshot> snapshot = new CompletableFuture<>();
        loop.accept(new LoopEvent.ViewerJoins(viewer, viewers, snapshot));
        return snapshot;
    }

    @Override
    public void left(ViewerSink viewer, String why, boolean cutOff) {
        loop.accept(new LoopEvent.ViewerLeaves(viewer, why, cutOff, viewers));
    }

    @Override
    public void roomFreed(ViewerSink viewer) {
        loop.accept(new LoopEvent.Wake());
    }
}
