package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;

/**
 * The swarm examples do what they are for, each in its world, run in this JVM and read back from its recording: the
 * fireflies flash together (Synchronize: LEDs and cameras), the e-pucks gather (Aggregate: range-and-bearing) and
 * kilobots find the light (Phototaxis: the ambient light sensor). (Forage: PythonControlIT.)
 */
class SwarmExamplesTest {
    @TempDir
    Path dir;

    /** Each step's reports of {@code name}: step, robot, value. */
    private Map<Long, Map<Integer, Double>> reports(String world, int steps, String name) throws Exception {
        Path record = dir.resolve(world + ".rec");
        HeadlessRun r = HeadlessRun.of("--env", InJvmSimulation.env(world).toString(), "--steps",
                Integer.toString(steps), "--one-jvm", "--record", record.toString(), "--timeout-s", "120");
        assertEquals(0, r.code(), r.all());
        assertTrue(r.summary().contains(" control_failed=0 "), r.all());
        Map<Long, Map<Integer, Double>> out = new TreeMap<>();
        try (RecordingReader reader = new RecordingReader(record)) {
            for (int k = 0; k < reader.steps(); k++) {
                RecordingReader.Step s = reader.step(k);
                for (RobotView v : s.views()) {
                    for (robosim.protocol.Report report : v.reports()) {
                        if (report.name().equals(name)) {
                            out.computeIfAbsent(s.update().step(), x -> new TreeMap<>()).put(v.robot(),
                                    report.value());
                        }
                    }
                }
            }
        }
        return out;
    }

    @Test
    void theFirefliesEndUpFlashingTogether() throws Exception {
        Map<Long, Map<Integer, Double>> flashing = reports("synchronization.xml", 1500, "flashing");
        long together = flashing.values().stream().filter(m -> m.values().stream().mapToDouble(v -> v).sum() == 10)
                .count();
        long lastFlash = flashing.entrySet().stream().filter(e -> e.getValue().containsValue(1.0))
                .mapToLong(Map.Entry::getKey).max().orElseThrow();
        assertEquals(10, flashing.get(lastFlash).values().stream().mapToDouble(v -> v).sum(),
                "all ten flash in the last flash's step");
        assertTrue(together >= 5, "at least five flashes of all ten: " + together);
    }

    @Test
    void theEPucksGather() throws Exception {
        Map<Long, Map<Integer, Double>> nearest = reports("aggregation.xml", 2000, "nearestMm");
        Map<Integer, Double> first = nearest.values().iterator().next();
        Map<Integer, Double> last = ((TreeMap<Long, Map<Integer, Double>>) nearest).lastEntry().getValue();
        double before = first.values().stream().mapToDouble(v -> v).average().orElseThrow();
        double after = last.values().stream().mapToDouble(v -> v).average().orElseThrow();
        assertTrue(after < before / 2 && last.values().stream().allMatch(d -> d < 150),
                "each ends within 150 mm of another, the mean nearest less than half the start's: " + first + " then "
                        + last);
    }

    @Test
    void kilobotsFindTheLight() throws Exception {
        Map<Long, Map<Integer, Double>> light = reports("kilobots.xml", 3000, "light");
        Map<Integer, Double> first = light.values().iterator().next();
        Map<Integer, Double> last = new TreeMap<>(); // (each robot's last report: a tumble reports nothing)
        light.values().forEach(last::putAll);
        assertTrue(first.values().stream().allMatch(v -> v < 600), "none starts there: " + first);
        assertTrue(last.values().stream().filter(v -> v >= 600).count() >= 3, "three or more arrive: " + last);
    }
}
