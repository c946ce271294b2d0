package robosim.protocol;

import picocli.CommandLine;

/** Every RoboSim process's command line: a bad option or argument is one line on stderr, {@code NAME: what (see --help)}, and exit code 2. */
public final class CommandLines {
    private CommandLines() {
    }

    /** The command line of {@code command} (a picocli command), whose errors say {@code name}. */
    public static CommandLine of(String name, Object command) {
        CommandLine cl = new CommandLine(command);
        cl.setParameterExceptionHandler((ex, args) -> {
            System.err.println(name + ": " + ex.getMessage() + " (see --help)");
            return 2;
        });
        return cl;
    }

    /** Runs {@code command} on {@code args} and exits with its code: a main method's whole body. */
    public static void exit(String name, Object command, String[] args) {
        System.exit(of(name, command).execute(args));
    }
}
