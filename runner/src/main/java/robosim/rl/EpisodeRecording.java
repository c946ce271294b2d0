package robosim.rl;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import robosim.protocol.RecordingWriter;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;
import robosim.sweep.MetricChoice;
import robosim.sweep.RunMetrics;

/**
 * One world's episode recorded, for a metric that is computed from a run's recording ({@code --episode-metric}: a
 * built-in metric or a {@link robosim.sweep.Metric} class of one's own, as a sweep measures a run): the episode's
 * steps go to a file of the host's folder, the metric reads it when asked, and a new episode begins a new file.
 */
final class EpisodeRecording implements AutoCloseable {
    private final Path file;
    private final MetricChoice metric;
    private final double areaCellM;
    private RecordingWriter writer;

    EpisodeRecording(Path folder, int world, MetricChoice metric, double areaCellM) {
        this.file = folder.resolve("world-" + world + ".rec");
        this.metric = metric;
        this.areaCellM = areaCellM;
    }

    /** A new episode, from {@code start}: the last one's recording is dropped. */
    void begin(WorldSnapshot start) throws IOException {
        close();
        Files.deleteIfExists(file);
        writer = new RecordingWriter(file);
        writer.snapshot(start);
    }

    void step(robosim.protocol.PoseUpdate update, StepRequest[] requests, StepResponse[] responses) throws IOException {
        writer.step(update, requests, responses);
    }

    /** The metric's value over the episode so far. */
    double measure() throws IOException {
        writer.flush();
        Map<String, Double> values = RunMetrics.of(file, List.of(metric), areaCellM);
        if (values.isEmpty()) {
            throw new IOException("metric " + metric.name() + " gave no value");
        }
        return values.values().iterator().next();
    }

    @Override
    public void close() throws IOException {
        if (writer != null) {
            writer.close();
            writer = null;
        }
    }
}
