package robosim.environment.run;

/**
 * What the Environment does when a robot's connection closes or fails mid-run ({@code --on-robot-loss}):
 * {@code REMOVE} (the default, the report's behaviour) takes it out of the world for good and refuses its
 * name afterwards; {@code HOLD} keeps it in the world, standing still as an obstacle, keeps the messages
 * sent to it (bounded) and lets a process that says hello with its name take it over at its current pose
 * from the next step, while the others go on; {@code WAIT} does the same but holds the whole world until it
 * is back, for at most the step timeout, after which it is removed.
 */
public enum RobotLoss { REMOVE, HOLD, WAIT }
