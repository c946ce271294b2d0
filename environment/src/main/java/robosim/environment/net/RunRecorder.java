package robosim.environment.net;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingWriter;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/**
 * Records a run ({@code --record FILE}) on its own {@code recorder} thread: the loop hands it each step's
 * viewer update, requests and responses (immutable, shared) through a queue of {@link #QUEUE} steps and goes on; the
 * thread writes them ({@link RecordingWriter}) and hands the file to the operating system whenever it has
 * caught up, so a killed Environment leaves every step it wrote whole. Nothing is dropped: should the disk
 * fall a whole queue behind, the loop waits for it (said in the log). A write that fails stops the
 * recording with a logged error; the run goes on.
 */
final class RunRecorder {
    private static final Logger LOG = LoggerFactory.getLogger(RunRecorder.class);
    /** Steps the loop may be ahead of the disk. */
    static final int QUEUE = 4096;

    private record Step(PoseUpdate update, StepRequest[] requests, StepResponse[] responses) {
    }

    private final Path file;
    private final RecordingWriter writer;
    private final BlockingQueue<Object> queue = new ArrayBlockingQueue<>(QUEUE);
    private final Thread thread;
    private volatile boolean failed;
    private boolean toldFull;

    /** Creates the file (it must not exist) and starts the {@code recorder} thread. */
    RunRecorder(Path file, WorldSnapshot start) throws IOException {
        this.file = file;
        this.writer = new RecordingWriter(file);
        try {
            writer.snapshot(start);
            writer.flush();
        } catch (IOException | RuntimeException e) {
            writer.close();
            throw e;
        }
        thread = new Thread(this::write, "recorder");
        thread.setDaemon(true);
        thread.start();
    }

    /** Loop thread: one released step. */
    void step(WorldSnapshot roster, PoseUpdate update, StepRequest[] requests, StepResponse[] responses) {
        if (roster != null) {
            hand(roster);
        }
        hand(new Step(update, requests, responses));
    }

    /** Loop thread: the end; the thread finishes the file and ends. */
    void end(SimulationEnd end) {
        hand(end);
    }

    private void hand(Object item) {
        if (failed) {
            return;
        }
        if (!queue.offer(item)) {
            if (!toldFull) {
                toldFull = true;
                LOG.warn("recording {}: the disk is {} steps behind; the run waits for it", file, QUEUE);
            }
            try {
                queue.put(item);
            } catch (InterruptedException e) { // (the loop is being stopped: the end says the rest)
                Thread.currentThread().interrupt();
            }
        }
    }

    /** False once a write has failed: the loop then hands nothing more. */
    boolean recording() {
        return !failed;
    }

    /** Waits up to {@code ms} for the file to be finished (after {@link #end}); logs it if it is not. */
    void awaitWritten(long ms) throws InterruptedException {
        thread.join(ms);
        if (thread.isAlive()) {
            LOG.warn("recording {} was not finished within {} ms of the end; its last steps may be missing", file, ms);
        }
    }

    private void write() {
        try (writer) {
            while (true) {
                Object item = queue.take();
                if (item instanceof Step s) {
                    writer.step(s.update(), s.requests(), s.responses());
                } else if (item instanceof WorldSnapshot roster) {
                    writer.roster(roster);
                } else {
                    writer.end((SimulationEnd) item);
                    LOG.info("recording {}: {} steps written", file, writer.steps());
                    return;
                }
                if (queue.isEmpty()) {
                    writer.flush();
                }
            }
        } catch (InterruptedException e) {
            stopped("interrupted");
            Thread.currentThread().interrupt();
        } catch (Throwable e) { // (whatever it is, the loop must never wait for this thread again)
            stopped(e.toString());
        }
    }

    private void stopped(String why) {
        failed = true;
        queue.clear(); // (a loop waiting on a full queue goes on)
        LOG.error("recording {} stopped after {} steps: {}", file, writer.steps(), why);
    }
}
