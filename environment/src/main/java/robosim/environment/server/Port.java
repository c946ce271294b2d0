package robosim.environment.server;

import java.io.Externalizable;
import java.util.Set;
import robosim.protocol.GeometryHello;
import robosim.protocol.RobotHello;
import robosim.protocol.SharedHello;
import robosim.protocol.ViewerHello;

/**
 * The Environment's object-protocol ports: the hellos each takes, and what each says to a client of another
 * kind. Every port reads any of the {@link #HELLOS} first, so that a robot at the viewer port, or a viewer at
 * the robot port, is told which port it wants instead of being dropped without a word.
 */
public enum Port {
    ROBOT("robot", "robots use", Set.of(RobotHello.class, SharedHello.class)),
    VIEWER("viewer", "viewers use", Set.of(ViewerHello.class)),
    GEOMETRY("Geometry", "Geometry uses", Set.of(GeometryHello.class));

    /** Every kind of client's hello: what any port reads first. */
    public static final Set<Class<?>> HELLOS = Set.of(RobotHello.class, SharedHello.class, ViewerHello.class,
            GeometryHello.class);

    private final String name;
    private final String clients;
    private final Set<Class<?>> hellos;

    Port(String name, String clients, Set<Class<?>> hellos) {
        this.name = name;
        this.clients = clients;
        this.hellos = hellos;
    }

    /**
     * The live Environment's words for its ports ({@link #description}, {@link #refusal}); {@code bound}: the robot,
     * viewer and Geometry ports as bound (-1 for one not listening), asked when a client is at the wrong port.
     */
    public static PortGuide environment(java.util.function.Supplier<int[]> bound) {
        return new PortGuide() {
            @Override
            public String description(Port port) {
                return port.description();
            }

            @Override
            public String wrongPort(Port here, Externalizable hello) {
                return here.refusal(hello, bound.get());
            }

            @Override
            public String speaker() {
                return "the Environment";
            }
        };
    }

    /** "robot", "viewer", "geometry": the port's word in a log line and in its thread's name. */
    public String word() {
        return name.toLowerCase(java.util.Locale.ROOT);
    }

    /** "the Environment's robot port" */
    public String description() {
        return "the Environment's " + name + " port";
    }

    /** True if {@code hello} is one this port serves. */
    public boolean takes(Externalizable hello) {
        return hellos.contains(hello.getClass());
    }

    /** The port whose client says {@code hello} (one of {@link #HELLOS}). */
    public static Port of(Externalizable hello) {
        for (Port p : values()) {
            if (p.takes(hello)) {
                return p;
            }
        }
        throw new IllegalArgumentException("no port takes a " + hello.getClass().getSimpleName());
    }

    /**
     * What this port says to a client whose hello is {@code hello}, of another port: "that is the Environment's
     * viewer port; robots use 8000" ({@code ports}: the robot, viewer and Geometry ports as bound; -1 for one not
     * listening, as Geometry in-process).
     */
    public String refusal(Externalizable hello, int[] ports) {
        Port wanted = of(hello);
        int port = ports[wanted.ordinal()];
        return "that is " + description() + "; " + wanted.clients + " " + (port > 0 ? port
                : "none here (Geometry runs in the Environment's process)");
    }
}
