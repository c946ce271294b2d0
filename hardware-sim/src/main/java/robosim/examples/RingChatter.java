package robosim.examples;

import java.util.List;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * The soak's robot (and an example of lock-step messaging): drives back and forth like
 * {@link BackAndForth}, one step per call, and before every step sends the next robot in world order
 * (a ring) its own running number. It checks that the previous robot's numbers arrive exactly once and
 * in order, and at the end prints one line to standard output:
 * {@code ring NAME from=PREV sent=N received=M problems=P}.
 */
public final class RingChatter implements RobotControl {
    private long sent;
    private long received;
    private long problems;
    private String firstProblem = "";
    private String from;

    @Override
    public void run(Robot robot) throws InterruptedException {
        List<String> names = robot.robotNames();
        int me = names.indexOf(robot.name());
        String to = names.get((me + 1) % names.size());
        from = names.get((me + names.size() - 1) % names.size());
        try {
            while (true) {
                for (int i = 0; i < 40; i++) {
                    step(robot, to, true);
                }
                for (int i = 0; i < 4; i++) {
                    step(robot, to, false);
                }
                for (int i = 0; i < 40; i++) {
                    step(robot, to, true);
                }
                for (int i = 0; i < 4; i++) {
                    step(robot, to, false);
                }
            }
        } finally {
            drain(robot);
            System.out.println("ring " + robot.name() + " from=" + from + " sent=" + sent + " received=" + received
                    + " problems=" + problems + (firstProblem.isEmpty() ? "" : " first_problem=" + firstProblem));
            System.out.flush();
        }
    }

    private void step(Robot robot, String to, boolean move) throws InterruptedException {
        robot.send(to, Long.toString(sent));
        if (move) {
            robot.move(250);
        } else {
            robot.turn(45);
        }
        sent++; // counted once the step that carried it is done
        drain(robot);
    }

    private void drain(Robot robot) {
        for (Message m = robot.receive(); m != null; m = robot.receive()) {
            if (!m.from().equals(from) || !m.text().equals(Long.toString(received))) {
                if (problems++ == 0) {
                    firstProblem = "expected_" + received + "_from_" + from + "_got_" + m.text() + "_from_" + m.from();
                }
            }
            received++;
        }
    }
}
