package robosim.environment.server;

/**
 * One viewer as the one who publishes to it sees it: its {@link ViewerQueue}, filled by the publisher and
 * never waited on, and a thread of its own that writes what the queue holds to the viewer. The
 * Environment's viewer workers and a replay's viewers are such viewers.
 */
public interface ViewerSink {
    /** Its queue, once it has said hello. */
    ViewerQueue queue();

    /** Its name for log lines, e.g. {@code viewer-worker[3]}. */
    String viewerName();

    /** Closes its connection, so its blocked write ends. Any thread. */
    void drop();

    /** Waits until it has sent everything it holds (or its connection is gone); true if it has. */
    boolean awaitDone(long nanos) throws InterruptedException;
}
