/**
 * The RoboSim wire protocol: one final {@link java.io.Externalizable} class per message, the
 * {@link robosim.protocol.ObjectConnection} wrapper that owns a socket and its object streams, and
 * the {@link robosim.protocol.ProtocolFilter} allow-list applied to every object input stream.
 *
 * <p>Every message and its fields are listed in {@code protocol/README.md} (the protocol index).
 * Message objects are plain values; none of them owns a thread. A connection is used by one
 * reading thread and one writing thread at a time (the caller's), never concurrently by two writers.
 */
package robosim.protocol;
