/**
 * The headless runner ({@code scripts/headless.sh}, {@code scripts/demo.sh}): starts the
 * Environment, the Geometry process and the robots as separate OS processes, watches the run
 * through a viewer connection (pose log, progress) on the {@code viewer-client} thread, and prints
 * a one-line summary. Child output is copied by one {@code pipe[...]} thread per stream.
 */
package robosim.runner;
