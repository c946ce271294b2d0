package robosim.environment.net;

import robosim.environment.run.HelloCheck;
import robosim.environment.run.SimulationLoop;

/**
 * What the Environment's robot port serves robots with, and all a robot's transport sees of the Environment (but a
 * shared connection's {@link SharedOutput}): the check every hello passes on the thread that read it, the loop to
 * post to, the coordinator design's threads for a socket of its own, and why shared connections are refused (null:
 * they are not).
 */
record RobotContext(HelloCheck check, SimulationLoop loop, Design design, String sharedRefusal) {
}
