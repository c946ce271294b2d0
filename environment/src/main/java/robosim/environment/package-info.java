/**
 * The Environment's command line ({@code scripts/environment.sh}): loads the file, opens the ports and
 * the control port, and prints {@code listening ...}, {@code running ...}, one {@code left ...} line per
 * robot that left mid-run, and {@code summary ...} on stdout for the headless runner. Its threads:
 * {@code main} (waits for each simulation's end), {@code start-announcer} (prints the {@code running}
 * line once every client is there) and {@code shutdown} (the JVM's hook on SIGTERM/SIGINT: stops the
 * simulation so every client is told).
 */
package robosim.environment;
