/**
 * Collision and sonar ranging with JTS: the {@link robosim.geometry.GeometryEngine} library (plain
 * objects, used by one thread at a time) and the Geometry process
 * ({@link robosim.geometry.GeometryMain}, one thread: it connects to the Environment and answers one
 * batch per step). The Environment links the same library for {@code --no-geometry}. Threads: the
 * engine's caller; and, when a step has at least {@code --split-sonar-from} robots asking for sonar
 * (40 by default on two cores or more), one worker of the JVM's common fork-join pool
 * ({@code ForkJoinPool.commonPool-worker-n}) reads the sonars of the robots after the middle range
 * while the caller reads the rest ({@link robosim.geometry.SonarPass}); the caller waits for it
 * before answering the step.
 */
package robosim.geometry;
