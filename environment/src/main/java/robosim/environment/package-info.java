/**
 * The Environment's command line ({@code scripts/environment.sh}): loads the file, opens the ports and
 * the control port, and prints {@code listening ...}, {@code running ...}, one {@code left ...} line per
 * robot that left mid-run, and {@code summary ...} on stdout for the headless runner. Its threads:
 * {@code main} (waits for each simulation's end), {@code start-announcer} (prints the {@code running}
 * line once every client is there) and {@code shutdown} (the JVM's hook on SIGTERM/SIGINT: stops the
 * simulation so every client is told); with {@code --web-port} also the browser viewer's {@code web-io},
 * {@code web-commands}, {@code web-feed} and its {@code viewer-client} (listed in {@code robosim.web}).
 */
package robosim.environment;
