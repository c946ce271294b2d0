package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;

/**
 * Every environment file this repository ships (examples/, test-envs/, bench/) loads: a user's first run of one
 * never meets malformed XML or a fault of its own (manualcontrol.xml's comment once held "--", which XML forbids).
 */
class BundledWorldsTest {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();

    @Test
    void everyBundledWorldLoads() throws Exception {
        List<Path> worlds = new ArrayList<>();
        for (String dir : new String[] {"examples", "test-envs", "bench"}) {
            try (Stream<Path> files = Files.walk(REPO.resolve(dir))) {
                for (Path f : files.filter(p -> p.toString().endsWith(".xml")).sorted().toList()) {
                    if (Files.readString(f).contains("<environment ")) {
                        worlds.add(f);
                    }
                }
            }
        }
        List<String> failed = new ArrayList<>();
        for (Path world : worlds) {
            try {
                new EnvironmentLoader().load(world);
            } catch (Exception e) {
                failed.add(REPO.relativize(world) + ": " + e.getMessage());
            }
        }
        assertTrue(worlds.size() >= 30, "the bundled worlds found: " + worlds.size());
        assertEquals(List.of(), failed);
    }
}
