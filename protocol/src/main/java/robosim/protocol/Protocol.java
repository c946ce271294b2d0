package robosim.protocol;

/** Constants shared by every RoboSim process. */
public final class Protocol {
    /** Carried by every handshake; a peer with another version is refused with a reason. */
    public static final int VERSION = 11;

    public static final int DEFAULT_ROBOT_PORT = 8000;
    public static final int DEFAULT_VIEWER_PORT = 3000;
    public static final int DEFAULT_GEOMETRY_PORT = 10000;
    public static final int DEFAULT_CONTROL_PORT = 8100;

    /** Written instead of a step number to tell a robot the simulation is over. */
    public static final long END_OF_SIMULATION = -1L;

    private Protocol() {
    }
}
