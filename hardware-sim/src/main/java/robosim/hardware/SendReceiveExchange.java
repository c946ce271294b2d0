package robosim.hardware;

import java.io.IOException;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * {@code SEND_RECEIVE}, the report's untested two-thread Hardware Simulator: the calling thread sends
 * each request, a {@code receiver[name]} thread reads and applies each response. They take turns
 * through two one-element queues: "sent" (true: a request went out, read its response; false: stop)
 * and "received" (true: go on; false: the simulation is over or the receiver failed).
 */
final class SendReceiveExchange {
    private SendReceiveExchange() {
    }

    /** Runs {@code sim}'s exchange until its simulation is over. */
    static void run(HardwareSimulator sim) throws IOException, InterruptedException {
        BlockingQueue<Boolean> sent = new ArrayBlockingQueue<>(1);
        BlockingQueue<Boolean> received = new ArrayBlockingQueue<>(1);
        Throwable[] failure = new Throwable[1];
        Thread receiver = new Thread(() -> {
            try {
                while (sent.take()) {
                    received.put(sim.receive());
                }
            } catch (IOException | RuntimeException | InterruptedException e) {
                failure[0] = e;
                received.offer(false);
            }
        }, "receiver[" + sim.name() + "]");
        receiver.setDaemon(true);
        receiver.start();
        try {
            do {
                sim.send();
                sent.put(true);
            } while (received.take());
        } finally {
            sent.offer(false);
            receiver.join(TimeUnit.SECONDS.toMillis(5));
            receiver.interrupt();
        }
        if (failure[0] instanceof IOException e) {
            throw e;
        } else if (failure[0] instanceof RuntimeException e) {
            throw e;
        }
    }
}
