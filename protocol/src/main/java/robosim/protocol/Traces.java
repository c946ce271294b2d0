package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * Lines a world's loop functions draw over it for the viewers (ARGoS's drawings in its Qt user functions): each a
 * named trace, a polyline of one colour, its points in the order drawn; not sensed, not moved, in no result. A value
 * of this class is a piece of a drawing: the traces begun and the points added since a moment, after the erasure of
 * everything drawn before where it is {@link #fresh}; the whole drawing is the fresh piece of everything
 * ({@link Log#whole}). A point names its trace by its place among all the drawing's traces, so pieces apply in order
 * ({@link Log#apply}). Bounded: {@link #MAX_TRACES} traces and {@link #MAX_POINTS} points in a drawing, a trace's name
 * {@link #MAX_NAME} characters (the limits {@code robosim.loop.Experiment#trace} states).
 *
 * <p>A piece made by a {@link Log} is a range of the log's arrays, which only grow (a grown array is a copy; an
 * erasure makes new ones): it stays as it was made while the log draws on, so the loop hands it to other threads as it
 * is. A piece read from the wire holds its own range only.
 */
public final class Traces {
    /** The most traces a drawing has. */
    public static final int MAX_TRACES = 1024;
    /** The most points a drawing has. */
    public static final int MAX_POINTS = 100_000;
    /** The longest name of a trace, characters. */
    public static final int MAX_NAME = 64;
    /** Nothing new. */
    public static final Traces NONE = new Traces(false, null, new String[0], new int[0], 0, 0, 0, new int[0],
            new double[0], new double[0], 0, 0, 0);

    private final boolean fresh;
    /** The log whose arrays these are (pieces of one log may share them), or null for arrays of this piece's own. */
    private final Log source;
    private final String[] names;
    private final int[] rgb;
    /** The place of {@code names[0]} among the drawing's traces. */
    private final int traceBase;
    private final int traceFrom;
    private final int traceTo;
    private final int[] of;
    private final double[] x;
    private final double[] y;
    /** The place of {@code of[0]} among the drawing's points. */
    private final int pointBase;
    private final int pointFrom;
    private final int pointTo;

    private Traces(boolean fresh, Log source, String[] names, int[] rgb, int traceBase, int traceFrom, int traceTo,
            int[] of, double[] x, double[] y, int pointBase, int pointFrom, int pointTo) {
        this.fresh = fresh;
        this.source = source;
        this.names = names;
        this.rgb = rgb;
        this.traceBase = traceBase;
        this.traceFrom = traceFrom;
        this.traceTo = traceTo;
        this.of = of;
        this.x = x;
        this.y = y;
        this.pointBase = pointBase;
        this.pointFrom = pointFrom;
        this.pointTo = pointTo;
    }

    /** True if everything drawn before this piece is erased first. */
    public boolean fresh() {
        return fresh;
    }

    /** True if applying it changes nothing. */
    public boolean isEmpty() {
        return !fresh && traceTo == traceFrom && pointTo == pointFrom;
    }

    /** The place, among the drawing's traces, of this piece's first new trace. */
    public int firstTrace() {
        return traceFrom;
    }

    /** Traces this piece begins. */
    public int traces() {
        return traceTo - traceFrom;
    }

    /** The name of the drawing's trace {@code t} (one this piece begins: {@code firstTrace() <= t}). */
    public String name(int t) {
        return names[check(t, traceFrom, traceTo) - traceBase];
    }

    /** The colour ({@code 0xRRGGBB}) of the drawing's trace {@code t}, one this piece begins. */
    public int rgb(int t) {
        return rgb[check(t, traceFrom, traceTo) - traceBase];
    }

    /** The place, among the drawing's points, of this piece's first. */
    public int firstPoint() {
        return pointFrom;
    }

    /** Points this piece adds. */
    public int points() {
        return pointTo - pointFrom;
    }

    /** The trace of the drawing's point {@code p} (one this piece adds: {@code firstPoint() <= p}). */
    public int traceOf(int p) {
        return of[check(p, pointFrom, pointTo) - pointBase];
    }

    public double xMm(int p) {
        return x[check(p, pointFrom, pointTo) - pointBase];
    }

    public double yMm(int p) {
        return y[check(p, pointFrom, pointTo) - pointBase];
    }

    private static int check(int i, int from, int to) {
        if (i < from || i >= to) {
            throw new IndexOutOfBoundsException(i + " is not in " + from + " to " + (to - 1));
        }
        return i;
    }

    /**
     * This piece followed by {@code later}, the one made next (a viewer that is sent the newest of many updates is sent
     * what all of them drew): a range of their log's arrays where they share them, else a copy of both. Pieces that do
     * not follow one another are not joined: {@code later} alone (the viewer that applies it finds the gap).
     */
    public Traces then(Traces later) {
        if (later.fresh || isEmpty()) {
            return later;
        }
        if (later.isEmpty()) {
            return this;
        }
        if (later.traceFrom != traceTo || later.pointFrom != pointTo) {
            return later;
        }
        if (source != null && source == later.source) { // (the later arrays hold this range too: a log only grows)
            return new Traces(fresh, source, later.names, later.rgb, later.traceBase, traceFrom, later.traceTo,
                    later.of, later.x, later.y, later.pointBase, pointFrom, later.pointTo);
        }
        int traces = later.traceTo - traceFrom;
        int points = later.pointTo - pointFrom;
        String[] n = new String[traces];
        int[] c = new int[traces];
        for (int t = traceFrom; t < later.traceTo; t++) {
            Traces from = t < traceTo ? this : later;
            n[t - traceFrom] = from.name(t);
            c[t - traceFrom] = from.rgb(t);
        }
        int[] o = new int[points];
        double[] px = new double[points];
        double[] py = new double[points];
        for (int p = pointFrom; p < later.pointTo; p++) {
            Traces from = p < pointTo ? this : later;
            o[p - pointFrom] = from.traceOf(p);
            px[p - pointFrom] = from.xMm(p);
            py[p - pointFrom] = from.yMm(p);
        }
        return new Traces(fresh, null, n, c, traceFrom, traceFrom, later.traceTo, o, px, py, pointFrom, pointFrom,
                later.pointTo);
    }

    // ---- the wire ----------------------------------------------------------------------------------------------

    /** Writes the piece: fresh, its first trace's place, its traces (name, colour), its first point's, its points. */
    public void write(ObjectOutput out) throws IOException {
        out.writeBoolean(fresh);
        out.writeInt(traceFrom);
        out.writeInt(traceTo - traceFrom);
        for (int t = traceFrom; t < traceTo; t++) {
            out.writeUTF(name(t));
            out.writeInt(rgb(t));
        }
        out.writeInt(pointFrom);
        out.writeInt(pointTo - pointFrom);
        for (int p = pointFrom; p < pointTo; p++) {
            out.writeShort(traceOf(p));
            out.writeDouble(xMm(p));
            out.writeDouble(yMm(p));
        }
    }

    /**
     * A piece as {@link #write} wrote it, checked: within the bounds, names of 1 to {@link #MAX_NAME} characters,
     * colours {@code 0xRRGGBB}, its points finite and on traces there are; its arrays hold its own range only.
     */
    public static Traces read(ObjectInput in) throws IOException {
        boolean fresh = in.readBoolean();
        int traceFrom = Limits.checkCount("first trace", in.readInt(), MAX_TRACES);
        int traces = Limits.checkCount("trace count", in.readInt(), MAX_TRACES - traceFrom);
        if (fresh && traceFrom != 0) {
            throw new ProtocolException("a fresh drawing's traces start at " + traceFrom + ", not 0");
        }
        String[] names = new String[traces];
        int[] rgb = new int[traces];
        for (int t = 0; t < traces; t++) {
            names[t] = in.readUTF();
            if (names[t].isEmpty() || names[t].length() > MAX_NAME) {
                throw new ProtocolException("a trace's name of " + names[t].length() + " characters (1 to " + MAX_NAME
                        + ")");
            }
            rgb[t] = in.readInt();
            if (rgb[t] < 0 || rgb[t] > 0xFFFFFF) {
                throw new ProtocolException("a trace's colour " + rgb[t] + " (0xRRGGBB)");
            }
        }
        int pointFrom = Limits.checkCount("first point", in.readInt(), MAX_POINTS);
        int points = Limits.checkCount("point count", in.readInt(), MAX_POINTS - pointFrom);
        if (fresh && pointFrom != 0) {
            throw new ProtocolException("a fresh drawing's points start at " + pointFrom + ", not 0");
        }
        int[] of = new int[points];
        double[] x = new double[points];
        double[] y = new double[points];
        for (int k = 0; k < points; k++) {
            of[k] = in.readUnsignedShort();
            x[k] = in.readDouble();
            y[k] = in.readDouble();
            if (of[k] >= traceFrom + traces || !Double.isFinite(x[k]) || !Double.isFinite(y[k])) {
                throw new ProtocolException("point " + (pointFrom + k) + " of trace " + of[k] + " (of "
                        + (traceFrom + traces) + ") at (" + x[k] + ", " + y[k] + ")");
            }
        }
        return new Traces(fresh, null, names, rgb, traceFrom, traceFrom, traceFrom + traces, of, x, y, pointFrom,
                pointFrom, pointFrom + points);
    }

    // ---- the drawing ----------------------------------------------------------------------------------------

    /**
     * A whole drawing, drawn on (by its loop functions' {@code trace}) or pieced together (by a viewer, {@link #apply}),
     * on one thread; its {@link #whole} and {@link #since} are {@link Traces} that stay as they were made.
     */
    public static final class Log {
        private String[] names = new String[4];
        private int[] rgb = new int[4];
        private int traces;
        private final Map<String, Integer> byName = new HashMap<>();
        private int[] of = new int[16];
        private double[] x = new double[16];
        private double[] y = new double[16];
        private int points;
        /** Where the next {@link #since} starts: traces and points, and whether the drawing was erased since. */
        private int traceMark;
        private int pointMark;
        private boolean erased;

        public int traces() {
            return traces;
        }

        public int points() {
            return points;
        }

        /**
         * Adds a point to trace {@code name} (begun, in {@code rgb}, if it is new); an IllegalArgumentException
         * for a name of no or over {@link #MAX_NAME} characters, a point that is not finite or a colour beyond
         * {@code 0xFFFFFF}, an IllegalStateException beyond {@link #MAX_TRACES} or {@link #MAX_POINTS}.
         */
        public void add(String name, double xMm, double yMm, int colour) {
            if (name == null || name.isEmpty() || name.length() > MAX_NAME) {
                throw new IllegalArgumentException("a trace's name has 1 to " + MAX_NAME + " characters, got "
                        + (name == null ? "none" : Printable.of(name, 80)));
            }
            if (!Double.isFinite(xMm) || !Double.isFinite(yMm)) {
                throw new IllegalArgumentException("trace " + name + ": a point of finite numbers, got (" + xMm
                        + ", " + yMm + ")");
            }
            if (colour < 0 || colour > 0xFFFFFF) {
                throw new IllegalArgumentException("a colour is 0xRRGGBB, got " + colour);
            }
            Integer t = byName.get(name);
            if (t == null && traces >= MAX_TRACES) {
                throw new IllegalStateException("a drawing holds at most " + MAX_TRACES + " traces: erase first");
            }
            if (points >= MAX_POINTS) {
                throw new IllegalStateException("a drawing holds at most " + MAX_POINTS + " points: erase first");
            }
            if (t == null) {
                t = begin(name, colour);
            }
            point(t, xMm, yMm);
        }

        private int begin(String name, int colour) {
            if (traces == names.length) {
                names = Arrays.copyOf(names, 2 * traces);
                rgb = Arrays.copyOf(rgb, 2 * traces);
            }
            names[traces] = name;
            rgb[traces] = colour;
            byName.put(name, traces);
            return traces++;
        }

        private void point(int t, double xMm, double yMm) {
            if (points == of.length) { // (a copy: the pieces made before keep the arrays they were made of)
                of = Arrays.copyOf(of, 2 * points);
                x = Arrays.copyOf(x, 2 * points);
                y = Arrays.copyOf(y, 2 * points);
            }
            of[points] = t;
            x[points] = xMm;
            y[points] = yMm;
            points++;
        }

        /** Erases everything drawn: new arrays, so the pieces made before keep theirs. */
        public void erase() {
            names = new String[4];
            rgb = new int[4];
            traces = 0;
            byName.clear();
            of = new int[16];
            x = new double[16];
            y = new double[16];
            points = 0;
            traceMark = 0;
            pointMark = 0;
            erased = true;
        }

        /** The whole drawing: a fresh piece of everything. */
        public Traces whole() {
            return new Traces(true, this, names, rgb, 0, 0, traces, of, x, y, 0, 0, points);
        }

        /** What was drawn since the last call (or the start, or an erasure: then a fresh piece): the next piece. */
        public Traces since() {
            Traces piece = erased || traceMark != traces || pointMark != points
                    ? new Traces(erased, this, names, rgb, 0, traceMark, traces, of, x, y, 0, pointMark, points) : NONE;
            traceMark = traces;
            pointMark = points;
            erased = false;
            return piece;
        }

        /**
         * Applies the next piece of a drawing made elsewhere (a viewer's): a fresh one erases first; what the drawing
         * holds already of it is skipped (the whole drawing of a snapshot holds its step's piece); one that would
         * leave a gap is refused.
         */
        public void apply(Traces piece) throws ProtocolException {
            if (piece.fresh) {
                erase();
            }
            if (piece.traceFrom > traces || piece.pointFrom > points) {
                throw new ProtocolException("a piece of a drawing from trace " + piece.traceFrom + " and point "
                        + piece.pointFrom + " does not follow " + traces + " traces and " + points + " points");
            }
            for (int t = traces; t < piece.traceTo; t++) {
                begin(piece.name(t), piece.rgb(t));
            }
            for (int p = points; p < piece.pointTo; p++) {
                if (piece.traceOf(p) >= traces) {
                    throw new ProtocolException("point " + p + " of trace " + piece.traceOf(p) + ", of " + traces);
                }
                point(piece.traceOf(p), piece.xMm(p), piece.yMm(p));
            }
        }
    }
}
