/**
 * The Environment's client interface: sockets and threads only, no world logic (that is the core's). The
 * {@link robosim.environment.net.ClientWorkerCoordinator} starts these threads, each named; one of them,
 * {@code simulation-loop}, owns simulation time and every other posts events to it through its
 * {@link robosim.environment.net.Inbox}. No lock is held across a socket read or write, a sleep or a wait.
 * This is the one list of them; other pages link here.
 *
 * <table>
 * <caption>The Environment's threads</caption>
 * <tr><th>thread</th><th>code</th><th>what it does</th><th>where it blocks</th></tr>
 * <tr><td>{@code simulation-loop}</td><td>{@link robosim.environment.net.SimulationLoop},
 *     {@link robosim.environment.net.Run}</td><td>every step (collect, resolve, release), the roster, pace,
 *     pause, the robots' deadlines, the end</td><td>its inbox, timed to the next deadline; its writes to
 *     robots and shared connections (one frame each after every event), which the connection watch bounds;
 *     a full recording queue</td></tr>
 * <tr><td>{@code robot-worker[#n]}, then {@code robot-worker[name]}</td><td>{@link
 *     robosim.environment.net.RobotClientWorker}</td><td>one per robot connection: the handshake, then its
 *     robot's requests, each posted</td><td>its socket read</td></tr>
 * <tr><td>{@code robot-worker[shared #n]}</td><td>{@link robosim.environment.net.SharedConnection}</td>
 *     <td>one per shared connection (several robots of one process): every robot's hello, then each frame
 *     of requests, posted as one event</td><td>its socket read</td></tr>
 * <tr><td>{@code robot-writer[name]}</td><td>{@link robosim.environment.net.RobotWriter}
 *     ({@code TWO_THREADS})</td><td>writes what the loop queues for its robot</td><td>its queue; its socket
 *     write</td></tr>
 * <tr><td>{@code stepper}</td><td>{@link robosim.environment.net.SequentialReader} ({@code SEQUENTIAL})</td>
 *     <td>reads every robot's request in world order</td><td>each robot's socket read</td></tr>
 * <tr><td>{@code geometry-worker}</td><td>{@link robosim.environment.net.GeometryClientWorker}</td><td>the
 *     Geometry connection: the world, each step's round trip, the end</td><td>its task queue; the round
 *     trip</td></tr>
 * <tr><td>{@code viewer-worker[n]}</td><td>{@link robosim.environment.server.ViewerClientWorker}</td><td>one
 *     per viewer: the snapshot, then its bounded, coalescing queue</td><td>its queue; its socket
 *     write</td></tr>
 * <tr><td>{@code accept-robots}, {@code accept-viewers}, {@code accept-geometry}</td><td>{@link
 *     robosim.environment.server.Acceptors}</td><td>accept connections; close at once one over the port's
 *     cap</td><td>accept</td></tr>
 * <tr><td>{@code connection-watch}</td><td>{@link robosim.environment.server.ConnectionWatch}</td><td>cuts off
 *     any connection (robot, shared, viewer, Geometry) that misses its handshake deadline or does not take a
 *     write within the write timeout</td><td>sleeps between looks</td></tr>
 * <tr><td>{@code recorder}</td><td>{@link robosim.environment.net.RunRecorder} ({@code --record})</td>
 *     <td>writes the recording from the queue the loop fills after each step</td><td>its queue; the
 *     disk</td></tr>
 * </table>
 * With {@code --no-geometry} (and {@code --one-jvm}) the geometry library's sonar pass may also use one worker
 * of the JVM's common fork-join pool on the loop's behalf (its package-info says when); the loop waits for it
 * within the step. With {@code --one-jvm} the file's robots start no thread here: their control threads
 * ({@code control[name]}, the Hardware Simulator's) hand their requests to
 * {@link robosim.environment.net.InMemoryRequests}, and the last one owed wakes the loop.
 * A replay ({@code robosim.environment.replay}) has its own clock thread and this package's
 * {@link robosim.environment.net.Inbox}, and serves its viewers with the same server layer as the Environment
 * ({@code robosim.environment.server}).
 */
package robosim.environment.net;
