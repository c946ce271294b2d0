/**
 * The headless runner ({@code scripts/headless.sh}, {@code scripts/demo.sh}): starts the
 * Environment, the Geometry process and the robots as separate OS processes, watches the run
 * through a viewer connection (pose log, progress) on the {@code viewer-client} thread, and prints
 * a one-line summary. Its threads: {@code main} (starts the children, waits for the start, the end
 * or a client that ends before the start), one {@code pipe[NAME.out]} and one {@code pipe[NAME.err]}
 * per child (copy its output; the Environment's stdout lines are the runner's events), and
 * {@code stop-children} (the JVM's shutdown hook: on SIGTERM, SIGINT or SIGHUP it stops every child).
 * With {@code --one-jvm} there is no child: {@code environment} ({@link robosim.runner.InJvmEnvironment}) runs
 * the Environment in the runner's JVM, with its robots and all the Environment's own threads, and hands its
 * lines to the runner as a child's pipe would.
 * A warm JVM ({@link robosim.runner.RunHost}, a sweep's worker) runs run after run: its {@code main} reads the
 * requests and answers, {@code run} is one run's runner {@code main} (its threads, and the Environment's, have the
 * run's {@link robosim.runner.ControlClassLoader} as context class loader); its owner
 * ({@link robosim.runner.WarmWorker}) reads its answers on {@code pipe[worker k.out]} and keeps its last words from
 * {@code pipe[worker k.err]}.
 * The soak ({@code scripts/soak.sh}, {@link robosim.runner.Soak}) adds {@code soak-client-n}: its silent
 * robots, frozen and visiting viewers and fault injectors, each on a thread of its own (never the common
 * pool: they block).
 */
package robosim.runner;
