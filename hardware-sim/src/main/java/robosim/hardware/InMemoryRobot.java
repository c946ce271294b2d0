package robosim.hardware;

import java.util.concurrent.locks.ReentrantLock;
import robosim.api.RobotControl;
import robosim.protocol.InMemoryLink;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One robot's Hardware Simulator in the Environment's JVM (a one-JVM run): the same
 * {@link HardwareSimulator}, the same step splitting and the same requests as over a socket, with no
 * exchange thread. The Environment's loop thread hands it each step number with the last response; the
 * request for it is built by whichever of two threads finds the control code yielded first: the loop
 * thread, at once, when the control code is still blocked in a call that goes on (or has returned), or the
 * control thread itself as it makes its next call ({@link ControlLink#onYield}). The step due is taken
 * under a lock, so each step gets exactly one request, and a response is applied under the same lock, so no
 * request is built from a call the response has not yet moved on. Only a response completes a call (sets
 * the control code running), so under the lock a yielded control code stays yielded: building a request
 * there never waits.
 */
final class InMemoryRobot implements InMemoryLink.Robot {
    private final HardwareSimulator sim;
    private final RobotControl control;
    private final InMemoryLink.Environment environment;
    private final ReentrantLock lock = new ReentrantLock();
    /** The step whose request nobody has built yet, or -1. */
    private long due = -1;
    private boolean started;

    InMemoryRobot(HardwareSimulator sim, RobotControl control, InMemoryLink.Environment environment) {
        this.sim = sim;
        this.control = control;
        this.environment = environment;
    }

    @Override
    public RobotHello hello() {
        return sim.hello();
    }

    @Override
    public void welcome(RobotWelcome welcome) {
        try {
            sim.welcomed(welcome);
        } catch (robosim.protocol.ProtocolException e) {
            throw new IllegalStateException("a robot in the Environment's JVM is started with its type", e);
        }
    }

    @Override
    public StepRequest step(long k) {
        owe(k);
        if (!started) {
            started = true;
            sim.link().onYield(this::yielded);
            sim.startControl(control);
        }
        return take();
    }

    @Override
    public StepRequest respond(StepResponse response, long next) {
        // the step due and the response under one hold of the lock: a call the response completes may yield
        // again at once, and its request is built only after the response is applied, by whichever thread
        lock.lock();
        try {
            due = next >= 0 ? next : -1;
            sim.apply(response);
        } finally {
            lock.unlock();
        }
        return next >= 0 ? take() : null;
    }

    @Override
    public void end(SimulationEnd end) {
        owe(-1);
        sim.endedHere(end.reason());
    }

    /** After its end: waits up to {@code ms} for its control code to end; true if it has. */
    boolean awaitControlCode(long ms) throws InterruptedException {
        return sim.awaitControlCode(ms);
    }

    /** {@code NAME: what its control code threw out of run}, or null if it did not (yet). */
    String controlFailure() {
        String failure = sim.controlFailure();
        return failure == null ? null : sim.name() + ": " + failure;
    }

    /** What its control code threw out of run, and when, or null if it did not (yet). */
    ControlFailure failure() {
        return sim.failure();
    }

    String name() {
        return sim.name();
    }

    ParameterAsks parameterAsks() {
        return sim.parameterAsks();
    }

    private void owe(long k) {
        lock.lock();
        try {
            due = k;
        } finally {
            lock.unlock();
        }
    }

    /** The control thread has yielded: it builds the request if its step is due and nobody has. */
    private void yielded() {
        StepRequest request = take();
        if (request != null) {
            environment.request(request);
        }
    }

    /** The request for the step due, if the control code has yielded and nobody has built it yet; else null. */
    private StepRequest take() {
        lock.lock();
        try {
            // only a response sets the control code running again (completing its call), and responses are
            // applied under this lock: the control code stays yielded here
            if (due < 0 || !sim.link().awaitControlFor(0)) {
                return null;
            }
            long k = due;
            due = -1;
            return sim.request(k);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // (the simulation is over for it: its control thread was told)
            return null;
        } finally {
            lock.unlock();
        }
    }
}
