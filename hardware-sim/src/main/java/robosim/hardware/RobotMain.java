package robosim.hardware;

import robosim.devices.RobotType;
import java.io.IOException;
import java.net.UnknownHostException;
import java.util.concurrent.Callable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.api.RobotControl;
import robosim.protocol.CommandLines;
import robosim.protocol.ClientOptions;
import robosim.protocol.Protocol;

/** {@code scripts/robot.sh CONTROL NAME HOST PORT}: one robot process. */
@Command(name = "robot.sh", mixinStandardHelpOptions = true,
        description = "Runs one robot's control code on a Hardware Simulator connected to an Environment.")
public final class RobotMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(RobotMain.class);

    @Parameters(index = "0", paramLabel = "CONTROL",
            description = "Control class, e.g. robosim.examples.BackAndForth, or a Python script, python:PATH (run "
                    + "with $ROBOSIM_PYTHON or python3, which needs the package in python/).")
    String controlClass;

    @Parameters(index = "1", paramLabel = "NAME", description = "The robot's name in the environment file.")
    String name;

    @Parameters(index = "2", paramLabel = "HOST", defaultValue = "localhost",
            description = "Environment host (default: ${DEFAULT-VALUE}).")
    String host;

    @Parameters(index = "3", paramLabel = "PORT", defaultValue = "" + Protocol.DEFAULT_ROBOT_PORT,
            description = "Environment robot port (default: ${DEFAULT-VALUE}).")
    int port;

    @Option(names = "--type",
            description = "Robot type: a registered one (scripts/describe.sh robots) or a RobotType class name "
                    + "(default: the type the environment file gives this robot, when it is a registered one; a "
                    + "RobotType class must be named).")
    String type;

    @Mixin
    ClientOptions client;

    @Mixin
    ExchangeOption exchange;

    @Override
    public Integer call() throws Exception {
        if (robosim.protocol.Connector.badPort(port) != null) {
            System.err.println("robot " + name + ": " + host + ":" + port + ": " + robosim.protocol.Connector.badPort(port));
            return 2;
        }
        if (exchange.given() == ExchangeOption.Threading.SHARED) {
            System.err.println("robot " + name + ": --exchange SHARED is for several robots in one process (robots.sh)");
            return 2;
        }
        RobotControl control;
        RobotType robotType;
        try {
            control = RobotLauncher.control(controlClass);
            robotType = type == null ? null : robosim.devices.RobotTypes.byName(type);
        } catch (IllegalArgumentException e) {
            System.err.println("robot " + name + ": " + e.getMessage());
            return 2;
        }
        LOG.info("robot {}: {}", name, ControlThreads.describe());
        try {
            HardwareSimulator sim = new RobotLauncher(host, port, client).connect(name, robotType);
            String reason = sim.run(control, exchange.given() == ExchangeOption.Threading.SEND_RECEIVE
                    ? HardwareSimulator.Exchange.SEND_RECEIVE : HardwareSimulator.Exchange.ONE_THREAD);
            LOG.info("robot {}: simulation over: {}", name, reason);
            if (sim.controlFailure() != null) {
                System.err.println("robot " + name + ": its control code failed: " + sim.controlFailure());
                return HardwareSimulator.EXIT_CONTROL_FAILED;
            }
            return 0;
        } catch (UnknownHostException e) {
            System.err.println("robot " + name + ": " + e.getMessage());
            return 2;
        } catch (IOException e) {
            System.err.println("robot " + name + ": " + e.getMessage());
            return 1;
        }
    }

    public static void main(String[] args) {
        CommandLines.exit("robot", new RobotMain(), args);
    }
}
