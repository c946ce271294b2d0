/**
 * The Environment's transports and their facade: sockets and threads around one run, no world logic (the core's)
 * and no run logic (the run's, {@code robosim.environment.run}).
 *
 * <h2>The layout</h2>
 * <ul>
 * <li>The facade, {@link robosim.environment.net.ClientWorkerCoordinator} (the report's name): the one class that
 *     knows every part; it builds the run and the transports, starts the threads and turns the control port's calls
 *     into events ({@link robosim.environment.net.RobotRoster}: {@code add} and {@code remove}). Nothing else here
 *     names it.</li>
 * <li>The run, its loop and the seams the transports meet it at are {@code robosim.environment.run}'s: a transport
 *     hands the loop {@code LoopEvent}s, is a {@code RobotPeer} (or a {@code GeometryPeer}) to the run, and a
 *     {@code LoopHook} where it must act on the loop's thread.</li>
 * <li>The transports: a socket per robot ({@link robosim.environment.net.RobotClientWorker},
 *     {@link robosim.environment.net.RobotConnection}, read and written as its {@link robosim.environment.net.Design}
 *     says: {@link robosim.environment.net.ThreadsDesign}, {@link robosim.environment.net.SequentialDesign} with
 *     its {@link robosim.environment.net.SequentialReader}, {@link robosim.environment.net.TwoThreadsDesign} with a
 *     {@link robosim.environment.net.RobotWriter}, or the loop's {@link robosim.environment.net.LoopWrites}), a
 *     shared connection ({@link robosim.environment.net.SharedConnection}, {@link robosim.environment.net.SharedRobot},
 *     {@link robosim.environment.net.SharedOutput}), robots in this JVM
 *     ({@link robosim.environment.net.InMemoryTransport}, {@link robosim.environment.net.InMemoryPeer}). They see
 *     the Environment through a {@link robosim.environment.net.RobotContext}; every robot's hello passes the run's
 *     {@code HelloCheck} on its reader's thread, every request the one {@link robosim.environment.net.RequestOrder}.
 *     Geometry: {@link robosim.environment.net.GeometryClientWorker}, a {@code GeometryPeer} to the run.</li>
 * <li>The connections' server layer (accepting, handshakes, deadlines, viewers' workers) is
 *     {@code robosim.environment.server}'s, shared with the replay.</li>
 * </ul>
 *
 * <h2>The threads</h2>
 * One of them, {@code simulation-loop}, owns simulation time, and every other posts events to it through its
 * {@link robosim.environment.run.Inbox}. No lock is held across a socket read or write, a sleep or a wait. This is
 * the one list of the Environment's threads; other pages link here.
 *
 * <table>
 * <caption>The Environment's threads</caption>
 * <tr><th>thread</th><th>code</th><th>what it does</th><th>where it blocks</th></tr>
 * <tr><td>{@code simulation-loop}</td><td>{@link robosim.environment.run.SimulationLoop},
 *     {@link robosim.environment.run.Run}</td><td>every step (collect, resolve, release), the roster, pace,
 *     pause, the robots' deadlines, the end; a platform thread, or in a one-JVM run a virtual one beside the
 *     control code ({@link robosim.environment.run.LoopThread})</td><td>its inbox, timed to the next deadline
 *     (a virtual loop: untimed, {@code loop-watch} wakes it); its writes to robots and shared connections (one
 *     frame each after every event), which the connection watch bounds; a full recording queue; with loop
 *     functions in Python, each call's answer on the loop link (a deadline of
 *     {@code LoopScript.CALL_MS} closes the link)</td></tr>
 * <tr><td>{@code loop-watch}</td><td>{@link robosim.environment.run.LoopThread}</td><td>with a virtual loop only:
 *     wakes it at each tick, and gives virtual threads a second carrier when it has not come round for a
 *     second</td><td>a timed wait on the loop's end</td></tr>
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
 * <tr><td>{@code recorder}</td><td>{@link robosim.environment.run.RunRecorder} ({@code --record})</td>
 *     <td>writes the recording from the queue the loop fills after each step</td><td>its queue; the
 *     disk</td></tr>
 * <tr><td>{@code control-io}</td><td>{@code robosim.environment.control.ControlServer} (netty)</td><td>the
 *     control port's one I/O thread: reads request lines, writes replies in each connection's order</td>
 *     <td>its selector</td></tr>
 * <tr><td>{@code control}</td><td>{@code ControlServer}</td><td>the control requests that wait (step, pause,
 *     start, load, add, remove; their verbs say so), one at a time</td><td>its queue; the loop's answer</td></tr>
 * <tr><td>{@code control-quick}</td><td>{@code ControlServer}</td><td>the requests answered at once (status,
 *     robots, resume, stop, shutdown)</td><td>its queue</td></tr>
 * <tr><td>{@code robot-output[name]}</td><td>{@code robosim.environment.control.RobotLaunches}
 *     ({@code --launch-robots})</td><td>one per robot process the control port's {@code add} started: pipes its
 *     output</td><td>its read of that output</td></tr>
 * <tr><td>{@code script-output[loop]}</td><td>{@code robosim.protocol.link.ScriptProcess}, for
 *     {@code robosim.environment.core.LoopScript}</td><td>a daemon, while a world's loop functions in Python run:
 *     logs their script's output line by line</td><td>its read of that output</td></tr>
 * <tr><td>{@code link-deadline}</td><td>{@code robosim.protocol.link.LinkFrames}</td><td>a daemon while a deadline
 *     is set: closes the loop link whose script's hello or call's answer is late</td><td>its timed queue</td></tr>
 * <tr><td>{@code main}</td><td>{@code robosim.environment.EnvironmentMain}</td><td>opens the ports, waits for
 *     each simulation's end, prints the summary</td><td>the end</td></tr>
 * <tr><td>{@code start-announcer}</td><td>{@code EnvironmentMain}</td><td>prints the {@code running} line once
 *     every client is there</td><td>the start</td></tr>
 * <tr><td>{@code shutdown}</td><td>{@code EnvironmentMain}</td><td>the JVM's hook on SIGTERM or SIGINT: stops the
 *     simulation, so every client is told</td><td>the end, at most a few seconds</td></tr>
 * <tr><td>{@code web-io}, {@code web-status}, {@code web-commands}, {@code web-feed}, {@code web-watch-N},
 *     {@code viewer-client}</td><td>{@code robosim.web} ({@code --web-port})</td><td>the browser viewer: its
 *     HTTP and WebSocket I/O, its pages' requests, and its own viewer connections to the viewer port (listed in
 *     its package)</td><td>as listed there</td></tr>
 * <tr><td>{@code control[name]}</td><td>{@code robosim.hardware.HardwareSimulator} ({@code --one-jvm})</td>
 *     <td>one per robot in this JVM: its control code (a virtual thread on JDK 21 and later)</td><td>the
 *     robot's own calls, until the loop gives its step</td></tr>
 * </table>
 * With {@code --no-geometry} (and {@code --one-jvm}) the geometry library's sonar pass may also use one worker
 * of the JVM's common fork-join pool on the loop's behalf (its package-info says when); the loop waits for it
 * within the step. With {@code --one-jvm} the file's robots start no thread here: their control threads hand their
 * requests to {@link robosim.environment.net.InMemoryTransport}, and the last one owed wakes the loop.
 * A replay ({@code robosim.environment.replay}) has its own clock thread and this package's
 * {@link robosim.environment.run.Inbox}, and serves its viewers with the same server layer as the Environment
 * ({@code robosim.environment.server}); its threads are listed in its package.
 */
package robosim.environment.net;
