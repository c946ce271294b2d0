package robosim.devices;

import java.util.List;

/**
 * What a kind of actuator is, declared once, in its class ({@link RobotActuator}): its name (how a robot type's device
 * list and control code's {@code actuate} name it), a line on what it does, the attributes a file may give it, and
 * what its values are (their order, as a sentence). The file reader, {@code describe.sh actuators}, the learners'
 * action spaces and the APIs read it.
 */
public record ActuatorInfo(String name, String summary, List<Attribute> attributes, String values) {
    public ActuatorInfo {
        if (name == null || !name.matches("[a-z][a-z0-9_]{0,31}")) {
            throw new IllegalArgumentException("an actuator's name is 1 to 32 lower-case letters, digits and _, got "
                    + name);
        }
        attributes = List.copyOf(attributes);
    }
}
