/**
 * Replaying a recording ({@code scripts/replay.sh FILE}): the viewer port serves it exactly as the live
 * Environment served the run, and the control port steers it (pause, resume, step, seek, speed). Threads:
 * {@code replay-clock} (the one owner of the replay's position and time: {@link
 * robosim.environment.replay.ReplayClock}), {@code accept-viewers} (hands each connection to a viewer
 * thread, under the connection cap), {@code connection-watch} (cuts off a viewer whose hello is late or
 * that does not take a write in time: {@link robosim.environment.server.ConnectionWatch}),
 * {@code replay-viewer[n]} (one per viewer, a {@link robosim.environment.server.ViewerClientWorker}: its handshake, then writes what its queue holds), the control
 * port's {@code control-io}, {@code control} and {@code control-quick}, {@code shutdown} (Ctrl-C: the end
 * to every viewer), {@code main} (waits for the end) and, with {@code --web-port}, the browser viewer's
 * {@code web-io}, {@code web-commands}, {@code web-feed} and its {@code viewer-client} ({@code robosim.web}).
 */
package robosim.environment.replay;
