/**
 * Robot sensors answered by the Environment (every SENSOR request but sonar): the plug-in base
 * class {@link robosim.environment.sensors.RobotSensor}, the built-in laser, heat and bump sensors,
 * and what a sensor may ask of the world ({@link robosim.environment.sensors.SensorContext}). Plain
 * objects, called by the simulation core on the thread that runs the step.
 */
package robosim.environment.sensors;
