/**
 * The RoboSim wire protocol: one final {@link java.io.Externalizable} class per message, the
 * {@link robosim.protocol.ObjectConnection} wrapper that owns a socket and its object streams, and
 * the {@link robosim.protocol.ProtocolFilter} allow-list applied to every object input stream.
 *
 * <p>Every message and its fields are listed in {@code protocol/README.md} (the protocol index).
 * Message objects are plain values; none of them owns a thread. A connection is used by one
 * reading thread and one writing thread at a time (the caller's), never concurrently by two writers.
 *
 * <p>Threads of this package: {@code viewer-client} ({@link robosim.protocol.ViewerClient}: reads one viewer
 * connection and hands each message to its listener; blocks on its socket read) and {@code handshake-deadline}
 * (one per process, {@link robosim.protocol.HandshakeDeadline}: closes a client's socket whose handshake has
 * not been answered by its deadline; sleeps until the next deadline).
 */
package robosim.protocol;
