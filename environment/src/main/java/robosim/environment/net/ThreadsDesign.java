package robosim.environment.net;

/**
 * {@code THREADS}, the paper's design and the default: one thread per robot ({@code robot-worker[name]})
 * reads its requests and posts each to the loop; the loop writes every response itself (the
 * connection watch bounds those writes). Everything {@link Design} does by default.
 */
final class ThreadsDesign implements Design {
}
