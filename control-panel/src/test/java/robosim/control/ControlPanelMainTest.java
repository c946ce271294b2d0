package robosim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * The Control Panel's command line: the port may be left out, and a bad one is one line (that --help lists every
 * request the Environment and a replay declare is {@code robosim.runner.ControlVerbsTest}'s).
 */
class ControlPanelMainTest {
    private static ControlPanelMain parsed(String... args) {
        ControlPanelMain m = new ControlPanelMain();
        new CommandLine(m).parseArgs(args);
        return m;
    }

    @Test
    void thePortMayBeLeftOut() {
        ControlPanelMain m = parsed("localhost", "status");
        assertNull(m.readRest());
        assertEquals(8100, m.port);
        assertEquals(List.of("status"), m.request);
    }

    @Test
    void aPortThenARequestOfSeveralWords() {
        ControlPanelMain m = parsed("localhost", "8101", "step", "5");
        assertNull(m.readRest());
        assertEquals(8101, m.port);
        assertEquals(List.of("step", "5"), m.request);
        ControlPanelMain window = parsed("localhost");
        assertNull(window.readRest());
        assertEquals(List.of(), window.request, "no request: the window, on the default port");
    }

    @Test
    void aPortOutOfRangeIsOneLineAndExitTwo() {
        assertEquals("port must be from 1 to 65535, got 81000", parsed("localhost", "81000", "status").readRest());
        assertEquals("port must be from 1 to 65535, got 99999999999", parsed("localhost", "99999999999").readRest());
        assertEquals(2, new CommandLine(new ControlPanelMain()).execute("localhost", "81000", "status"));
    }
}
