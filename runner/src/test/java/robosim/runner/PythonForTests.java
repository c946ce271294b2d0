package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * The Python that tests of Python control code run scripts with, and the environment that makes a script's
 * {@code import robosim} this checkout's package ({@code python/src}, whatever is installed): {@code ROBOSIM_PYTHON}
 * when it is set ({@code .ci/run} sets its virtual environment's), else a virtual environment made once in
 * {@code runner/target/python} by {@code python3 -m venv} with the package installed from the registry's
 * {@code msgpack} ({@code pip install ./python}); on a machine without {@code python3} (and no {@code ROBOSIM_PYTHON}),
 * the tests that ask are skipped.
 */
final class PythonForTests {
    private static final Path ROOT = Path.of("").toAbsolutePath().getParent();
    private static final long SETUP_S = 300;
    private static String interpreter;

    private PythonForTests() {
    }

    /** {@code ROBOSIM_PYTHON} and {@code PYTHONPATH} for a script run ({@link ScriptRun}) that starts Python. */
    static synchronized Map<String, String> environment() throws Exception {
        if (interpreter == null) {
            interpreter = find();
        }
        return Map.of("ROBOSIM_PYTHON", interpreter, "PYTHONPATH", ROOT.resolve("python/src").toString());
    }

    private static String find() throws Exception {
        String given = System.getenv("ROBOSIM_PYTHON");
        if (given != null && !given.isBlank()) {
            assertEquals(0, run(List.of(given, "-c", "import msgpack")), "ROBOSIM_PYTHON=" + given
                    + " cannot import msgpack: pip install ./python into it");
            return given;
        }
        // (a machine without Python cannot run Python control code: these tests are skipped there, saying so; CI
        // sets ROBOSIM_PYTHON, so there they always run)
        Assumptions.assumeTrue(run(List.of("python3", "--version")) == 0, "no python3 on the PATH and no "
                + "ROBOSIM_PYTHON: the tests of Python control code are skipped");
        Path venv = ROOT.resolve("runner/target/python");
        Path python = venv.resolve("bin/python");
        if (!Files.isExecutable(python) || run(List.of(python.toString(), "-c", "import msgpack")) != 0) {
            assertEquals(0, run(List.of("python3", "-m", "venv", "--clear", venv.toString())),
                    "these tests run Python control code: they need python3 (3.11+) with its venv module");
            assertEquals(0, run(List.of(python.toString(), "-m", "pip", "install", "-q", ROOT.resolve("python")
                    .toString())), "pip install ./python into " + venv);
        }
        return python.toString();
    }

    private static int run(List<String> command) throws IOException, InterruptedException {
        Path out = Files.createTempFile("python-setup", ".txt");
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile()).start();
            assertTrue(p.waitFor(SETUP_S, TimeUnit.SECONDS), String.join(" ", command) + " took over " + SETUP_S + " s");
            if (p.exitValue() != 0) {
                System.err.println(String.join(" ", command) + ":\n" + Files.readString(out, StandardCharsets.UTF_8));
            }
            return p.exitValue();
        } catch (IOException e) {
            return -1; // (no such program: said by the caller's assertion)
        } finally {
            Files.deleteIfExists(out);
        }
    }
}
