package robosim.rl;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * The threads that step a batch's worlds with its caller: {@code size - 1} helpers ({@code rl-worlds[t]}), each
 * running share t of a step while the caller runs share 0, then waiting for the next step. A step is handed over
 * by a volatile round number, not a queue: a helper spins for {@link #SPIN_NS} before it parks (a learner's turn
 * between two steps is tens of microseconds, and waking a parked thread costs as much again on a busy machine), so
 * a learner that pauses costs a core for that long, no more. The caller spins for its helpers the same way. No lock.
 */
final class StepCrew implements AutoCloseable {
    /** How long a waiting thread spins before it parks, ns. */
    static final long SPIN_NS = 500_000;

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
    private volatile Throwable failure;

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

    /** Runs share 0 of {@code step} on this thread and the others on the helpers; returns when all are done. */
    void run(Share step) throws Exception {
        caller = Thread.currentThread();
        failure = null;
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
        long start = System.nanoTime();
        while (pending.get() > 0) {
            if (System.nanoTime() - start < SPIN_NS) {
                Thread.onSpinWait();
            } else {
                callerParked = true;
                if (pending.get() > 0) {
                    LockSupport.park(this);
                }
                callerParked = false;
            }
        }
        Throwable first = own != null ? own : failure;
        if (first instanceof Exception e) {
            throw e;
        }
        if (first instanceof Error e) {
            throw e;
        }
    }

    private boolean parked(int t) {
        synchronized (parkedFlags) {
            return parkedFlags[t];
        }
    }

    private void help(int share) {
        long seen = 0;
        while (!closed) {
            long start = System.nanoTime();
            while (round == seen && !closed) {
                if (System.nanoTime() - start < SPIN_NS) {
                    Thread.onSpinWait();
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
            if (closed) {
                return;
            }
            seen = round;
            try {
                work.run(share);
            } catch (Exception | Error e) {
                failure = e;
            }
            if (pending.decrementAndGet() == 0 && callerParked) {
                LockSupport.unpark(caller);
            }
        }
    }

    @Override
    public void close() {
        closed = true;
        for (Thread h : helpers) {
            LockSupport.unpark(h);
        }
    }
}
