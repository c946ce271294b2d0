import java.util.Locale;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The floor of the one-JVM shape: the hand-off between the simulation loop and N robots' blocking control code, with
 * nothing else. As in a one-JVM run (environment/.../run/SimulationLoop, InMemoryTransport, hardware/ControlLink),
 * each robot's control code runs on a thread of its own and blocks in each call on its baton (a ReentrantLock and
 * its Condition); the loop gives every robot its step (completes its call), the control code makes its decision
 * (WORK_NS of arithmetic) and blocks in its next call, and the robot whose request is the last one owed posts a
 * wake into the loop's inbox (an ArrayBlockingQueue, on which the loop waits); the loop then does its own work for
 * each request (LOOP_NS a robot) and gives the next step. Every robot must see every step once, in order (checked).
 * Modes: platform (loop and control on platform threads), virtual (control on virtual threads, the loop a platform
 * thread), virtual-loop (both virtual: run with -Djdk.virtualThreadScheduler.parallelism=1 for the one-carrier
 * shape a one-JVM run takes), inline (the decisions made on the loop's thread: the limit, no hand-off).
 * usage: java [-Djdk.virtualThreadScheduler.parallelism=1] bench/FloorHandoff.java N STEPS MODE
 * Prints one line: robots=N steps=S mode=M wall=Ws steps/s=R robot-steps/s=R.
 */
public class FloorHandoff {
    /** The decision's and the loop's share of work, in rounds of a xorshift the JIT cannot fold (about 1.6 ns each). */
    static final int WORK = 185;
    static final int LOOP_WORK = 1230;

    static long work(long x, int rounds) {
        for (int i = 0; i < rounds; i++) {
            x ^= x << 13;
            x ^= x >>> 7;
            x ^= x << 17;
        }
        return x;
    }

    /** One robot's baton: its control thread waits in a call until the loop gives its step. */
    static final class Robot {
        final ReentrantLock lock = new ReentrantLock();
        final Condition given = lock.newCondition();
        long step; // the step given (guarded by lock)
        long seen; // the last step its control code decided on (its thread's)
        volatile long request;
        volatile long requestFor;
    }

    static Robot[] robots;
    static final ArrayBlockingQueue<Object> INBOX = new ArrayBlockingQueue<>(1024);
    static final AtomicInteger OWED = new AtomicInteger();
    static final Object WAKE = new Object();
    static volatile String failure;

    /** The control code of robot i: decides on each step it is given, then blocks in its next call. */
    static void control(int i, long steps) {
        Robot r = robots[i];
        try {
            for (long k = 1; k <= steps; k++) {
                r.lock.lock();
                try {
                    while (r.step < k) {
                        r.given.await();
                    }
                } finally {
                    r.lock.unlock();
                }
                decide(r, k, i);
                if (OWED.decrementAndGet() == 0) {
                    INBOX.put(WAKE);
                }
            }
        } catch (InterruptedException e) {
            failure = "robot " + i + " interrupted";
        }
    }

    static void decide(Robot r, long k, int i) {
        if (k != r.seen + 1) {
            failure = "robot " + i + " saw step " + k + " after " + r.seen;
        }
        r.seen = k;
        r.request = work(k * 0x9E3779B97F4A7C15L + i + 1, WORK);
        r.requestFor = k;
    }

    static long loop(long steps, boolean inline) throws InterruptedException {
        long acc = 0;
        for (long k = 1; k <= steps; k++) {
            if (inline) {
                for (int i = 0; i < robots.length; i++) {
                    decide(robots[i], k, i);
                }
            } else {
                OWED.set(robots.length);
                for (Robot r : robots) {
                    r.lock.lock();
                    try {
                        r.step = k;
                        r.given.signal();
                    } finally {
                        r.lock.unlock();
                    }
                }
                if (INBOX.poll(60, TimeUnit.SECONDS) == null) {
                    throw new IllegalStateException("no wake within 60 s at step " + k);
                }
            }
            for (int i = 0; i < robots.length; i++) {
                if (robots[i].requestFor != k) {
                    failure = "the loop found no request of robot " + i + " for step " + k;
                }
                acc = work(acc ^ robots[i].request, LOOP_WORK);
            }
        }
        return acc;
    }

    static Thread thread(boolean virtual, String name, Runnable body) throws ReflectiveOperationException {
        if (!virtual) {
            Thread t = new Thread(body, name);
            t.setDaemon(true);
            return t;
        }
        Object builder = Thread.class.getMethod("ofVirtual").invoke(null);
        builder = Class.forName("java.lang.Thread$Builder").getMethod("name", String.class).invoke(builder, name);
        return (Thread) Class.forName("java.lang.Thread$Builder").getMethod("unstarted", Runnable.class)
                .invoke(builder, body);
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 3 || !args[2].matches("platform|virtual|virtual-loop|inline")) {
            System.err.println("usage: java [-Djdk.virtualThreadScheduler.parallelism=1] bench/FloorHandoff.java N STEPS "
                    + "platform|virtual|virtual-loop|inline");
            System.exit(2);
        }
        int n = Integer.parseInt(args[0]);
        long steps = Long.parseLong(args[1]);
        String mode = args[2];
        robots = new Robot[n];
        for (int i = 0; i < n; i++) {
            robots[i] = new Robot();
        }
        boolean inline = mode.equals("inline");
        boolean virtualControl = mode.startsWith("virtual");
        if (!inline) {
            for (int i = 0; i < n; i++) {
                int id = i;
                thread(virtualControl, "control[" + i + "]", () -> control(id, steps)).start();
            }
        }
        long[] result = new long[2];
        Runnable body = () -> {
            try {
                long t0 = System.nanoTime();
                result[1] = loop(steps, inline);
                result[0] = System.nanoTime() - t0;
            } catch (InterruptedException e) {
                failure = "the loop was interrupted";
            }
        };
        Thread loop = thread(mode.equals("virtual-loop"), "loop", body);
        loop.start();
        loop.join();
        for (Robot r : robots) {
            if (r.seen != steps && failure == null) {
                failure = "a robot saw " + r.seen + " of " + steps + " steps";
            }
        }
        if (failure != null) {
            System.out.println("FAILED: " + failure);
            System.exit(1);
        }
        double s = result[0] / 1e9;
        System.out.println(String.format(Locale.ROOT, "robots=%d steps=%d mode=%s wall=%.3fs steps/s=%.1f "
                + "robot-steps/s=%.1f (check %x)", n, steps, mode, s, steps / s, n * steps / s, result[1] & 0xfff));
    }
}
