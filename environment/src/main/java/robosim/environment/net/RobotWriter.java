package robosim.environment.net;

import robosim.protocol.Printable;
import java.io.IOException;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.protocol.ObjectConnection;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepResponse;

/**
 * {@code TWO_THREADS}: the second thread of a robot, {@code robot-writer[name]}, which writes what the
 * loop queues (a response with the next step number, or the end), in order, so responses go out in
 * parallel and the loop never writes to that socket. A write that fails closes the connection; the
 * robot's reading thread then fails and reports the departure.
 */
final class RobotWriter implements RobotOutput {
    /** What to send next: a response with the next step, or the end alone. */
    private record Outgoing(StepResponse response, long nextStep, SimulationEnd end, boolean midStep) {
    }

    private static final Outgoing STOP = new Outgoing(null, 0, null, false);

    private final RobotConnection robot;
    private final ObjectConnection connection;
    private final boolean stepMessages;
    /** Lock-step: at most one response is ever outstanding, plus the end and the stop. */
    private final BlockingQueue<Outgoing> outgoing = new ArrayBlockingQueue<>(4);
    private final Thread thread;

    RobotWriter(RobotConnection robot, boolean stepMessages) {
        this.robot = robot;
        this.connection = robot.connection();
        this.stepMessages = stepMessages;
        this.thread = new Thread(this::writeLoop, "robot-writer[" + Printable.of(robot.name()) + "]");
        thread.setDaemon(true);
        thread.start();
    }

    @Override
    public void response(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        enqueue(new Outgoing(response, nextStep, end, true));
    }

    @Override
    public void end(SimulationEnd end, boolean midStep) throws IOException {
        enqueue(new Outgoing(null, 0, end, midStep));
    }

    private void enqueue(Outgoing o) throws IOException {
        if (!outgoing.offer(o)) {
            throw new IOException("its writer has fallen behind (" + outgoing.size() + " writes waiting)");
        }
    }

    /** The reading thread is done: lets the writer send what it holds (at most a few seconds), then stops it. */
    @Override
    public void close() throws InterruptedException {
        outgoing.offer(STOP);
        thread.join(TimeUnit.SECONDS.toMillis(5));
        thread.interrupt();
    }

    private void writeLoop() {
        try {
            while (true) {
                Outgoing o = outgoing.take();
                if (o == STOP) {
                    return;
                }
                robot.clock().writing();
                try {
                    if (o.response() == null) {
                        LoopWrites.writeEnd(connection, o.end(), o.midStep());
                    } else {
                        LoopWrites.writeResponse(connection, stepMessages, o.response(), o.nextStep(), o.end());
                    }
                } finally {
                    robot.clock().written();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException | RuntimeException e) {
            robot.drop();
        }
    }
}
