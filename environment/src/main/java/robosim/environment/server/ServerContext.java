package robosim.environment.server;

import robosim.protocol.SimulationKeys;

/**
 * What every connection of a server's object ports is served with, whoever serves them (the live Environment or a
 * replay): the keys a client proves and the TLS they bring (null: none), how often an object stream is reset, the
 * handshake deadline and the write timeout (ms; 0 or less: none), the one {@link StrangerBudget} of every port, the
 * {@link ConnectionWatch} that times every connection, and the {@link PortGuide} that says what each port is. A
 * {@link ClientWorker} sees this and nothing of whoever serves it.
 */
public record ServerContext(SimulationKeys keys, int resetEvery, int handshakeTimeoutMs, long writeTimeoutMs,
        StrangerBudget strangers, ConnectionWatch watch, PortGuide guide) {
    /** A client whose hello is not accepted this long after it connected is dropped, ms. */
    public static final int DEFAULT_HANDSHAKE_TIMEOUT_MS = 10_000;
    /** A robot or viewer that cannot take one write in this long is dropped, ms. */
    public static final long DEFAULT_WRITE_TIMEOUT_MS = 10_000;
    /** Connections each port holds at once, beyond the robots the file names, by default. */
    public static final int DEFAULT_MAX_CONNECTIONS = 64;

    /** A context with a stranger budget and a connection watch of its own (the watch is started by {@link Acceptors}). */
    public static ServerContext of(SimulationKeys keys, int resetEvery, int handshakeTimeoutMs, long writeTimeoutMs,
            PortGuide guide) {
        return new ServerContext(keys, resetEvery, handshakeTimeoutMs, writeTimeoutMs,
                new StrangerBudget(StrangerBudget.DEFAULT_BYTES), new ConnectionWatch(handshakeTimeoutMs, writeTimeoutMs),
                guide);
    }
}
