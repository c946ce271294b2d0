package robosim.hardware;

import java.io.IOException;
import java.net.Socket;
import java.util.List;
import robosim.api.RobotControl;
import robosim.protocol.SimulationKeys;

/**
 * Many robots of one process, their exchanges on the calling thread (each robot's control code on its
 * own thread): over one shared connection ({@link SharedLink}, what {@code robots.sh} does by default),
 * or each over its own ({@link SharedExchange}).
 */
public final class ManyRobots {
    private ManyRobots() {
    }

    /**
     * Says every robot's hello over {@code socket} and runs those welcomed until each one's simulation is
     * over; a robot refused is logged and left out (an IOException names the reasons if every one was).
     *
     * @param sims simulators not connected yet; {@code controls} their control code, in the same order
     */
    public static void runOverOneConnection(List<HardwareSimulator> sims, List<RobotControl> controls, Socket socket,
            int resetEvery, SimulationKeys keys) throws IOException, InterruptedException {
        SharedLink.connect(sims, socket, resetEvery, keys, robosim.protocol.ObjectConnection.DEFAULT_ANSWER_MS)
                .run(controls);
    }

    /**
     * Runs robots connected each over its own socket until each one's simulation is over.
     *
     * @param sims connected simulators, in world order (the order the Environment writes in)
     */
    public static void runShared(List<HardwareSimulator> sims, List<RobotControl> controls)
            throws IOException, InterruptedException {
        SharedExchange.run(sims, controls);
    }
}
