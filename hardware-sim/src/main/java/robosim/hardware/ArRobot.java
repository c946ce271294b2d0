package robosim.hardware;

import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;

/** Pioneer-like robot: radius 250 mm, a ring of 8 sonars across the front. */
public final class ArRobot extends RobotType {
    @Override
    public RobotProperties properties() {
        return RobotModels.AR_ROBOT;
    }
}
