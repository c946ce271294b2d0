/**
 * What a robot is and what it senses, each one class in a registry: robot types ({@link robosim.devices.RobotType}: a
 * {@link robosim.devices.Body} and the devices it carries; {@link robosim.devices.RobotTypes}), sensors
 * ({@link robosim.devices.RobotSensor}, each declaring its {@link robosim.devices.SensorInfo}: its name, its file
 * {@link robosim.devices.Attribute}s, its values and their range, whether the Geometry process computes it;
 * {@link robosim.devices.Sensors}), and how a velocity becomes a step's motion ({@link robosim.devices.Drive}). A
 * registry finds its members with {@link java.util.ServiceLoader}: a new one is its class, which says
 * {@code @AutoService(ITS_KIND.class)}. Plain objects, no threads: a sensor is called on the thread that steps the
 * world, through a {@link robosim.devices.SensorContext}.
 */
package robosim.devices;
