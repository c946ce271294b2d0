package robosim.environment;

import picocli.CommandLine.Option;
import robosim.environment.net.GeometryLoss;
import robosim.environment.net.RobotLoss;

/**
 * The Environment's options for its clients coming and going mid-run: losing its Geometry process or a robot,
 * and starting robot processes for the control port's {@code add} (a picocli mixin).
 */
final class ClientOptions {
    @Option(names = "--on-geometry-loss", defaultValue = "IN_PROCESS",
            description = "When the Geometry process dies or hangs mid-run: IN_PROCESS (go on with in-process "
                    + "geometry, same results; the default) or WAIT (hold the step until a new Geometry process "
                    + "attaches). Either way a new Geometry process may attach and takes over.")
    GeometryLoss onGeometryLoss;

    @Option(names = "--on-robot-loss", defaultValue = "REMOVE",
            description = "When a robot's connection closes or fails mid-run: REMOVE (take it out of the world; the "
                    + "default), HOLD (it stands where it is, messages to it are kept, and a robot process that says "
                    + "hello with its name takes it over at the next step) or WAIT (as HOLD, but the world waits for "
                    + "it, at most the step timeout, then removes it).")
    RobotLoss onRobotLoss;

    @Option(names = "--launch-robots", description = "Let the control port's add NAME TYPE X Y HEADING CONTROL start "
            + "that robot's process on this machine (robosim.hardware.RobotMain on this class path; at most "
            + robosim.environment.control.RobotLaunches.MAX + " at once), as headless.sh does; without it, add waits "
            + "for a robot process started elsewhere.")
    boolean launchRobots;

}
