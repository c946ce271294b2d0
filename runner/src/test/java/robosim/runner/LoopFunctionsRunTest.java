package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A world's loop functions in a headless run, in one JVM and with every part its own process: loop functions that
 * throw end the run with one line naming them, the call and the step, and exit code 4 (as control code that throws);
 * a class that is not there is one line before anything starts (exit 2).
 */
class LoopFunctionsRunTest {
    @TempDir
    Path dir;

    private Path world(String loopClass) throws Exception {
        Path file = dir.resolve("loop.xml");
        Files.writeString(file, """
                <environment name="loop" timeStepMs="100">
                  <loopFunctions class="%s"/>
                  <arena width="4" height="2"/>
                  <robots>
                    <robot name="r1" type="ArRobot" control="robosim.examples.BackAndForth" x="1.5" y="1"/>
                  </robots>
                </environment>
                """.formatted(loopClass));
        return file;
    }

    @Test
    void loopFunctionsThatThrowEndTheRunWithExitCode4InOneJvmAndAsProcesses() throws Exception {
        Path file = world(ThrowsInPostStep.class.getName());
        for (String layout : new String[] {"--one-jvm", "--robots-in-one-process"}) {
            HeadlessRun r = HeadlessRun.of("--env", file.toString(), "--steps", "20", layout, "--timeout-s", "120");
            assertEquals(4, r.code(), r.all());
            String line = "loop functions robosim.runner.ThrowsInPostStep failed in postStep at step 3: "
                    + "java.lang.IllegalStateException: the nest is gone";
            assertTrue(r.all().contains(line), layout + ": " + r.all());
            assertTrue(r.summary().startsWith("steps=2 ") || r.summary().startsWith("steps=3 "), r.all());
        }
    }

    @Test
    void loopFunctionsThatAreNotThereAreOneLineBeforeTheRun() throws Exception {
        HeadlessRun r = HeadlessRun.of("--env", world("robosim.examples.NoSuchLoop").toString(), "--steps", "5",
                "--one-jvm");
        assertEquals(2, r.code(), r.all());
        assertTrue(r.all().contains("<loopFunctions>: there is no class robosim.examples.NoSuchLoop on the class path"),
                r.all());
    }
}
