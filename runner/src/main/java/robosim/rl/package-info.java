/**
 * Learning controllers: K copies of a world stepped together for a learner in another process
 * ({@link robosim.rl.BatchWorlds}, {@link robosim.rl.BatchLink}, {@link robosim.rl.LearningHostMain}; Python's
 * {@code robosim.rl}, python/README.md "Learning controllers"). The thread that serves the link owns time: it reads
 * a step's actions, steps its share of the worlds (world 0 among them) while the others step the rest, and answers.
 *
 * <table>
 * <caption>threads</caption>
 * <tr><th>thread</th><th>role</th></tr>
 * <tr><td>{@code main}</td><td>accepts connections until one is the learner's, then serves its link: the owner of
 * time</td></tr>
 * <tr><td>{@code link-hello[n]}</td><td>daemons, one a connection while the learner is awaited
 * (robosim.protocol.link.FirstHello, at most 16 at once): each reads its connection's hello and answers it</td></tr>
 * <tr><td>{@code rl-worlds[t]}</td><td>daemons, one fewer than the threads asked for (the cores, at most the
 * worlds; {@link robosim.rl.StepCrew}): each steps its share of the worlds while {@code main} steps its own, and
 * nothing else; between steps it spins for half a millisecond, then parks</td></tr>
 * <tr><td>{@code link-deadline}</td><td>the links' (robosim.protocol.link.LinkFrames): closes a learner's
 * connection whose hello is late (a deadline), and a world's loop link whose script's answer is late</td></tr>
 * <tr><td>{@code script-output[loop]}</td><td>robosim.protocol.link.ScriptProcess: one a world whose loop functions
 * are a Python script, logging its output</td></tr>
 * <tr><td>{@code rl-viewer[n]}</td><td>with {@code --viewer-port} or {@code --web-port}: one a viewer, as an
 * Environment's viewer workers (robosim.environment.server), fed world 0 through a bounded queue; with them that
 * package's {@code accept-viewers} and {@code connection-watch}, and with {@code --web-port} the browser viewer's
 * {@code web-*} threads (robosim.web)</td></tr>
 * </table>
 */
package robosim.rl;
