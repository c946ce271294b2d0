package robosim.environment.replay;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import robosim.environment.run.Inbox;

/**
 * The questions other threads put to the {@link ReplayClock}, each answered on its thread, through the same
 * {@link Inbox} as the live run's loop: bounded (one more than {@link #CAPACITY} waiting is refused as
 * busy), and once the clock has gone every question is answered that the replay has ended, none left
 * waiting.
 */
final class ClockInbox {
    static final int CAPACITY = 1024;

    private final Inbox<Void> inbox = new Inbox<>(CAPACITY, 0);
    private final CountDownLatch closed = new CountDownLatch(1);

    /** A question: its action runs on the clock's thread, given the time then (ns). */
    private final class Question<T> implements Inbox.Event<Void> {
        private final LongFunction<T> action;
        private final CompletableFuture<T> answer = new CompletableFuture<>();

        Question(LongFunction<T> action) {
            this.action = action;
        }

        @Override
        public void apply(Void owner) {
            try {
                answer.complete(action.apply(System.nanoTime()));
            } catch (RuntimeException e) {
                answer.completeExceptionally(e);
            }
        }

        @Override
        public void refuse() {
            answer.completeExceptionally(new IllegalStateException(inbox.closed() ? "the replay has ended"
                    : "the replay is busy; try again"));
        }
    }

    /** Any thread: {@code action} will run on the clock's thread, given the time then (ns); its answer. */
    <T> CompletableFuture<T> ask(LongFunction<T> action) {
        Question<T> q = new Question<>(action);
        inbox.post(q);
        return q.answer;
    }

    /** Any thread: wakes the clock. */
    void wake() {
        ask(now -> null);
    }

    /** The clock's thread: runs the next question, waiting for one up to {@code nanos}. */
    void runNext(long nanos) throws InterruptedException {
        Inbox.Event<Void> q = inbox.poll(nanos);
        if (q != null) {
            q.apply(null);
        }
    }

    /** The clock's thread, at its end: answers what is queued; later questions are told it has ended. */
    void close() {
        for (Inbox.Event<Void> q; (q = inbox.poll()) != null; ) {
            q.apply(null);
        }
        inbox.close();
        closed.countDown();
    }

    boolean awaitClosed(long ms) throws InterruptedException {
        return closed.await(ms, TimeUnit.MILLISECONDS);
    }
}
