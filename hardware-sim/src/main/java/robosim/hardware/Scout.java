package robosim.hardware;

import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;

/** Nomadic Scout-like robot: radius 190 mm, 16 sonars all round. */
public final class Scout extends RobotType {
    @Override
    public RobotProperties properties() {
        return RobotModels.SCOUT;
    }
}
