package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Control code of one's own, outside the project: a control class written here, compiled against
 * the robot-api jar alone, and run by {@code scripts/headless.sh --classpath DIR} with every part as
 * its own process. Runs after package (failsafe), when runner/target/lib holds the built jars.
 */
class OwnControlCodeIT {
    private static final long TIMEOUT_S = 120;
    private static final int STEPS = 40;
    private static final String CONTROL_CLASS = "com.example.own.SquareStep";
    /** Moves 1000 mm (4 steps of 250 mm at 500 ms, 500 mm/s), turns 90 deg (2 steps), then sleeps. */
    private static final String CONTROL_SOURCE = """
            package com.example.own;

            import robosim.api.Robot;
            import robosim.api.RobotControl;

            public final class SquareStep implements RobotControl {
                @Override
                public void run(Robot robot) throws InterruptedException {
                    System.out.println(robot.name() + " runs its own control code: step " + robot.stepMs()
                            + " ms, " + robot.sonarAnglesDeg().length + " sonars");
                    robot.move(1000);
                    robot.turn(90);
                    robot.sleep(Long.MAX_VALUE);
                }
            }
            """;
    private static final String WORLD = """
            <?xml version="1.0" encoding="UTF-8"?>
            <environment name="own" timeStepMs="500" seed="1">
              <arena width="6" height="4"/>
              <robots>
                <robot name="own1" type="Scout" control="%s" x="1" y="1" heading="0"/>
              </robots>
            </environment>
            """.formatted(CONTROL_CLASS);

    /** The runner module's directory: failsafe runs tests there. */
    private final Path runnerDir = Path.of("").toAbsolutePath();
    private final Path root = runnerDir.getParent();

    @TempDir
    Path dir;

    @Test
    void aClassCompiledAgainstTheApiJarAloneRunsThroughHeadlessShWithClasspath() throws Exception {
        Path classes = compileAgainst(robotApiJar());
        Path world = Files.writeString(dir.resolve("own.xml"), WORLD);
        Path poses = dir.resolve("poses.csv");

        ProcessBuilder pb = new ProcessBuilder("bash", "scripts/headless.sh", "--env", world.toString(),
                "--classpath", classes.toString(), "--steps", Integer.toString(STEPS), "--pose-log",
                poses.toString(), "--timeout-s", Long.toString(TIMEOUT_S - 20));
        pb.directory(root.toFile()).redirectErrorStream(true);
        pb.environment().remove("ROBOSIM_CLASSPATH");
        Process headless = pb.start();
        CompletableFuture<String> output = readFully(headless.getInputStream());
        if (!headless.waitFor(TIMEOUT_S, TimeUnit.SECONDS)) {
            headless.descendants().forEach(ProcessHandle::destroyForcibly);
            headless.destroyForcibly();
            fail("headless.sh did not end within " + TIMEOUT_S + " s");
        }
        String out = output.get(30, TimeUnit.SECONDS);
        assertEquals(0, headless.exitValue(), out);
        List<String> lines = out.lines().toList();
        String last = lines.get(lines.size() - 1);
        assertTrue(last.startsWith("steps=" + STEPS + " robots=1 "), last);
        assertTrue(lines.contains("own1 runs its own control code: step 500 ms, 16 sonars"),
                "the control class's own line is in the output:\n" + out);

        String[] end = Files.readAllLines(poses).get(STEPS).split(",");
        assertEquals(List.of(Integer.toString(STEPS), "own1"), List.of(end[0], end[1]), String.join(",", end));
        assertEquals(2.0, Double.parseDouble(end[2]), 1e-9, "1 m along x from x = 1 m");
        assertEquals(1.0, Double.parseDouble(end[3]), 1e-9);
        assertEquals(90.0, Double.parseDouble(end[4]), 1e-9, "then a quarter turn to the left");
    }

    /** runner/target/lib/robot-api-*.jar, made by package (the scripts' class path). */
    private Path robotApiJar() throws IOException {
        Path lib = runnerDir.resolve("target/lib");
        try (Stream<Path> jars = Files.isDirectory(lib) ? Files.list(lib) : Stream.empty()) {
            return jars.filter(p -> p.getFileName().toString().matches("robot-api-.*\\.jar")).findFirst()
                    .orElseThrow(() -> new AssertionError("no robot-api-*.jar in " + lib
                            + ": run this test after package (./mvnw verify), which copies it there"));
        }
    }

    /** Compiles CONTROL_SOURCE with nothing but {@code apiJar} on the class path; returns the class folder. */
    private Path compileAgainst(Path apiJar) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertNotNull(javac, "no system Java compiler: run the tests on a JDK, not a JRE");
        Path source = dir.resolve("src/com/example/own/SquareStep.java");
        Files.createDirectories(source.getParent());
        Files.writeString(source, CONTROL_SOURCE);
        Path classes = Files.createDirectories(dir.resolve("classes"));
        StringWriter diagnostics = new StringWriter();
        boolean compiled;
        try (StandardJavaFileManager files = javac.getStandardFileManager(null, null, StandardCharsets.UTF_8)) {
            compiled = javac.getTask(diagnostics, files, null,
                    List.of("--release", "17", "-classpath", apiJar.toString(), "-d", classes.toString()), null,
                    files.getJavaFileObjects(source.toFile())).call();
        }
        assertTrue(compiled, "the control class must compile against " + apiJar.getFileName() + " alone:\n"
                + diagnostics);
        return classes;
    }

    /** Reads a process's whole output on a thread of its own, so the test can wait on the process. */
    private static CompletableFuture<String> readFully(InputStream in) {
        CompletableFuture<String> text = new CompletableFuture<>();
        Thread reader = new Thread(() -> {
            try (in) {
                text.complete(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                text.completeExceptionally(e);
            }
        }, "headless-output");
        reader.setDaemon(true);
        reader.start();
        return text;
    }
}
