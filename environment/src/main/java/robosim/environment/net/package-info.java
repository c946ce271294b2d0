/**
 * The Environment's client interface: sockets and threads only, no world logic. The
 * {@link robosim.environment.net.ClientWorkerCoordinator} owns the listening sockets and one thread
 * per connected client ({@code robot-worker[name]}, {@code viewer-worker[n]}, {@code geometry-worker}),
 * gathers each step's requests and calls the core on the thread of the last robot worker to arrive.
 */
package robosim.environment.net;
