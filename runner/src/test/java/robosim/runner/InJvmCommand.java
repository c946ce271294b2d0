package robosim.runner;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;

/**
 * One command line (a process's main class) run in this JVM: its exit code, the lines it said on stderr (not the log
 * lines of anything else in this JVM, "12:00:00.000 [thread] ..."), and its stdout.
 */
record InJvmCommand(int code, List<String> err, String out) {
    static InJvmCommand run(Callable<Integer> command, String... args) {
        PrintStream savedErr = System.err;
        PrintStream savedOut = System.out;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        int code;
        try {
            code = new CommandLine(command).execute(args);
        } finally {
            System.setErr(savedErr);
            System.setOut(savedOut);
        }
        return new InJvmCommand(code, err.toString(StandardCharsets.UTF_8).lines()
                .filter(l -> !l.matches("^\\d\\d:\\d\\d:\\d\\d\\.\\d+ \\[.*")).toList(), out.toString(StandardCharsets.UTF_8));
    }
}
