package robosim.rl;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * The threads that step a batch's worlds with its caller: {@code size - 1} helpers ({@code rl-worlds[t]}), each
 * running share t of a step while the caller runs share 0, then waiting for the next step. A step is handed over
 * by a volatile round number, not a queue: a waiting helper spins for {@link #SPIN_NS} (yielding its core to any
 * other thread that wants it) before it parks, since a learner's turn between two steps is tens of microseconds
 * and waking a parked thread costs as much again on a busy machine; a learner that pauses costs a core for that
 * long, no more. The caller waits for its helpers the same way. No lock is held across a wait; the size should
 * not exceed the cores (a helper that spins takes a core from one still stepping).
 */
final class StepCrew implements AutoCloseable {
    /** How long a waiting thread spins before it parks, ns. */
    static final long SPIN_NS = 500_000;
    /** How long a parked caller sleeps before it looks again (its helpers' end wakes it sooner), ns. */
    private static final long CALLER_PARK_NS = 1_000_000;

    /** One share of a step's work. */
    interface Share {
        void run(int share) throws Exception;
    }

    private final Thread[] helpers;
    private final boolean[] parkedFlags;
    private volatile Thread caller;
    private volatile long round;
    private volatile Share work;
    private volatile boolean closed;
    private volatile boolean callerParked;
    private final AtomicInteger pending = new AtomicInteger();
    /** The first failure of a helper in this step, with any later ones suppressed in it. */
    private final AtomicReference<Throwable> failure = new AtomicReference<>();

    StepCrew(int size) {
        this.helpers = new Thread[size - 1];
        this.parkedFlags = new boolean[size - 1];
        for (int t = 0; t < helpers.length; t++) {
            int share = t + 1;
            helpers[t] = new Thread(() -> help(share), "rl-worlds[" + share + "]");
            helpers[t].setDaemon(true);
            helpers[t].start();
        }
    }

    /**
     * Runs share 0 of {@code step} on this thread and the others on the helpers; returns when all are done (an
     * interrupt meanwhile is kept for the caller, not acted on: the helpers are mid-step). One caller at a time.
     *
     * @throws IllegalStateException if the crew is closed
     */
    void run(Share step) throws Exception {
        if (closed) {
            throw new IllegalStateException("the crew is closed");
        }
        caller = Thread.currentThread();
        failure.set(null);
        work = step;
        pending.set(helpers.length);
        round++; // (publishes the work)
        for (int t = 0; t < helpers.length; t++) {
            if (parked(t)) {
                LockSupport.unpark(helpers[t]);
            }
        }
        Throwable own = null;
        try {
            step.run(0);
        } catch (Exception | Error e) {
            own = e;
        }
        awaitHelpers();
        Throwable theirs = failure.get();
        Throwable first = own != null ? own : theirs;
        if (own != null && theirs != null) {
            own.addSuppressed(theirs);
        }
        if (first instanceof Exception e) {
            throw e;
        }
        if (first instanceof Error e) {
            throw e;
        }
    }

    private void awaitHelpers() {
        boolean interrupted = false;
        long start = System.nanoTime();
        while (pending.get() > 0) {
            if (System.nanoTime() - start < SPIN_NS) {
                Thread.yield();
            } else {
                callerParked = true;
                if (pending.get() > 0) {
                    LockSupport.parkNanos(this, CALLER_PARK_NS);
                }
                callerParked = false;
                interrupted |= Thread.interrupted(); // (else park returns at once, and this loop would spin)
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    private boolean parked(int t) {
        synchronized (parkedFlags) {
            return parkedFlags[t];
        }
    }

    private void help(int share) {
        long seen = 0;
        while (true) {
            long start = System.nanoTime();
            while (round == seen) {
                if (closed) {
                    return; // (between steps only: a step handed over is always run, so its caller is not left waiting)
                }
                if (System.nanoTime() - start < SPIN_NS) {
                    Thread.yield();
                } else {
                    synchronized (parkedFlags) {
                        parkedFlags[share - 1] = true;
                    }
                    if (round == seen && !closed) {
                        LockSupport.park(this);
                    }
                    synchronized (parkedFlags) {
                        parkedFlags[share - 1] = false;
                    }
                }
            }
            seen = round;
            try {
                work.run(share);
            } catch (Exception | Error e) {
                if (!failure.compareAndSet(null, e)) {
                    failure.get().addSuppressed(e);
                }
            }
            if (pending.decrementAndGet() == 0 && callerParked) {
                LockSupport.unpark(caller);
            }
        }
    }

    /** The helpers end once they are between steps (one running finishes it first). */
    @Override
    public void close() {
        closed = true;
        for (Thread h : helpers) {
            LockSupport.unpark(h);
        }
    }
}
