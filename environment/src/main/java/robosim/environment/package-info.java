/**
 * The Environment's command line ({@code scripts/environment.sh}): loads the file, opens the ports and
 * the control port, and prints {@code listening ...}, {@code running ...}, one {@code left ...} line per
 * robot that left mid-run, and {@code summary ...} on stdout for the headless runner. Its threads ({@code main},
 * {@code start-announcer}, {@code shutdown}, and with {@code --web-port} the browser viewer's) are in the
 * Environment's thread table, with every other ({@code robosim.environment.net}'s package documentation).
 */
package robosim.environment;
