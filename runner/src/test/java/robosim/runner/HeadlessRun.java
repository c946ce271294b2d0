package robosim.runner;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import picocli.CommandLine;

/**
 * One run of headless.sh in this JVM (its Environment, Geometry and robots are processes, or with --one-jvm
 * all in this JVM): what it
 * printed on stdout and stderr, caught while it ran, and what it returned. Test classes run one at a time in
 * a test JVM, so nothing else prints meanwhile.
 */
record HeadlessRun(int code, List<String> out, List<String> err) {
    static HeadlessRun of(String... args) {
        PrintStream savedOut = System.out;
        PrintStream savedErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code;
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            code = new CommandLine(new HeadlessRunner()).execute(args);
        } finally {
            System.setOut(savedOut);
            System.setErr(savedErr);
        }
        return new HeadlessRun(code, out.toString(StandardCharsets.UTF_8).lines().toList(),
                err.toString(StandardCharsets.UTF_8).lines().toList());
    }

    /** Its last line on stdout: the summary of a run that got that far. */
    String summary() {
        return out.isEmpty() ? "" : out.get(out.size() - 1);
    }

    String all() {
        return "exit " + code + "\nstdout:\n" + String.join("\n", out) + "\nstderr:\n" + String.join("\n", err);
    }
}
