package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Children started once closing has begun (a sweep's pool as Ctrl-C stops it) are stopped at once, not left running. */
class ChildProcessesTest {
    @TempDir
    Path tmp;

    @Test
    void aChildStartedAfterCloseIsStoppedAtOnceAndSaysSo() throws Exception {
        ChildProcesses children = new ChildProcesses(List.of());
        Process before = children.startLogged("sleeper", Sleeper.class.getName(), List.of(), tmp.resolve("a.log"));
        children.close();
        assertTrue(before.waitFor(30, TimeUnit.SECONDS), "a child started before close is stopped by it");
        IOException late = assertThrows(IOException.class, () -> children.startLogged("late",
                Sleeper.class.getName(), List.of(), tmp.resolve("b.log")));
        assertTrue(late.getMessage().startsWith("late: started while every child is being stopped"), late.getMessage());
        for (ProcessHandle h : ProcessHandle.current().children().toList()) {
            if (h.info().commandLine().orElse("").contains(Sleeper.class.getName())) {
                h.onExit().get(30, TimeUnit.SECONDS); // (killed: it ends; a timeout fails the test)
            }
        }
    }
}
