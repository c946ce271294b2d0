package robosim.environment.run;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Test fixture: a robot without a socket, whose place in the world the run assigns (a file's robot, one that joins,
 * one that takes over). It answers each step it is given by posting its request (to a {@link Hand}'s queue, or a
 * loop's inbox: queued, as over a socket, so nothing depends on timing) until step {@code silentFrom}, from which it
 * says nothing, and at step {@code leaveAt} posts that its connection closed instead. The run calls it on the thread
 * that drives it; a test may read what it got from its own.
 */
final class Bot implements RobotPeer {
    static final long NEVER = Long.MAX_VALUE;

    final String name;
    private final Consumer<LoopEvent> post;
    private final long leaveAt;
    private final long silentFrom;
    private volatile int index = -1;
    volatile RobotWelcome welcome;
    /** The first step it was given (-1 before). */
    volatile long firstStep = -1;
    final List<StepResponse> responses = new CopyOnWriteArrayList<>();
    volatile SimulationEnd end;
    private volatile boolean closed;
    private volatile boolean dropped;
    /** The plug-in sensors it asks to read every step. */
    private volatile List<String> reads = List.of();

    Bot(Consumer<LoopEvent> post, String name, long leaveAt, long silentFrom) {
        this.post = post;
        this.name = name;
        this.leaveAt = leaveAt;
        this.silentFrom = silentFrom;
    }

    Bot(Hand hand, String name, long leaveAt, long silentFrom) {
        this(hand::post, name, leaveAt, silentFrom);
    }

    Bot(Hand hand, String name) {
        this(hand::post, name, NEVER, NEVER);
    }

    /** From now on it asks to read these plug-in sensors every step. */
    Bot reads(String... sensors) {
        reads = List.of(sensors);
        return this;
    }

    /** Says hello (as the file's robot {@code fileIndex}, or -1 for one that is not in the file); its verdict, once drained. */
    CompletableFuture<String> hello(int fileIndex) {
        CompletableFuture<String> verdict = new CompletableFuture<>();
        post.accept(new LoopEvent.HellosCome(Hellos.of(new Hellos.Hello(this, new RobotHello(name, robosim.devices.RobotTypes.properties("ArRobot")),
                fileIndex, verdict))));
        return verdict;
    }

    /** Its connection closes now. */
    void leave(String why) {
        closed = true;
        post.accept(new LoopEvent.RobotLeaves(this, why));
    }

    @Override
    public int index() {
        return index;
    }

    @Override
    public void assign(int i) {
        index = i;
    }

    @Override
    public void welcome(RobotWelcome w) {
        welcome = w;
    }

    @Override
    public void begin(long first) {
        firstStep = first;
        answer(first);
    }

    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd e) {
        responses.add(response);
        if (e != null) {
            end = e;
        } else {
            answer(nextStep);
        }
    }

    private void answer(long k) {
        if (closed || dropped || k >= silentFrom) {
            return;
        }
        if (k == leaveAt) {
            leave("its connection closed at step " + k);
            return;
        }
        post.accept(new LoopEvent.Request(this, new StepRequest(k, 100, 0, false, List.of(), reads)));
    }

    @Override
    public void end(SimulationEnd e, boolean midStep) {
        end = e;
    }

    @Override
    public boolean begun() {
        return firstStep >= 0;
    }

    @Override
    public boolean closed() {
        return closed || dropped;
    }

    @Override
    public void drop() {
        dropped = true;
    }

    boolean dropped() {
        return dropped;
    }
}
