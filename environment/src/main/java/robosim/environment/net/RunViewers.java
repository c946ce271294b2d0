package robosim.environment.net;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Supplier;
import robosim.environment.core.WorldSpec;
import robosim.environment.server.ViewerHost;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.WorldSnapshot;

/**
 * The live run's viewers: the list the loop publishes to, and the {@link ViewerHost} a viewer worker joins through,
 * which hands every join, departure and room to the loop as an event (the list changes on the loop thread, and, once
 * the run is over, on the worker's).
 */
final class RunViewers implements ViewerHost {
    private final Viewers viewers = new Viewers();
    private final Consumer<LoopEvent> loop;
    private final WorldSpec spec;
    private final Supplier<RunStatus> status;

    /** {@code loop}: posts an event to the loop; {@code status}: what the loop has published (robots that joined). */
    RunViewers(Consumer<LoopEvent> loop, WorldSpec spec, Supplier<RunStatus> status) {
        this.loop = loop;
        this.spec = spec;
        this.status = status;
    }

    /** The viewers now (the loop publishes to them; any thread may count them or wait for them). */
    Viewers list() {
        return viewers;
    }

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
        loop.accept(new LoopEvent.ViewerJoins(viewer, snapshot));
        return snapshot;
    }

    @Override
    public void left(ViewerSink viewer, String why, boolean cutOff) {
        loop.accept(new LoopEvent.ViewerLeaves(viewer, why, cutOff, viewers));
    }

    @Override
    public void roomFreed(ViewerSink viewer) {
        loop.accept(new LoopEvent.ViewerHasRoom());
    }
}
