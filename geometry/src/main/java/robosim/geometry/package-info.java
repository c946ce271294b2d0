/**
 * Collision and sonar ranging with JTS: the {@link robosim.geometry.GeometryEngine} library (plain
 * objects, no threads, used by one thread at a time) and the Geometry process
 * ({@link robosim.geometry.GeometryMain}, one thread: it connects to the Environment and answers one
 * batch per step). The Environment links the same library for {@code --no-geometry}.
 */
package robosim.geometry;
