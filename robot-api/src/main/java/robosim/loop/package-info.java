/**
 * An experiment's own code, run by the simulator inside the world while it steps: {@link robosim.loop.LoopFunctions}
 * (ARGoS's loop functions) and the {@link robosim.loop.Experiment} it sees and changes. Unlike {@code robosim.api},
 * this package names the simulator: it never runs on a real robot. No threads of its own: everything here is called
 * on the Environment's {@code simulation-loop} thread (or the stepper's own: the learning host, a benchmark).
 */
package robosim.loop;
