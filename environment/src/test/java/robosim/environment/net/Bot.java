package robosim.environment.net;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Test fixture: a robot without a socket, driven by a {@link Hand}, whose place in the world the run assigns (a
 * file's robot, one that joins, one that takes over). It answers each step it is given by posting its request -
 * queued, as over a socket, so nothing depends on timing - until step {@code silentFrom} (from which it says
 * nothing), and at step {@code leaveAt} posts that its connection closed instead.
 */
final class Bot implements RobotPeer {
    static final long NEVER = Long.MAX_VALUE;

    final String name;
    private final Hand hand;
    private final long leaveAt;
    private final long silentFrom;
    private int index = -1;
    RobotWelcome welcome;
    /** The first step it was given (-1 before). */
    long firstStep = -1;
    final List<StepResponse> responses = new ArrayList<>();
    SimulationEnd end;
    private boolean closed;
    private boolean dropped;

    Bot(Hand hand, String name, long leaveAt, long silentFrom) {
        this.hand = hand;
        this.name = name;
        this.leaveAt = leaveAt;
        this.silentFrom = silentFrom;
    }

    Bot(Hand hand, String name) {
        this(hand, name, NEVER, NEVER);
    }

    /** Says hello (as the file's robot {@code fileIndex}, or -1 for one that is not in the file); its verdict, once drained. */
    CompletableFuture<String> hello(int fileIndex) {
        CompletableFuture<String> verdict = new CompletableFuture<>();
        hand.post(new LoopEvent.HellosCome(Hellos.of(new Hellos.Hello(this, new RobotHello(name, RobotModels.AR_ROBOT),
                fileIndex, verdict))));
        return verdict;
    }

    /** Its connection closes now. */
    void leave(String why) {
        closed = true;
        hand.post(new LoopEvent.RobotLeaves(this, why));
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
        hand.post(new LoopEvent.Request(this, new StepRequest(k, 100, 0, false, List.of(), List.of())));
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
