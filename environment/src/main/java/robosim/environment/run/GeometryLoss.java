package robosim.environment.run;

/**
 * What the Environment does when its Geometry process dies, hangs or answers nonsense mid-run:
 * {@code IN_PROCESS} (the default) resolves that step, and every later one, with the same geometry
 * library in-process (same results, bit for bit) until a new Geometry process attaches; {@code WAIT}
 * holds the step until a new Geometry process attaches.
 */
public enum GeometryLoss { IN_PROCESS, WAIT }
