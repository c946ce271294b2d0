package robosim.environment.net;

import robosim.environment.run.HelloCheck;
import robosim.environment.run.Hellos;
import robosim.environment.run.LoopEvent;
import robosim.environment.run.LoopHook;
import robosim.environment.run.Run;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import robosim.protocol.InMemoryLink;
import robosim.protocol.StepRequest;

/**
 * The transport of a run's robots in the Environment's JVM ({@code --one-jvm}): it starts each robot (its
 * Hardware Simulator and control class, through the {@link InMemoryLink.Starter} of the {@link Settings}, an
 * {@link InMemoryPeer} to the loop) and carries their requests to the loop, its {@link LoopHook}: at most one wake
 * of the loop per step, however many robots. A request built at once, as the loop gives the step, waits in a list
 * of the loop's own and is handed in once the run has moved on as far as it can; a request built on a control
 * thread goes into a queue, and the count of requests still owed tells the thread that brings the last one to wake
 * the loop ({@link LoopEvent.Wake}). While the loop gives steps it holds the count open itself, so the count
 * reaches zero only once, when everything is in. Before the loop judges its deadlines it takes what has come, so a
 * robot whose control code does not yield is judged alone.
 */
final class InMemoryTransport implements LoopHook {
    private final InMemoryLink.Starter starter;
    private final HelloCheck check;
    private final Consumer<LoopEvent> loop;
    /** Requests owed, plus one while the loop holds the count open. */
    private final AtomicInteger owed = new AtomicInteger();
    private final ConcurrentLinkedQueue<LoopEvent.Request> arrived = new ConcurrentLinkedQueue<>();
    /** Loop thread only: requests built as the loop gave their steps. */
    private final List<LoopEvent.Request> ready = new ArrayList<>();
    /** Loop thread only: the loop holds the count open. */
    private boolean holding;

    /** Starts robots with {@code starter}, checks their hellos with {@code check}; {@code loop} posts an event to the loop. */
    InMemoryTransport(InMemoryLink.Starter starter, HelloCheck check, Consumer<LoopEvent> loop) {
        this.starter = starter;
        this.check = check;
        this.loop = loop;
    }

    /**
     * Any thread holding no lock (the control class's constructor runs here): starts robot {@code name}, a
     * {@code type}, with control class {@code control}, and says its hello. Returns the loop's verdict (null:
     * welcomed, else why not).
     *
     * @throws IllegalArgumentException why it cannot start (its type, its control class, the hello's check)
     */
    CompletableFuture<String> start(String name, String type, String control) {
        InMemoryPeer peer = new InMemoryPeer(this, name);
        peer.attach(starter.start(name, type, control, peer));
        HelloCheck.Checked checked = check.admit(peer.hello());
        if (checked.refusal() != null) {
            throw new IllegalArgumentException(checked.refusal());
        }
        CompletableFuture<String> verdict = new CompletableFuture<>();
        loop.accept(new LoopEvent.HellosCome(Hellos.of(new Hellos.Hello(peer, checked.hello(), checked.index(),
                verdict))));
        return verdict;
    }

    /**
     * After the end: waits up to {@code ms} for the robots' control code to end; whose threw, whose still runs.
     */
    InMemoryLink.ControlEnd awaitControlCode(long ms) throws InterruptedException {
        return starter.awaitControlCode(ms);
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
        if (request != null && settled(peer)) {
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
            loop.accept(new LoopEvent.Wake());
        }
    }

    /** Loop thread: {@code peer} has ended; it owes nothing more. */
    void forgive(InMemoryPeer peer) {
        if (peer.owes.compareAndSet(true, false) && owed.decrementAndGet() == 0) {
            loop.accept(new LoopEvent.Wake()); // (what has come, from the others, is handed in)
        }
    }

    private boolean settled(InMemoryPeer peer) {
        if (peer.owes.compareAndSet(true, false)) {
            owed.decrementAndGet(); // (the loop holds the count open: it does not reach zero here)
            return true;
        }
        return false;
    }

    /**
     * Loop thread, once the run has moved on as far as it can: hands in the requests built at once, lets go of
     * the count and, if nothing is owed (or the deadlines are about to be judged), what came from control threads.
     * True if it handed in any.
     */
    @Override
    public boolean handIn(Run run, boolean deadline) {
        boolean any = !ready.isEmpty();
        for (int i = 0; i < ready.size(); i++) {
            ready.get(i).apply(run);
        }
        ready.clear();
        if (holding) {
            holding = false;
            owed.decrementAndGet();
        }
        if (deadline || owed.get() == 0) {
            for (LoopEvent.Request r; (r = arrived.poll()) != null; ) {
                r.apply(run);
                any = true;
            }
        }
        return any;
    }

    /** Loop thread: requests built at once wait to be handed in, or the count is held open (settle soon). */
    @Override
    public boolean pending() {
        return holding || !ready.isEmpty();
    }
}
