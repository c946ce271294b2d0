package robosim.protocol;

import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;

/**
 * Counts the bytes read since {@link #startMessage()} and fails once a message has used more than
 * its budget, so a peer cannot make us read an endless object. The object stream above it may read
 * a little ahead, so the bound is approximate by at most one buffer.
 */
final class MessageBudgetInputStream extends FilterInputStream {
    private volatile long budget;
    private long used;

    MessageBudgetInputStream(InputStream in, long budget) {
        super(in);
        this.budget = budget;
    }

    /** The budget of each message from now on (the reading thread, or before it reads). */
    void budget(long bytes) {
        budget = bytes;
    }

    void startMessage() {
        used = 0;
    }

    /** Bytes taken from the stream since the message began. */
    long used() {
        return used;
    }

    /** True once the stream under it has ended (the peer closed its side). */
    boolean ended() {
        return ended;
    }

    private boolean ended;

    private void count(long n) throws ProtocolException {
        if (n > 0) {
            used += n;
            if (used > budget) {
                throw new ProtocolException("message exceeds " + budget + " bytes: read " + used);
            }
        }
    }

    @Override
    public int read() throws IOException {
        int b = super.read();
        if (b >= 0) {
            count(1);
        } else {
            ended = true;
        }
        return b;
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        int n = super.read(b, off, len);
        count(n);
        ended |= n < 0;
        return n;
    }

    @Override
    public long skip(long n) throws IOException {
        long skipped = super.skip(n);
        count(skipped);
        return skipped;
    }
}
