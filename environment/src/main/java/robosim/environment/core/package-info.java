/**
 * The simulation core: plain objects, no threads, and it calls out only to a world's loop functions
 * ({@link robosim.environment.core.ExperimentCode}: the experiment's own code, between a step's phases, on the calling
 * thread; loop functions in Python, {@link robosim.environment.core.LoopScript}, are the one socket here: the loop
 * link to their script, each call's answer awaited under a deadline).
 * {@link robosim.environment.core.WorldSpec} is the loaded file;
 * {@link robosim.environment.core.SimulationCore} owns the world state
 * ({@link robosim.environment.core.EnvironmentMap}) and turns one step's requests into that step's
 * Geometry request ({@code prepare}) and, from Geometry's checked answer, into the step's responses
 * ({@code complete}). Called only by the Environment's {@code simulation-loop} thread.
 */
package robosim.environment.core;
