package robosim.hardware;

import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The baton between the control thread and the Hardware Simulator thread. The control thread runs
 * until it makes a blocking call ({@link #execute}); only then does the simulator thread build the
 * next step ({@link #awaitControl}), and it hands the baton back when the call is done
 * ({@link #complete}). So the steps a program takes do not depend on thread timing.
 */
final class ControlLink {
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private Command pending;
    private boolean controlRunning = true;
    private boolean shutdown;
    /** Called on the control thread each time it yields, holding no lock (a robot in the Environment's JVM). */
    private Runnable onYield;

    /**
     * Before the control code starts: {@code hook} runs on the control thread each time the control code
     * yields (blocks in a call or returns), after the simulator side may take over and outside every lock.
     */
    void onYield(Runnable hook) {
        onYield = hook;
    }

    /** Control thread: starts a blocking call and waits until the simulator thread completes it. */
    void execute(Command c) throws InterruptedException {
        lock.lock();
        try {
            if (shutdown) {
                throw new InterruptedException("the simulation is over");
            }
            pending = c;
            controlRunning = false;
            changed.signalAll();
            if (onYield != null) {
                lock.unlock();
                try {
                    onYield.run();
                } finally {
                    lock.lock();
                }
            }
            while (!c.done) {
                if (shutdown) {
                    throw new InterruptedException("the simulation is over");
                }
                changed.await();
            }
        } finally {
            lock.unlock();
        }
    }

    /** Control thread: the control code has returned; from now on the robot idles. */
    void controlFinished() {
        lock.lock();
        try {
            pending = null;
            controlRunning = false;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
        if (onYield != null) {
            onYield.run();
        }
    }

    /** Simulator thread: waits until the control code is blocked or finished; its call, or null. */
    Command awaitControl() throws InterruptedException {
        lock.lock();
        try {
            while (controlRunning && !shutdown) {
                changed.await();
            }
            return pending;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Simulator thread: waits up to {@code nanos} for the control code to block or finish; true if it
     * has (then {@link #awaitControl} returns at once).
     */
    boolean awaitControlFor(long nanos) throws InterruptedException {
        lock.lock();
        try {
            while (controlRunning && !shutdown) {
                if (nanos <= 0) {
                    return false;
                }
                nanos = changed.awaitNanos(nanos);
            }
            return true;
        } finally {
            lock.unlock();
        }
    }

    /** Simulator thread: the call is done; the control thread runs again. */
    void complete(Command c) {
        lock.lock();
        try {
            c.done = true;
            pending = null;
            controlRunning = true;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** True once the simulation is over ({@link #shutdown}). */
    boolean over() {
        lock.lock();
        try {
            return shutdown;
        } finally {
            lock.unlock();
        }
    }

    /** The simulation is over: a blocked or later call throws InterruptedException. */
    void shutdown() {
        lock.lock();
        try {
            shutdown = true;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }
}
