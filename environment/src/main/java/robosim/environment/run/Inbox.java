package robosim.environment.run;

import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The queue through which other threads reach the one thread that owns something (the live run's
 * {@code simulation-loop}, a replay's clock): each event applies itself to the owner on the owner's
 * thread, and knows how it is refused when the owner is gone or too busy, so whoever waits on its answer is
 * always answered. Bounded; a post waits at most {@code postLimitMs} for room, then is refused. Once
 * {@link #close}d every event still queued, and every one posted later, is refused, each exactly once.
 *
 * @param <T> what the events act on
 */
public final class Inbox<T> {
    /** Something another thread asks of the owner. */
    public interface Event<T> {
        /** On the owner's thread: does what was asked. */
        void apply(T owner);

        /** Any thread: the owner will not do it (it is gone, or its queue stayed full); answers the asker. */
        void refuse();
    }

    private final BlockingQueue<Event<T>> queue;
    private final long postLimitMs;
    private volatile boolean closed;

    public Inbox(int capacity, long postLimitMs) {
        this.queue = new ArrayBlockingQueue<>(capacity);
        this.postLimitMs = postLimitMs;
    }

    /**
     * Any thread: hands {@code event} to the owner, waiting at most the post limit for room; refuses it if
     * the inbox is closed or stays full. False if it was refused.
     */
    public boolean post(Event<T> event) {
        if (closed) {
            event.refuse();
            return false;
        }
        try {
            if (!queue.offer(event, postLimitMs, TimeUnit.MILLISECONDS)) {
                event.refuse();
                return false;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            event.refuse();
            return false;
        }
        if (closed) {
            refuseQueued(); // (closed while it went in: nobody will take it)
        }
        return true;
    }

    /** The owner: the next event, waiting for one up to {@code nanos}; null if none came. */
    public Event<T> poll(long nanos) throws InterruptedException {
        return queue.poll(nanos, TimeUnit.NANOSECONDS);
    }

    /** The owner: the next event, waiting for one as long as it takes. */
    public Event<T> take() throws InterruptedException {
        return queue.take();
    }

    /** The owner: the next event if one is queued, else null. */
    public Event<T> poll() {
        return queue.poll();
    }

    /** Events queued now. */
    public int size() {
        return queue.size();
    }

    /** The owner, at its end: refuses what is queued; every later post is refused. */
    public void close() {
        closed = true;
        refuseQueued();
    }

    public boolean closed() {
        return closed;
    }

    private void refuseQueued() {
        for (Event<T> e; (e = queue.poll()) != null; ) {
            e.refuse();
        }
    }
}
