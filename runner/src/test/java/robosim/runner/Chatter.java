package robosim.runner;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * BackAndForth driven one step at a time (move(250), turn(45): one step each at the default
 * velocities and a 500 ms step), sending a numbered message to the next robot before every step and
 * checking that the previous robot's numbers arrive exactly once and in order.
 */
final class Chatter implements RobotControl {
    final List<String> problems = new ArrayList<>();
    final CountDownLatch finished = new CountDownLatch(1);
    /** Messages that went out: counted once the step that carried them is done. */
    long sent;
    long received;
    private String from;

    @Override
    public void run(Robot robot) {
        List<String> names = robot.robotNames();
        int me = names.indexOf(robot.name());
        String to = names.get((me + 1) % names.size());
        from = names.get((me + names.size() - 1) % names.size());
        try {
            while (true) {
                for (int i = 0; i < 40; i++) {
                    robot.send(to, Long.toString(sent));
                    robot.move(250);
                    sent++;
                    drain(robot);
                }
                for (int i = 0; i < 4; i++) {
                    robot.send(to, Long.toString(sent));
                    robot.turn(45);
                    sent++;
                    drain(robot);
                }
            }
        } catch (InterruptedException e) {
            drain(robot);
        } finally {
            finished.countDown();
        }
    }

    private void drain(Robot robot) {
        for (Message m = robot.receive(); m != null; m = robot.receive()) {
            if (!m.from().equals(from) || Long.parseLong(m.text()) != received) {
                problems.add("expected " + received + " from " + from + ", got " + m.text() + " from " + m.from());
            }
            received++;
        }
    }
}
