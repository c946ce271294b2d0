package robosim.remote;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.examples.RobotInfo;

/** The Remote Control: drives the robots listed in RobotInfo.xml from the keyboard. */
@Command(name = "remote-control.sh", mixinStandardHelpOptions = true,
        description = "Drives robots (running RemoteControlRobot) from the keyboard. Arrows: forward, back, turn "
                + "left, turn right; space: stop; Tab or 1-9: choose the robot.")
public final class RemoteControlMain implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "ROBOT_INFO.xml", defaultValue = RobotInfo.DEFAULT,
            description = "The robots to drive: name, host and port of each (default: ${DEFAULT-VALUE}).")
    Path file;

    @Option(names = "--step-mm", defaultValue = "250", description = "Distance per arrow press (default: ${DEFAULT-VALUE}).")
    double stepMm;

    @Option(names = "--turn-deg", defaultValue = "15", description = "Turn per arrow press (default: ${DEFAULT-VALUE}).")
    double turnDeg;

    private static volatile boolean windowOpened;

    @Override
    public Integer call() throws Exception {
        List<RobotInfo> robots;
        try {
            robots = RobotInfo.load(file);
        } catch (IllegalArgumentException e) {
            System.err.println("remote-control: " + e.getMessage());
            return 2;
        }
        if (!(stepMm > 0) || !(turnDeg > 0) || stepMm > 100_000 || turnDeg > 360) {
            System.err.println("remote-control: --step-mm must be in (0, 100000] and --turn-deg in (0, 360]");
            return 2;
        }
        robosim.protocol.SimulationKeys keys;
        try {
            keys = robosim.protocol.SimulationKeys.fromEnvironment();
        } catch (java.io.IOException e) {
            System.err.println("remote-control: " + e.getMessage());
            return 2;
        }
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            System.err.println("remote-control: needs a display (set DISPLAY)");
            return 2;
        }
        RemoteControlWindow.open(robots, stepMm, turnDeg, keys);
        windowOpened = true;
        return 0;
    }

    public static void main(String[] args) {
        CommandLine cl = CommandLines.of("remote-control", new RemoteControlMain());
        int code = cl.execute(args);
        if (!windowOpened) {
            System.exit(code);
        }
    }
}
