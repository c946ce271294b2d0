package robosim.runner;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.protocol.ConnectOptions;
import robosim.protocol.Connector;

/**
 * {@code scripts/pose-log.sh}: a recording viewer of a running Environment, on this machine or another,
 * without a display: writes every step's poses as CSV (the {@code --pose-log} columns) until the
 * simulation ends, then prints one line and exits 0. The simulation's keys come from the environment
 * ({@code ROBOSIM_KEYS}), as for every other client.
 */
@Command(name = "pose-log.sh", mixinStandardHelpOptions = true,
        description = "Records every step's robot poses from a running Environment's viewer port as CSV "
                + "(step,robot,x_m,y_m,heading_deg,state) until the simulation ends.")
public final class PoseLogMain implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "HOST", description = "The Environment's host.")
    String host;

    @Parameters(index = "1", paramLabel = "PORT", description = "Its viewer port (the default is 3000).")
    int port;

    @Parameters(index = "2", paramLabel = "FILE.csv", description = "Where to write the poses (not overwritten).")
    Path file;

    @Mixin
    WatchOptions watching;

    @Mixin
    ConnectOptions connect;

    @Override
    public Integer call() throws Exception {
        String bad = Connector.badPort(port);
        if (bad != null) {
            System.err.println("pose-log: " + bad);
            return 2;
        }
        if (file.toAbsolutePath().getParent() == null || !Files.isDirectory(file.toAbsolutePath().getParent())) {
            System.err.println("pose-log: " + file + ": its directory does not exist");
            return 2;
        }
        RunWatch watch;
        try {
            watch = RunWatch.connect(host, port, file, watching.progress(), 0, connect.millis(),
                    java.nio.file.StandardOpenOption.CREATE_NEW, java.nio.file.StandardOpenOption.WRITE);
        } catch (java.nio.file.FileAlreadyExistsException e) {
            System.err.println("pose-log: " + file + " already exists: not overwritten");
            return 2;
        } catch (IOException e) {
            Files.deleteIfExists(file); // (made by this run, with nothing but the header)
            System.err.println("pose-log: " + host + ":" + port + ": " + e.getMessage());
            return e instanceof java.net.UnknownHostException ? 2 : 1;
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(watching.timeoutS() > 0 ? watching.timeoutS()
                : 100L * 365 * 86_400);
        try (watch) {
            // (a simulation that ends before its snapshot ends the connection: awaitEnd says how)
            if (watch.awaitSnapshot(secondsLeft(deadline))) {
                System.out.println("pose-log: recording " + host + ":" + port + " into " + file);
                System.out.flush();
            }
            String reason = watch.awaitEnd(secondsLeft(deadline));
            System.out.println("pose-log: " + watch.poseLogSteps() + " steps written to " + file + " (" + reason + ")");
            return 0;
        } catch (IOException e) {
            System.err.println("pose-log: " + host + ":" + port + ": " + e.getMessage() + " (" + watch.poseLogSteps()
                    + " steps written to " + file + ")");
            return 1;
        }
    }

    private static long secondsLeft(long deadline) {
        return Math.max(0, TimeUnit.NANOSECONDS.toSeconds(deadline - System.nanoTime()));
    }

    public static void main(String[] args) {
        CommandLines.exit("pose-log", new PoseLogMain(), args);
    }
}
