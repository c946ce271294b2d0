package robosim.environment.net;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import robosim.protocol.StepRequest;

/**
 * The requests of a run's robots in the Environment's JVM ({@link InMemoryPeer}), on their way to the loop:
 * at most one wake of the loop per step, however many robots. A request built at once, as the loop gives
 * the step, waits in a list of the loop's own and is applied once the loop has moved on as far as it can;
 * a request built on a control thread goes into a queue, and the count of requests still owed tells the
 * thread that brings the last one to wake the loop ({@link LoopEvent.InMemoryArrived}). While the loop gives
 * steps it holds the count open itself, so the count reaches zero only once, when everything is in. At each
 * deadline check the loop takes what has come, so a robot whose control code does not yield is judged
 * alone.
 */
final class InMemoryRequests {
    private final Consumer<LoopEvent> loop;
    /** Requests owed, plus one while the loop holds the count open. */
    private final AtomicInteger owed = new AtomicInteger();
    private final ConcurrentLinkedQueue<LoopEvent.Request> arrived = new ConcurrentLinkedQueue<>();
    /** Loop thread only: requests built as the loop gave their steps. */
    private final List<LoopEvent.Request> ready = new ArrayList<>();
    /** Loop thread only: the loop holds the count open. */
    private boolean holding;

    /** @param loop posts an event to the loop */
    InMemoryRequests(Consumer<LoopEvent> loop) {
        this.loop = loop;
    }

    /** Loop thread, before giving {@code peer} a step: one more request owed. */
    void owe(InMemoryPeer peer) {
        if (!holding) {
            holding = true;
            owed.incrementAndGet();
        }
        peer.owes.set(true);
        owed.incrementAndGet();
    }

    /** Loop thread, having given {@code peer} its step: its request, if it was built at once. */
    void given(InMemoryPeer peer, StepRequest request) {
        if (request != null && settle(peer)) {
            ready.add(new LoopEvent.Request(peer, request));
        }
    }

    /** A control thread: {@code peer}'s request; the last one owed wakes the loop. */
    void arrived(InMemoryPeer peer, StepRequest request) {
        if (!peer.owes.compareAndSet(true, false)) {
            return; // (it was dropped or ended meanwhile)
        }
        arrived.add(new LoopEvent.Request(peer, request));
        if (owed.decrementAndGet() == 0) {
            loop.accept(new LoopEvent.InMemoryArrived());
        }
    }

    /** Loop thread: {@code peer} has ended; it owes nothing more. */
    void forgive(InMemoryPeer peer) {
        if (peer.owes.compareAndSet(true, false) && owed.decrementAndGet() == 0) {
            loop.accept(new LoopEvent.InMemoryArrived()); // (what has come, from the others, is applied)
        }
    }

    private boolean settle(InMemoryPeer peer) {
        if (peer.owes.compareAndSet(true, false)) {
            owed.decrementAndGet(); // (the loop holds the count open: it does not reach zero here)
            return true;
        }
        return false;
    }

    /**
     * Loop thread, once it has moved on as far as it can: applies the requests built at once, lets go of
     * the count and, if nothing is owed, applies what came from control threads. True if it applied any.
     */
    boolean settle(Run run) {
        boolean any = !ready.isEmpty();
        for (int i = 0; i < ready.size(); i++) {
            ready.get(i).apply(run);
        }
        ready.clear();
        if (holding) {
            holding = false;
            if (owed.decrementAndGet() == 0) {
                any |= take(run);
            }
        }
        return any;
    }

    /** Loop thread: requests built at once wait to be applied, or the count is held open (settle soon). */
    boolean pending() {
        return holding || !ready.isEmpty();
    }

    /** Loop thread: applies every request that has come from a control thread; true if there was one. */
    boolean take(Run run) {
        boolean any = false;
        for (LoopEvent.Request r; (r = arrived.poll()) != null; ) {
            r.apply(run);
            any = true;
        }
        return any;
    }
}
