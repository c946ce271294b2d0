/**
 * The simulation core: plain objects, no sockets, no threads. {@link robosim.environment.core.WorldSpec}
 * is the loaded file; {@link robosim.environment.core.SimulationCore} owns the world state
 * ({@link robosim.environment.core.EnvironmentMap}) and turns one step's requests into that step's
 * responses. Called by exactly one thread at a time (the thread that releases the step).
 */
package robosim.environment.core;
