/**
 * The Environment's client interface: sockets and threads only, no world logic. One thread,
 * {@code simulation-loop} ({@link robosim.environment.net.SimulationLoop}), owns simulation time; every
 * other thread posts events to it. The threads of this package, each named:
 * <ul>
 * <li>{@code simulation-loop}: every step (gather, core, Geometry link, responses, viewers, pace, pause,
 *     deadlines, the end); blocks on its event queue, timed to its next deadline, in its writes to
 *     robots and shared connections (one frame each after every event), which the write watchdog
 *     bounds, and on a full recording queue.</li>
 * <li>{@code robot-worker[name]} (one per robot): the handshake, then reads its robot's requests; blocks
 *     in its socket read.</li>
 * <li>{@code robot-worker[shared #n]} (one per shared connection, several robots of one process): every
 *     robot's hello, then each frame of requests, posted as one event; blocks in its socket read.</li>
 * <li>{@code robot-writer[name]} ({@code TWO_THREADS}): writes what the loop queues for its robot.</li>
 * <li>{@code stepper} ({@code SEQUENTIAL}): reads every robot's request in world order.</li>
 * <li>{@code geometry-worker}: the Geometry connection - the world, each step's round trip, the end.</li>
 * <li>{@code viewer-worker[n]} (one per viewer): the snapshot, then its bounded, coalescing queue.</li>
 * <li>{@code accept-robots}, {@code accept-viewers}, {@code accept-geometry}: accept connections, and
 *     close at once one over the port's cap.</li>
 * <li>{@code handshake-deadlines}: closes a connection whose hello is not accepted within the handshake
 *     timeout of its arrival, however slowly it sends.</li>
 * <li>{@code recorder} ({@code --record}): writes the run's recording from the queue the loop fills after
 *     each step; the loop waits for it only when the disk has fallen a whole queue behind.</li>
 * <li>{@code write-watchdog}: cuts off a robot that has not taken one of the loop's writes within the
 *     write timeout (the loop writes responses itself, so it cannot time its own writes).</li>
 * </ul>
 * With {@code --no-geometry} the geometry library's sonar pass may also use one worker of the JVM's common
 * fork-join pool on the loop's behalf (its package-info says when); the loop waits for it within the step.
 * No lock is held across a socket read or write, a sleep or a wait.
 */
package robosim.environment.net;
