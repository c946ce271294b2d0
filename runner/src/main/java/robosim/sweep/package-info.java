/**
 * Seed and parameter sweeps ({@code scripts/sweep.sh}, {@code docs/EXPERIMENTS.md}): a {@code <sweep>} file
 * ({@link robosim.sweep.SweepFile}, {@link robosim.sweep.Sweep}) numbers its runs; each run is the headless runner,
 * recording, in a warm JVM that runs run after run ({@link robosim.runner.WarmWorker}) or, with
 * {@code --fresh-jvm-per-run}, in a process of its own ({@link robosim.sweep.SweepRun}); its row comes from the runner's summary line and
 * the recording ({@link robosim.sweep.RunMetrics}, and {@link robosim.sweep.Metric}s of one's own) and is written
 * whole into the output directory ({@link robosim.sweep.OutputDirectory}, {@link robosim.sweep.Row}); the tables
 * and plots are made from the rows ({@link robosim.sweep.Tables}, {@link robosim.sweep.Plots}). On this machine
 * ({@link robosim.sweep.LocalPool}) or as a Slurm job array ({@link robosim.sweep.Slurm}).
 * Threads: {@code main} (reads the file, starts the pool or submits to Slurm, makes the tables; with
 * {@code --slurm --wait} polls {@code squeue} twice a second), {@code sweep-run[k]} (one per run at once: owns
 * a warm worker, hands it a run, waits for its answer and writes the row), {@code pipe[worker k.out]} and
 * {@code pipe[worker k.err]} (read a warm worker's answers and keep its last words, {@link robosim.runner.WarmWorker}), {@code sweep-stop} (the JVM's shutdown hook: on Ctrl-C it stops
 * every run and makes the tables from the rows written; in a Slurm task it marks the run stopped, so it writes no
 * row), {@code stop-children} ({@link robosim.runner.ChildProcesses}' hook), and the JVM's {@code process reaper}
 * (puts an ended run's class-data archive in place, {@code ChildProcesses.startLogged}).
 */
package robosim.sweep;
