/**
 * One simulation run and the loop that owns its time: no socket, no transport (those are
 * {@code robosim.environment.net}'s), no world logic (the core's, {@code robosim.environment.core}).
 *
 * <ul>
 * <li>The run, loop thread only, and drivable by hand (a test drives it with a fake clock, no thread, no socket):
 *     {@link robosim.environment.run.Run} (time and the order of a step: start, begin, collect, resolve, release,
 *     publish) and its parts, each owning its state: {@link robosim.environment.run.Progress} (the phase machine),
 *     {@link robosim.environment.run.Roster} (the robots and their lifecycle: the transitions are its own),
 *     {@link robosim.environment.run.Admission} (the verdicts on hellos, {@code add}, {@code remove}),
 *     {@link robosim.environment.run.RunControl} and {@link robosim.environment.run.ReleasePoint} (pause, step N,
 *     pace), {@link robosim.environment.run.GeometryLink} (where steps are resolved, the Geometry timeout and
 *     failover), {@link robosim.environment.run.StatusBoard} (the status, derived from the parts) publishing a
 *     {@link robosim.environment.run.PublishedRun} (which owns what it publishes) and, after each release, one
 *     immutable {@link robosim.environment.run.ReleasedWorld}; its outputs are a
 *     {@link robosim.environment.run.RunListener} and {@link robosim.environment.run.ReleaseListener}s
 *     ({@link robosim.environment.run.RunViewers}, {@link robosim.environment.run.RunRecorder}); how it runs, its
 *     {@link robosim.environment.run.Settings}.</li>
 * <li>The one owner of time: {@link robosim.environment.run.SimulationLoop} (the loop thread and its
 *     {@link robosim.environment.run.Inbox}) applies each {@link robosim.environment.run.LoopEvent} to the run, then
 *     lets the transports' {@link robosim.environment.run.LoopHook}s hand in and write.</li>
 * <li>The seams the transports meet it at: a robot is a {@link robosim.environment.run.RobotPeer} (its hello checked
 *     by the {@link robosim.environment.run.HelloCheck} on its reader's thread, handed in as
 *     {@link robosim.environment.run.Hellos}), a Geometry process a {@link robosim.environment.run.GeometryPeer}.</li>
 * </ul>
 *
 * <p>Threads here: {@code simulation-loop} ({@link robosim.environment.run.SimulationLoop}), {@code loop-watch}
 * ({@link robosim.environment.run.LoopThread}, with a virtual loop) and {@code recorder}
 * ({@link robosim.environment.run.RunRecorder}); the one list of the Environment's threads, what each does and
 * where it blocks, is {@code robosim.environment.net}'s package page.
 */
package robosim.environment.run;
