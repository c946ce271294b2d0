package robosim.environment.server;

import java.io.Externalizable;

/**
 * What a server tells its clients about its ports: what each port is (in a refusal, and to a client that speaks
 * another protocol), what a client of another kind is told (which port it wants), and who speaks (in a refusal of
 * another protocol version). The live Environment's is {@link Port}'s own words; a replay has its own.
 */
public interface PortGuide {
    /** "the Environment's robot port". */
    String description(Port port);

    /** What a client whose hello is {@code hello}, which port {@code here} does not take, is told. */
    String wrongPort(Port here, Externalizable hello);

    /** Who speaks the protocol here, for a refusal: "the Environment". */
    String speaker();

    /** The refusal of a client of protocol {@code version}, or null if it is this server's. */
    default String version(int version) {
        return version == robosim.protocol.Protocol.VERSION ? null : "protocol version " + version
                + " is not supported (" + speaker() + " speaks " + robosim.protocol.Protocol.VERSION + ")";
    }
}
