package robosim.environment.run;

/**
 * How a robot reaches the Environment: over a socket of its own (the report's), with the other robots of its
 * process over one shared connection, or in the Environment's own JVM ({@code --one-jvm}). Each is a
 * {@link RobotPeer} to the loop (and, where it needs one, a {@link LoopHook}); a {@link CoordinatorDesign} says
 * which it serves.
 */
public enum Transport { SOCKET, SHARED, IN_MEMORY }
