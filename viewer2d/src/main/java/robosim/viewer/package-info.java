/**
 * The 2D viewer. Threads: {@code viewer-client} (network, one per connection: reads the Environment's
 * updates and publishes an immutable {@link robosim.viewer.Scene} for each update (at most the frame rate's a second), through
 * {@link robosim.viewer.SceneFeed}), {@code viewer-follow} ({@link robosim.viewer.RunFollower}: waits
 * for each connection to end, then reconnects to the next run with backoff; it touches the feed only
 * between connections) and the Swing event thread (everything in
 * {@link robosim.viewer.ViewerWindow} and {@link robosim.viewer.WorldPanel}). The network thread never
 * touches a Swing component; the event thread only reads immutable scenes.
 * {@link robosim.viewer.SceneRenderer} draws a scene onto any Graphics2D, on screen or off.
 * The robot-specific viewer ({@link robosim.viewer.RobotWindow}, {@code --watch ROBOT} or a click on a
 * robot) has its own connection with the same two threads, feeding a {@link robosim.viewer.RobotFeed}
 * that the event thread polls; {@link robosim.viewer.RobotRenderer} draws it. A click opens that
 * connection on {@code robot-window-open}, a short-lived thread, never on the event thread.
 */
package robosim.viewer;
