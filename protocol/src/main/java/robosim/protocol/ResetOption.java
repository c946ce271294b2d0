package robosim.protocol;

import picocli.CommandLine.Option;

/** Messages between an {@link ObjectConnection}'s stream resets (a picocli mixin of every command line whose process has one). */
public final class ResetOption {
    @Option(names = "--reset-every", paramLabel = "N", defaultValue = "" + ObjectConnection.DEFAULT_RESET_EVERY,
            description = "Messages between object-stream resets (default: ${DEFAULT-VALUE}; 0 = never, for "
                    + "measurement only).")
    private int messages;

    public int messages() {
        return messages;
    }
}
