/**
 * The object ports' server layer, the same for the live Environment and a replay: {@link
 * robosim.environment.server.Acceptors} (the listening sockets, their {@code accept-*} threads, the caps), {@link
 * robosim.environment.server.ClientWorker} (a thread per connection, its one failure policy) with its {@link
 * robosim.environment.server.Handshake} (the stranger's limits and {@link robosim.environment.server.StrangerBudget},
 * the secret's proof, the verdict, the refusal), {@link robosim.environment.server.ConnectionClock} and {@link
 * robosim.environment.server.ConnectionWatch} (every connection's deadlines, one mechanism), and the viewers' side:
 * {@link robosim.environment.server.ViewerClientWorker} (one viewer's thread, whoever publishes to it: a {@link
 * robosim.environment.server.ViewerHost}), {@link robosim.environment.server.ViewerQueue} and {@link
 * robosim.environment.server.Viewers}. A worker is given a {@link robosim.environment.server.ServerContext} and
 * nothing of whoever serves it; what a port says of itself is its {@link robosim.environment.server.PortGuide}.
 *
 * <p>Threads made here: {@code accept-robots}, {@code accept-viewers}, {@code accept-geometry}, {@code
 * connection-watch}, and one worker per connection ({@code viewer-worker[n]} for the Environment, {@code
 * replay-viewer[n]} for a replay; the robot and Geometry workers are the Environment's). Each is listed, with where
 * it blocks, in the Environment's thread table ({@code robosim.environment.net}'s package documentation) and the
 * replay's ({@code robosim.environment.replay}'s).
 */
package robosim.environment.server;
