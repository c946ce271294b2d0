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
 * ({@link Log#apply}). Bounded: {@link #MAX_TRACES} traces and {@link #MAX_POINTS} points in a drawing.
 *
 * <p>A piece is a range of a {@link Log}'s arrays, which only grow (a grown array is a copy; an erasure makes new
 * ones): it stays as it was made while the log draws on, so the loop hands it to other threads as it is.
 */
public final class Traces {
    /** The most traces a drawing has. */
    public static final int MAX_TRACES = 1024;
    /** The most points a drawing has. */
    public static final int MAX_POINTS = 100_000;
    /** The longest name of a trace, characters. */
    public static final int MAX_NAME = 64;
    /** Nothing new. */
    public static final Traces NONE = new Traces(false, new String[0], new int[0], 0, 0, new int[0], new double[0],
            new double[0], 0, 0);

    private final boolean fresh;
    private final String[] names;
    private final int[] rgb;
    private final int traceFrom;
    private final int traceTo;
    private final int[] of;
    private final double[] x;
    private final double[] y;
    private final int pointFrom;
    private final int pointTo;

    private Traces(boolean fresh, String[] names, int[] rgb, int traceFrom, int traceTo, int[] of, double[] x,
            double[] y, int pointFrom, int pointTo) {
        this.fresh = fresh;
        this.names = names;
        this.rgb = rgb;
        this.traceFrom = traceFrom;
        this.traceTo = traceTo;
        this.of = of;
        this.x = x;
        this.y = y;
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
        return names[check(t, traceFrom, traceTo)];
    }

    /** The colour ({@code 0xRRGGBB}) of the drawing's trace {@code t}, one this piece begins. */
    public int rgb(int t) {
        return rgb[check(t, traceFrom, traceTo)];
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
        return of[check(p, pointFrom, pointTo)];
    }

    public double xMm(int p) {
        return x[check(p, pointFrom, pointTo)];
    }

    public double yMm(int p) {
        return y[check(p, pointFrom, pointTo)];
    }

    private static int check(int i, int from, int to) {
        if (i < from || i >= to) {
            throw new IndexOutOfBoundsException(i + " is not in " + from + " to " + (to - 1));
        }
        return i;
    }

    /**
     * This piece followed by {@code later}, both of one log in the order made (a viewer that is sent the newest of
     * many updates is sent what all of them drew); were they not one after the other, all that {@code later}'s log
     * holds, as a fresh piece.
     */
    public Traces then(Traces later) {
        if (later.fresh || isEmpty()) {
            return later;
        }
        if (later.isEmpty()) {
            return this;
        }
        if (later.traceFrom != traceTo || later.pointFrom != pointTo) { // (not one after the other: all of later's)
            return new Traces(true, later.names, later.rgb, 0, later.traceTo, later.of, later.x, later.y, 0,
                    later.pointTo);
        }
        return new Traces(fresh, later.names, later.rgb, traceFrom, later.traceTo, later.of, later.x, later.y,
                pointFrom, later.pointTo);
    }

    // ---- the wire ----------------------------------------------------------------------------------------------

    /** Writes the piece: fresh, its first trace's place, its traces (name, colour), its first point's, its points. */
    public void write(ObjectOutput out) throws IOException {
        out.writeBoolean(fresh);
        out.writeInt(traceFrom);
        out.writeInt(traceTo - traceFrom);
        for (int t = traceFrom; t < traceTo; t++) {
            out.writeUTF(names[t]);
            out.writeInt(rgb[t]);
        }
        out.writeInt(pointFrom);
        out.writeInt(pointTo - pointFrom);
        for (int p = pointFrom; p < pointTo; p++) {
            out.writeShort(of[p]);
            out.writeDouble(x[p]);
            out.writeDouble(y[p]);
        }
    }

    /** A piece as {@link #write} wrote it, checked: within the bounds, its points on traces there are, finite. */
    public static Traces read(ObjectInput in) throws IOException {
        boolean fresh = in.readBoolean();
        int traceFrom = Limits.checkCount("first trace", in.readInt(), MAX_TRACES);
        int traces = Limits.checkCount("trace count", in.readInt(), MAX_TRACES - traceFrom);
        if (fresh && traceFrom != 0) {
            throw new ProtocolException("a fresh drawing's traces start at " + traceFrom + ", not 0");
        }
        String[] names = new String[traceFrom + traces];
        int[] rgb = new int[traceFrom + traces];
        for (int t = traceFrom; t < names.length; t++) {
            names[t] = in.readUTF();
            if (names[t].isEmpty() || names[t].length() > MAX_NAME) {
                throw new ProtocolException("a trace's name of " + names[t].length() + " characters (1 to " + MAX_NAME
                        + ")");
            }
            rgb[t] = in.readInt() & 0xFFFFFF;
        }
        int pointFrom = Limits.checkCount("first point", in.readInt(), MAX_POINTS);
        int points = Limits.checkCount("point count", in.readInt(), MAX_POINTS - pointFrom);
        if (fresh && pointFrom != 0) {
            throw new ProtocolException("a fresh drawing's points start at " + pointFrom + ", not 0");
        }
        int[] of = new int[pointFrom + points];
        double[] x = new double[of.length];
        double[] y = new double[of.length];
        for (int p = pointFrom; p < of.length; p++) {
            of[p] = in.readUnsignedShort();
            x[p] = in.readDouble();
            y[p] = in.readDouble();
            if (of[p] >= names.length || !Double.isFinite(x[p]) || !Double.isFinite(y[p])) {
                throw new ProtocolException("point " + p + " of trace " + of[p] + " (of " + names.length + ") at ("
                        + x[p] + ", " + y[p] + ")");
            }
        }
        return new Traces(fresh, names, rgb, traceFrom, names.length, of, x, y, pointFrom, of.length);
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

        /** The name of trace {@code t}. */
        public String name(int t) {
            return names[check(t, 0, traces)];
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
            return new Traces(true, names, rgb, 0, traces, of, x, y, 0, points);
        }

        /** What was drawn since the last call (or the start): the next piece. */
        public Traces since() {
            Traces piece = erased || traceMark != traces || pointMark != points
                    ? new Traces(erased, names, rgb, traceMark, traces, of, x, y, pointMark, points) : NONE;
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
                erased = false;
            }
            if (piece.traceFrom > traces || piece.pointFrom > points) {
                throw new ProtocolException("a piece of a drawing from trace " + piece.traceFrom + " and point "
                        + piece.pointFrom + " does not follow " + traces + " traces and " + points + " points");
            }
            for (int t = traces; t < piece.traceTo; t++) {
                begin(piece.names[t], piece.rgb[t]);
            }
            for (int p = points; p < piece.pointTo; p++) {
                if (piece.of[p] >= traces) {
                    throw new ProtocolException("point " + p + " of trace " + piece.of[p] + ", of " + traces);
                }
                point(piece.of[p], piece.x[p], piece.y[p]);
            }
        }

        /** Trace {@code t}'s colour. */
        public int rgb(int t) {
            return rgb[check(t, 0, traces)];
        }

        /** Point {@code p}'s trace, and where it is. */
        public int traceOf(int p) {
            return of[check(p, 0, points)];
        }

        public double xMm(int p) {
            return x[check(p, 0, points)];
        }

        public double yMm(int p) {
            return y[check(p, 0, points)];
        }
    }
}
