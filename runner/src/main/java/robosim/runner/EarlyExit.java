package robosim.runner;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Waits for a run to begin, and notices a robot or Geometry process that ends before it does: the
 * Environment would wait for that client for ever, so the runner stops at once with its reason.
 */
final class EarlyExit {
    /**
     * A client's exit reaches us on its own pipe, the Environment's "running" line on another; a client
     * that ended only after taking part (a run of a few steps) is told apart by the "running" line that
     * then follows within this time (a client that really ended first leaves the Environment waiting
     * for it, so no "running" line can follow).
     */
    private static final long CONFIRM_S = 3;

    private EarlyExit() {
    }

    /**
     * Returns when the run has begun or the Environment has ended (null), or when a client ended before
     * the run began (its name, exit code and last error lines).
     */
    static String await(CompletableFuture<Void> started, Process environment, List<ChildProcesses.Child> clients)
            throws InterruptedException {
        CompletableFuture<ChildProcesses.Child> firstExit = new CompletableFuture<>();
        for (ChildProcesses.Child c : clients) {
            c.process.onExit().thenRun(() -> firstExit.complete(c));
        }
        CompletableFuture<Void> environmentEnded = environment.onExit().thenRun(() -> { });
        try {
            CompletableFuture.anyOf(started, environmentEnded, firstExit).get();
            if (started.isDone() || environmentEnded.isDone()) {
                return null;
            }
            CompletableFuture.anyOf(started, environmentEnded).get(CONFIRM_S, TimeUnit.SECONDS);
            return null;
        } catch (TimeoutException notStarted) {
            ChildProcesses.Child c = firstExit.join();
            String said = c.lastErrorLines(10_000);
            return c.name + " exited (code " + c.process.exitValue() + ") before the simulation began"
                    + (said.isEmpty() ? "" : ": " + said);
        } catch (ExecutionException e) {
            throw new IllegalStateException("waiting for the start failed", e.getCause());
        }
    }
}
