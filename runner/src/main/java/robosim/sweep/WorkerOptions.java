package robosim.sweep;

import picocli.CommandLine.Option;

/** How a sweep's runs are run, wherever: whether each keeps its recording, and whether each has a JVM of its own (a picocli mixin of sweep.sh and its Slurm tasks). */
final class WorkerOptions {
    @Option(names = "--keep-recordings", description = "Keep each run's recording in DIR/recordings "
            + "(scripts/replay.sh plays it; scripts/record-tool.sh metrics gives its row again).")
    boolean keepRecordings;

    @Option(names = "--fresh-jvm-per-run", description = "Run each run in a JVM of its own, started for it (the isolation "
            + "of control code that needs it: static state a class loader of its own does not reset, threads it leaves "
            + "running, System.exit). By default each of the pool's workers is a warm JVM that runs run after run, "
            + "each run's control classes loaded afresh.")
    boolean freshJvmPerRun;
}
