package robosim.environment.net;

import java.util.List;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;

/**
 * What a robot's hello is checked against before the loop sees it (the protocol version, a name in the
 * file, properties that do not contradict the file) and the welcome an accepted robot gets. Immutable;
 * any thread.
 */
final class Handshakes {
    private final WorldSpec spec;
    private final List<String> names;
    private final boolean stepMessages;

    Handshakes(WorldSpec spec, List<String> names, boolean stepMessages) {
        this.spec = spec;
        this.names = names;
        this.stepMessages = stepMessages;
    }

    /** Null if the hello may go to the loop, else the refusal. */
    String check(RobotHello hello, int index) {
        if (hello.protocolVersion() != Protocol.VERSION) {
            return "protocol version " + hello.protocolVersion() + " is not supported (the Environment speaks "
                    + Protocol.VERSION + ")";
        }
        if (index < 0) {
            return "no robot named \"" + hello.name() + "\" in " + spec.source() + " (robots: "
                    + String.join(", ", names) + ")";
        }
        return spec.robots().get(index).contradiction(hello.properties(), spec.source());
    }

    /** The welcome of robot {@code index}: the time step, its start pose, every robot's name, its sensors. */
    RobotWelcome welcome(int index) {
        WorldSpec.RobotSpec r = spec.robots().get(index);
        return welcome(index, r.xMm(), r.yMm(), r.headingDeg());
    }

    /** The welcome of robot {@code index} at a pose of its own: where it stands when it comes back mid-run. */
    RobotWelcome welcome(int index, double xMm, double yMm, double headingDeg) {
        return RobotWelcome.accepted(spec.timeStepMs(), xMm, yMm, headingDeg, names,
                spec.robots().get(index).sensorNames()).withStepMessages(stepMessages);
    }
}
