package robosim.environment.replay;

import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;

/**
 * The questions other threads put to the {@link ReplayClock}, each answered on its thread: bounded (one
 * more than {@link #CAPACITY} waiting is refused as busy), and once the clock has gone every question is
 * answered that the replay has ended, none left waiting.
 */
final class ClockInbox {
    static final int CAPACITY = 1024;

    private final BlockingQueue<Runnable> inbox = new ArrayBlockingQueue<>(CAPACITY);
    private final CountDownLatch closed = new CountDownLatch(1);

    /** Any thread: {@code action} will run on the clock's thread, given the time then (ns); its answer. */
    <T> CompletableFuture<T> ask(LongFunction<T> action) {
        CompletableFuture<T> answer = new CompletableFuture<>();
        Runnable r = () -> {
            try {
                answer.complete(action.apply(System.nanoTime()));
            } catch (RuntimeException e) {
                answer.completeExceptionally(e);
            }
        };
        if (!inbox.offer(r)) {
            answer.completeExceptionally(new IllegalStateException("the replay is busy; try again"));
        } else if (closed.getCount() == 0 && inbox.remove(r)) { // (the clock has gone: nobody would answer)
            answer.completeExceptionally(new IllegalStateException("the replay has ended"));
        }
        return answer;
    }

    /** Any thread: wakes the clock. */
    void wake() {
        inbox.offer(() -> { });
    }

    /** The clock's thread: runs the next question, waiting for one up to {@code nanos}. */
    void runNext(long nanos) throws InterruptedException {
        Runnable r = inbox.poll(nanos, TimeUnit.NANOSECONDS);
        if (r != null) {
            r.run();
        }
    }

    /** The clock's thread, at its end: answers what is left; later questions are told it has ended. */
    void close() {
        closed.countDown();
        for (Runnable r; (r = inbox.poll()) != null; ) {
            r.run();
        }
    }

    boolean awaitClosed(long ms) throws InterruptedException {
        return closed.await(ms, TimeUnit.MILLISECONDS);
    }
}
