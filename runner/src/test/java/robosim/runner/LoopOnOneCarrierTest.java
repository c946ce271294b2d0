package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A one-JVM run on JDK 21+ puts the loop on a virtual thread beside the control code, all on one carrier. Control code
 * that computes without calling the robot ({@link Spins}) would keep the loop off the carrier for ever; the loop's
 * watch gives virtual threads a second carrier, and the step timeout removes the robot as in every other layout. Its
 * own JVM (on the newest JDK 21+ here): the spinning code ends with it.
 */
class LoopOnOneCarrierTest {
    @TempDir
    Path dir;

    @Test
    void controlCodeThatNeverCallsTheRobotIsRemovedAtTheStepTimeoutThoughItHoldsTheOneCarrier() throws Exception {
        Path jdk = SameRunEveryLayoutTest.NewestJdk.atLeast(21);
        org.junit.jupiter.api.Assumptions.assumeTrue(jdk != null, "no JDK 21 or later on this machine: without "
                + "virtual threads the loop is a platform thread (CI has JDK 25)");
        Path world = dir.resolve("spins.xml");
        Files.writeString(world, """
                <environment name="spins" timeStepMs="100">
                  <arena width="13" height="4"/>
                  <robots>
                    <robot name="r1" type="ArRobot" control="robosim.examples.BackAndForth" x="1.5" y="1"/>
                    <robot name="r2" type="ArRobot" control="robosim.runner.Spins" x="1.5" y="3"/>
                  </robots>
                </environment>
                """);
        List<String> command = new ArrayList<>(List.of(jdk.resolve("bin").resolve("java").toString(),
                "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"),
                HeadlessRunner.class.getName(), "--env", world.toString(), "--steps", "30", "--one-jvm",
                "--step-timeout-ms", "3000", "--timeout-s", "120"));
        Path out = dir.resolve("out.txt");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile()).start();
        try {
            assertTrue(p.waitFor(180, TimeUnit.SECONDS), "the run did not end: " + Files.readString(out));
        } finally {
            p.destroyForcibly();
        }
        String all = Files.readString(out);
        assertEquals(HeadlessRunner.EXIT_ROBOTS_REMOVED, p.exitValue(), all);
        assertTrue(all.contains("the simulation loop runs on a virtual thread beside the control code"), all);
        assertTrue(Pattern.compile("the simulation loop has not come round for \\d+ ms: code on its carrier thread "
                + "computes without calling the robot \\(or the machine is very busy\\); virtual threads now have 2 "
                + "carriers").matcher(all).find(), all);
        assertTrue(Pattern.compile("removed robot=r2 step=\\d+ reason=sent no request for step \\d+ within 3000 ms "
                + "\\(step timeout\\): its control code made no call of the robot").matcher(all).find(), all);
        assertTrue(all.contains("steps=30 robots=2 "), all);
    }
}
