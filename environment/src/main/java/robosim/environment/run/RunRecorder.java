package robosim.environment.run;

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
 * Records a run ({@code --record FILE}) on its own {@code recorder} thread, a {@link ReleaseListener} of the run:
 * it opens the file as the run begins, from the world as a viewer would get it, then the loop hands it each
 * released step's viewer update, requests and responses (immutable, shared) through a queue of {@link #QUEUE}
 * steps and goes on; the thread writes them ({@link RecordingWriter}) and hands the file to the operating system
 * whenever it has caught up, so a killed Environment leaves every step it wrote whole. Nothing is dropped: should
 * the disk fall a whole queue behind, the loop waits for it (said in the log). A file that cannot be made, or a
 * write that fails, stops the recording with a logged error; the run goes on.
 */
public final class RunRecorder implements ReleaseListener {
    private static final Logger LOG = LoggerFactory.getLogger(RunRecorder.class);
    /** Steps the loop may be ahead of the disk. */
    static final int QUEUE = 4096;

    private record Step(PoseUpdate update, StepRequest[] requests, StepResponse[] responses) {
    }

    private final Path file;
    private final BlockingQueue<Object> queue = new ArrayBlockingQueue<>(QUEUE);
    /** The file's writer and thread, once the run has begun. */
    private volatile RecordingWriter writer;
    private volatile Thread thread;
    private volatile boolean failed;
    private boolean toldFull;
    private final boolean readings;

    /**
     * Records into {@code file}, which must not exist, once the run begins; {@code readings} false: without the
     * robots' sensor readings ({@link RecordingWriter}).
     */
    public RunRecorder(Path file, boolean readings) {
        this.file = file;
        this.readings = readings;
    }

    /** Loop thread: creates the file (it must not exist) and starts the {@code recorder} thread. */
    @Override
    public void begun(WorldSnapshot start) {
        RecordingWriter w;
        try {
            w = new RecordingWriter(file, readings);
        } catch (IOException | RuntimeException e) {
            cannot(e);
            return;
        }
        try {
            w.snapshot(start);
            w.flush();
        } catch (IOException | RuntimeException e) {
            try {
                w.close();
            } catch (IOException ignored) {
                // it failed already
            }
            cannot(e);
            return;
        }
        writer = w;
        Thread t = new Thread(this::write, "recorder");
        t.setDaemon(true);
        thread = t;
        t.start();
    }

    private void cannot(Exception e) {
        failed = true;
        LOG.error("cannot record into {}: {}", file, e.toString());
    }

    /** Loop thread: one released step (the world it grew to first, if robots joined). */
    @Override
    public void released(ReleasedWorld world, ReleaseListener.Step step) {
        if (failed || writer == null) {
            return;
        }
        int n = world.robots();
        StepRequest[] asked = new StepRequest[n];
        StepResponse[] responses = new StepResponse[n];
        for (int i = 0; i < n; i++) {
            if (step.tookPart(i)) {
                asked[i] = step.request(i);
                responses[i] = step.response(i);
            }
        }
        if (world.grown()) {
            hand(world.snapshot());
        }
        hand(new Step(world.update(), asked, responses));
    }

    /** Loop thread: the end; the thread finishes the file and ends. */
    @Override
    public void ended(SimulationEnd end) {
        if (writer != null) {
            hand(end);
        }
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

    /** Waits up to {@code ms} for the file to be finished (after the end); logs it if it is not. */
    public void awaitWritten(long ms) throws InterruptedException {
        Thread t = thread;
        if (t == null) {
            return;
        }
        t.join(ms);
        if (t.isAlive()) {
            LOG.warn("recording {} was not finished within {} ms of the end; its last steps may be missing", file, ms);
        }
    }

    private void write() {
        RecordingWriter writer = this.writer;
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
