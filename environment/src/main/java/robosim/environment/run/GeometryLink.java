package robosim.environment.run;

import java.util.function.LongSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.InProcessGeometry;
import robosim.environment.core.SimulationCore;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.GeometryWorld;

/**
 * Where the loop's steps are resolved, and what happens when that fails: the attached Geometry process
 * (through its {@link GeometryPeer}, asynchronously: the answer comes back as an event), or the
 * geometry library in-process ({@code --no-geometry}, or after a loss under
 * {@link GeometryLoss#IN_PROCESS}). Owns the Geometry timeout and the failover.
 * Loop thread only.
 */
public final class GeometryLink implements SimulationCore.Geometry {
    private static final Logger LOG = LoggerFactory.getLogger(GeometryLink.class);

    private final Settings settings;
    private final LongSupplier clock;
    private GeometryWorld world;
    private InProcessGeometry inProcess;
    /** The Geometry process that takes steps now, or null. */
    private GeometryPeer attached;
    /** A Geometry process that has said hello and is being sent the world (or waits for the start). */
    private GeometryPeer joining;
    /**
     * The step being resolved (sent to {@link #attached}, or waiting for a Geometry process under WAIT)
     * until {@link #resolved}: a loss before then resolves it again.
     */
    private GeometryStepRequest outstanding;
    private long sentNanos;
    /** When the world went to {@link #joining}, or 0. */
    private long joinSentNanos;
    private int losses;
    private int attaches;
    private boolean started;
    /** The world last sent to a Geometry process: when robots have joined since, the next step sends the new one. */
    private GeometryWorld sentWorld;

    /** {@code clock}: the run's (ns), for the Geometry timeout. */
    GeometryLink(Settings settings, LongSupplier clock) {
        this.settings = settings;
        this.clock = clock;
    }

    /**
     * A Geometry process said hello: null if it may take over, else why not. Geometry is attached once: a
     * hello while one is live is refused (nobody takes over a live Geometry process's world); a new one
     * is let in only once the live one is lost.
     */
    String join(GeometryPeer worker) {
        if (settings.inProcessGeometry()) {
            return "this Environment resolves geometry in-process (--no-geometry)";
        }
        if (attached != null) {
            return "a Geometry process is already attached (another may attach only once it is lost)";
        }
        if (joining != null) {
            return world == null ? "a Geometry process is already attached" : "another Geometry process is attaching";
        }
        joining = worker;
        if (world != null) {
            send(worker, world);
        }
        return null;
    }

    /** True when the run may start: geometry in-process, or a Geometry process ready to be sent the world. */
    boolean canStart() {
        return settings.inProcessGeometry() || joining != null;
    }

    /** The run starts with this world: a waiting Geometry process is sent it (it answers {@link #ready}). */
    void start(GeometryWorld startWorld) {
        this.world = startWorld;
        if (settings.inProcessGeometry()) {
            inProcess = new InProcessGeometry(startWorld);
        } else if (joining != null) {
            send(joining, startWorld);
        }
    }

    /**
     * Robots have joined: from the next step on geometry is resolved in this world (in-process at once; an
     * attached Geometry process is sent it before the next step).
     */
    void worldChanged(GeometryWorld changed) {
        world = changed;
        if (inProcess != null) {
            inProcess = new InProcessGeometry(changed);
        }
    }

    private void send(GeometryPeer worker, GeometryWorld w) {
        sentWorld = w;
        joinSentNanos = clock.getAsLong();
        worker.sendWorld(w);
    }

    /** True once steps can be resolved (in-process, or a Geometry process has the world). */
    boolean ready() {
        return inProcess != null || attached != null;
    }

    /**
     * A Geometry process has the world and takes over (mid-run: after the one before it was lost); a step
     * waiting for it (WAIT) is sent to it now.
     */
    void attached(GeometryPeer worker) {
        if (worker != joining) {
            return;
        }
        joining = null;
        joinSentNanos = 0;
        if (started) {
            attaches++;
            LOG.warn("a new Geometry process attached: geometry is resolved there again");
        } else {
            LOG.info("Geometry process attached");
        }
        started = true;
        attached = worker;
        inProcess = null;
        if (outstanding != null) {
            if (sentWorld != world) { // (robots joined while it was being sent the world)
                sentWorld = world;
                worker.sendWorld(world);
            }
            sentNanos = clock.getAsLong();
            worker.resolve(outstanding);
        }
    }

    /**
     * Resolves {@code request}: returns the answer at once when geometry is in-process, else sends it to
     * the Geometry process and returns null (the answer comes as an event, see {@link #answer}).
     */
    @Override
    public GeometryStepResponse resolve(GeometryStepRequest request) {
        outstanding = request;
        if (attached != null) {
            if (sentWorld != world) {
                sentWorld = world;
                attached.sendWorld(world);
            }
            sentNanos = clock.getAsLong();
            attached.resolve(request);
            return null;
        }
        if (inProcess != null) {
            return inProcess.resolve(request);
        }
        return null; // WAIT: a Geometry process that attaches gets it
    }

    /** An answer: the step's, if it comes from the process it was sent to; else null (stale). */
    GeometryStepResponse answer(GeometryPeer from, GeometryStepResponse answer) {
        return from == attached && outstanding != null ? answer : null;
    }

    /** The outstanding step is complete (its answer passed the core's check): a loss no longer redoes it. */
    void resolved() {
        outstanding = null;
    }

    /**
     * The Geometry process {@code worker} is lost (it left, failed, gave a bad answer or timed out).
     * Returns the answer to the outstanding step if the loss policy resolves it at once (IN_PROCESS),
     * else null (no step outstanding, or WAIT: the step waits for a new Geometry process).
     */
    GeometryStepResponse lost(GeometryPeer worker, String why, long step) {
        worker.drop();
        if (worker == joining) {
            joining = null;
            joinSentNanos = 0;
            LOG.warn("a Geometry process was lost before it took over ({}); waiting for another", why);
            return null;
        }
        if (worker != attached) {
            return null;
        }
        attached = null;
        losses++;
        if (settings.onGeometryLoss() == GeometryLoss.IN_PROCESS && world != null) {
            LOG.warn("Geometry process lost in step {} ({}); going on with in-process geometry (same results); "
                    + "a new Geometry process may attach", robosim.protocol.StepNumbers.shown(step), why);
            inProcess = new InProcessGeometry(world);
            return outstanding == null ? null : inProcess.resolve(outstanding);
        }
        LOG.warn("Geometry process lost in step {} ({}); the step waits for a new Geometry process",
                robosim.protocol.StepNumbers.shown(step), why);
        return null;
    }

    /**
     * A Geometry process that has taken longer than the Geometry timeout over a step's answer, or over
     * taking the world it was sent; else null.
     */
    GeometryPeer overdue(long now) {
        long limit = settings.geometryTimeoutMs() * 1_000_000L;
        if (limit <= 0) {
            return null;
        }
        if (attached != null && outstanding != null && now - sentNanos > limit) {
            return attached;
        }
        return joining != null && joinSentNanos != 0 && now - joinSentNanos > limit ? joining : null;
    }

    /** Where collision and sonar are resolved now, for the status. */
    String where(boolean ended) {
        if (settings.inProcessGeometry()) {
            return "in-process";
        }
        if (attached != null || (joining != null && world == null)) {
            return "attached"; // (before the start: one has said hello and waits for the world)
        }
        if (ended) {
            return "none";
        }
        return inProcess != null ? "in-process" : "waiting";
    }

    /** The end: every Geometry process is told; one in the middle of a round trip nobody will read is cut off. */
    void end(robosim.protocol.SimulationEnd end) {
        if (attached != null && outstanding != null) {
            attached.drop();
        } else if (attached != null) {
            attached.end(end);
        }
        if (joining != null) {
            joining.end(end);
        }
    }

    int losses() {
        return losses;
    }

    int attaches() {
        return attaches;
    }
}
