package robosim.protocol;

import picocli.CommandLine.Mixin;

/**
 * A client process's connections to the Environment: how long it keeps trying to connect and how often its object
 * streams reset (a picocli mixin of geometry.sh, robot.sh and robots.sh).
 */
public final class ClientOptions {
    @Mixin
    private ConnectOptions connect;

    @Mixin
    private ResetOption reset;

    public ConnectOptions connect() {
        return connect;
    }

    /** Messages between the object streams' resets. */
    public int resetEvery() {
        return reset.messages();
    }
}
