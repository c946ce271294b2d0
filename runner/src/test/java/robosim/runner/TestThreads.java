package robosim.runner;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Threads for tests' robots by hand, which block in socket reads: a thread each, never the common pool
 * (whose few threads, on a machine with more cores, a blocked robot would hold while another waits to run).
 */
final class TestThreads {
    private static final AtomicInteger SERIAL = new AtomicInteger();

    /** A new thread for each task, named {@code test-robot-N}, daemon. */
    static final ExecutorService ROBOTS = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "test-robot-" + SERIAL.incrementAndGet());
        t.setDaemon(true);
        return t;
    });

    private TestThreads() {
    }
}
