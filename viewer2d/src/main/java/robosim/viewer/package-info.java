/**
 * The 2D viewer. Threads: {@code viewer-client} (network, one per connection: reads the Environment's
 * updates and publishes an immutable {@link robosim.viewer.Scene} at most once a frame, through
 * {@link robosim.viewer.SceneFeed}), {@code viewer-follow} ({@link robosim.viewer.RunFollower}: waits
 * for each connection to end, then reconnects to the next run with backoff; it touches the feed only
 * between connections) and the Swing event thread (everything in
 * {@link robosim.viewer.ViewerWindow} and {@link robosim.viewer.WorldPanel}). The network thread never
 * touches a Swing component; the event thread only reads immutable scenes.
 * {@link robosim.viewer.SceneRenderer} draws a scene onto any Graphics2D, on screen or off.
 */
package robosim.viewer;
