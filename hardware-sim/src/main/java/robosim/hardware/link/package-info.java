/**
 * The robot link ({@link robosim.hardware.link.RobotLink}; hardware-sim/README.md, "The robot link"): one robot's
 * API served to control code in another process, in any language, as length-prefixed MessagePack frames
 * ({@link robosim.protocol.link.LinkFrames}), one request and one reply per call ({@link robosim.hardware.link.RobotCalls}).
 * It runs on the thread that serves the robot's control code (its {@code control[name]}); it starts no thread of its
 * own (the links' {@code link-deadline} and {@code script-output[name]} are {@link robosim.protocol.link}'s).
 */
package robosim.hardware.link;
