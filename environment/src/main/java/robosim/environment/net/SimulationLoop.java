package robosim.environment.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.WorldSpec;

/**
 * The one owner of simulation time, on its own thread, {@code simulation-loop}: the only code that
 * advances the step. It takes events from one bounded queue ({@link LoopEvent}) and, per step, gathers
 * every robot's request, prepares the step in the core, has it resolved through the
 * {@link GeometryLink} (the Geometry worker does the round trip and posts the answer back), completes
 * it, and at the release point (pause, step N, pace, a full recording viewer) sends every robot its
 * response and the next step number, offers the poses to the viewers and checks for the end. It
 * blocks on its queue, with a timeout for the next deadline (pace, step timeout, Geometry timeout,
 * viewer write timeout), and in its own writes to robots, which the {@link WriteWatchdog} cuts short
 * past the write timeout; it holds no lock, ever. Its decisions live in {@link StepCycle} and
 * {@link RunLifecycle}.
 */
final class SimulationLoop implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(SimulationLoop.class);

    private final ClientWorkerCoordinator coordinator;
    private final Settings settings;
    private final WorldSpec spec;
    private final BlockingQueue<LoopEvent> events;
    private final Handshakes handshakes;
    private final StepCycle cycle;
    private final long tickNanos;
    private int registered;
    private long nextTick;
    /** Hellos that came while a step was being resolved: they are answered once it is complete. */
    private final List<LoopEvent> heldHellos = new ArrayList<>();
    /** Shared connections with a frame to write once the loop has done what it does now. */
    private final SharedOutput shared = new SharedOutput();
    /** Who is connected or has left changed since the status last saw it. */
    private boolean rosterChanged;

    SimulationLoop(ClientWorkerCoordinator coordinator, BlockingQueue<LoopEvent> events, Handshakes handshakes,
            StepCycle cycle) {
        this.coordinator = coordinator;
        this.settings = coordinator.settings();
        this.spec = coordinator.spec();
        this.events = events;
        this.handshakes = handshakes;
        this.cycle = cycle;
        this.tickNanos = tick(settings);
    }

    /** How often deadlines are checked: a quarter of the shortest one, between 5 and 100 ms. */
    private static long tick(Settings s) {
        long shortest = Long.MAX_VALUE;
        for (long ms : new long[] {s.stepTimeoutMs(), s.geometryTimeoutMs(), s.writeTimeoutMs()}) {
            if (ms > 0) {
                shortest = Math.min(shortest, ms);
            }
        }
        return TimeUnit.MILLISECONDS.toNanos(Math.max(5, Math.min(100, shortest / 4)));
    }

    @Override
    public void run() {
        try {
            cycle.advance(System.nanoTime());
            cycle.publishPhase();
            publishRoster();
            while (!cycle.ended()) {
                long now = System.nanoTime();
                LoopEvent e = events.poll(Math.max(0, Math.min(nextTick, cycle.paceDue()) - now), TimeUnit.NANOSECONDS);
                // everything queued by now is taken before any deadline is judged (a request or an answer
                // waiting in the queue is not late), and no more, so a busy queue never starves the deadlines
                for (int more = e == null ? 0 : events.size(); e != null; more--) {
                    handle(e);
                    cycle.advance(System.nanoTime());
                    shared.flush();
                    e = more > 0 ? events.poll() : null;
                }
                while (!heldHellos.isEmpty() && !cycle.midStep()) {
                    answer(heldHellos.remove(0));
                    rosterChanged = true;
                    cycle.advance(System.nanoTime());
                    shared.flush();
                }
                now = System.nanoTime();
                if (now - nextTick >= 0) {
                    cycle.tick(now);
                    nextTick = now + tickNanos;
                }
                cycle.advance(now);
                shared.flush();
                cycle.publishPhase();
                if (rosterChanged || cycle.takeRosterChange()) {
                    rosterChanged = false;
                    publishRoster();
                }
            }
        } catch (InterruptedException e) {
            cycle.finish("the Environment was interrupted", false);
        } catch (RuntimeException | Error e) {
            LOG.error("the simulation loop failed", e);
            cycle.finish("the simulation loop failed: " + e, false);
        } finally {
            shared.flush(); // (the end, to the robots of shared connections)
            heldHellos.forEach(this::refuseOver);
            cycle.publishPhase();
            publishRoster();
            coordinator.loopEnded();
        }
    }

    private void handle(LoopEvent e) {
        if (e instanceof LoopEvent.Request r) {
            cycle.request(r.worker(), r.request());
        } else if (e instanceof LoopEvent.Batch b) {
            for (LoopEvent each : b.events()) {
                handle(each);
            }
        } else if (e instanceof LoopEvent.RobotJoins || e instanceof LoopEvent.SharedJoins) {
            if (cycle.midStep()) {
                heldHellos.add(e); // (a robot joins between steps: after this one is resolved)
            } else {
                answer(e);
                rosterChanged = true;
            }
        } else if (e instanceof LoopEvent.RobotLeaves l) {
            leave(l.worker(), l.why());
            rosterChanged = true;
        } else if (e instanceof LoopEvent.GeometryJoins g) {
            g.verdict().complete(cycle.ended() ? "the simulation is over" : cycle.geometry().join(g.worker()));
        } else if (e instanceof LoopEvent.GeometryReady g) {
            cycle.geometryReady(g.worker());
        } else if (e instanceof LoopEvent.GeometryAnswer a) {
            cycle.geometryAnswer(a.worker(), a.answer());
        } else if (e instanceof LoopEvent.GeometryLeaves g) {
            cycle.geometryLost(g.worker(), g.why());
        } else if (e instanceof LoopEvent.ViewerJoins v) {
            cycle.addViewer(v.viewer(), v.snapshot());
        } else if (e instanceof LoopEvent.Pause p) {
            cycle.control().pause(p.held(), cycle.running() && !cycle.everyoneAway()); // (nothing steps: held now)
        } else if (e instanceof LoopEvent.Resume r) {
            cycle.control().resume(cycle.released());
            cycle.advance(System.nanoTime()); // (a run that may begin now begins before the answer)
            cycle.publishPhase();
            r.applied().complete(null);
        } else if (e instanceof LoopEvent.StepN s) {
            cycle.control().stepN(s.n(), s.done(), cycle.released(), cycle.running());
        } else if (e instanceof LoopEvent.AddRobot a) {
            a.verdict().complete(cycle.add(a.rule()));
            rosterChanged = true;
        } else if (e instanceof LoopEvent.RemoveRobot r) {
            r.verdict().complete(cycle.removeRobot(r.name()));
            rosterChanged = true;
        } else if (e instanceof LoopEvent.Stop s) {
            cycle.finish(s.reason(), false);
        }
        // ViewerHasRoom: nothing to do but try the release again (advance)
    }

    /** Answers a robot's hello, or those of a shared connection's robots (their welcomes written in one frame). */
    private void answer(LoopEvent hello) {
        if (hello instanceof LoopEvent.RobotJoins j) {
            j.verdict().complete(register(j));
            return;
        }
        LoopEvent.SharedJoins s = (LoopEvent.SharedJoins) hello;
        s.connection().outputTo(shared);
        for (LoopEvent.RobotJoins j : s.joins()) {
            String refusal = register(j);
            if (refusal != null) {
                s.connection().replies().welcome(((SharedRobot) j.worker()).slot(),
                        robosim.protocol.RobotWelcome.refused(refusal));
            }
            j.verdict().complete(refusal);
        }
        s.connection().flush(); // (the welcomes go out before any step number)
        s.answered().complete(true);
    }

    /** A hello left when the run ended. */
    private void refuseOver(LoopEvent hello) {
        if (hello instanceof LoopEvent.RobotJoins j) {
            j.verdict().complete("the simulation is over");
        } else {
            LoopEvent.SharedJoins s = (LoopEvent.SharedJoins) hello;
            s.joins().forEach(j -> j.verdict().complete("the simulation is over"));
            s.joins().forEach(j -> s.connection().replies().welcome(((SharedRobot) j.worker()).slot(),
                    robosim.protocol.RobotWelcome.refused("the simulation is over")));
            s.connection().flush();
            s.answered().complete(true);
        }
    }

    /** A robot's hello, already checked against the file: null (its welcome is sent) or the refusal. */
    private String register(LoopEvent.RobotJoins j) {
        if (!cycle.waiting()) {
            int live = cycle.indexOf(j.hello().name());
            return live >= 0 ? cycle.rejoin(j.worker(), j.hello(), live, handshakes)
                    : cycle.join(j.worker(), j.hello(), handshakes);
        }
        int index = j.index();
        if (index < 0) {
            return "the simulation has not started: a robot that joins a running world says hello once it runs";
        }
        RobotPeer[] robots = cycle.robots();
        if (robots[index] != null) {
            return "robot " + j.hello().name() + " is already connected";
        }
        try {
            j.worker().welcome(handshakes.welcome(index));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        j.worker().assign(index);
        robots[index] = j.worker();
        cycle.registered()[index] = j.hello().properties();
        registered++;
        LOG.info("robot {} connected ({} of {})", cycle.name(index), registered, robots.length);
        cycle.everyoneHere(registered == robots.length);
        return null;
    }

    private void leave(RobotPeer worker, String why) {
        int i = worker.index();
        RobotPeer[] robots = cycle.robots();
        if (i < 0 || i >= robots.length || robots[i] != worker) {
            return;
        }
        if (cycle.waiting()) {
            robots[i] = null;
            cycle.registered()[i] = null;
            registered--;
            cycle.everyoneHere(false);
            LOG.warn("robot {} left before the start ({}); waiting for it again", cycle.name(i),
                    Printable.of(why));
        } else {
            cycle.leave(i, why);
        }
    }

    /** Publishes the robots that have said hello and whether each takes part, for the status. */
    private void publishRoster() {
        List<RunRecord.Member> members = new ArrayList<>();
        RobotPeer[] robots = cycle.robots();
        for (int i = 0; i < robots.length; i++) {
            if (robots[i] != null) {
                members.add(new RunRecord.Member(cycle.name(i), robots[i],
                        cycle.waiting() || cycle.present(i)));
            }
        }
        cycle.record().roster = List.copyOf(members);
        cycle.record().states = cycle.states();
    }
}
