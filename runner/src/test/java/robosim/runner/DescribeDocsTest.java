package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Each README's table of a registry is the registry's, as {@code describe.sh LIST --markdown} writes it: a sensor,
 * robot type or metric added is one class, and the line its table gains (which this test asks for).
 */
class DescribeDocsTest {
    @ParameterizedTest
    @CsvSource({"environment/README.md, sensors", "hardware-sim/README.md, robots", "hardware-sim/README.md, actuators",
        "docs/EXPERIMENTS.md, metrics"})
    void aReadmesTableIsTheRegistrys(String file, String list) throws Exception {
        List<String> lines = Files.readAllLines(Path.of("..").resolve(file));
        int start = lines.indexOf("<!-- describe.sh " + list + " --markdown -->");
        int end = lines.indexOf("<!-- end of describe.sh " + list + " -->");
        assertTrue(start >= 0 && end > start, file + " holds no table of " + list + " between its markers");
        assertEquals(DescribeMain.table(list), lines.subList(start + 1, end), file + "'s table of " + list
                + " is not the registry's: paste what scripts/describe.sh " + list + " --markdown prints between its "
                + "markers");
    }
}
