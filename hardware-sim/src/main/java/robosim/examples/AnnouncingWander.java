package robosim.examples;

import robosim.api.Robot;

/** {@link Wander}, broadcasting its pose before every leg or turn, for robots that others track. */
final class AnnouncingWander extends Wander {
    @Override
    protected void everyStep(Robot robot) {
        PoseBoard.announce(robot);
    }
}
