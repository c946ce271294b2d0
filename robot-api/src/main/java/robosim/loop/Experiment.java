package robosim.loop;

import java.nio.file.Path;
import java.util.Map;
import java.util.random.RandomGenerator;

/**
 * The world as an experiment's {@link LoopFunctions} see and change it. Units as the robot API's: millimetres (the
 * arena's lower-left corner at the origin), degrees counter-clockwise from +x, colours {@code 0xRRGGBB}. Robots,
 * objects and lights are numbered in world order, from 0. What it changes takes effect at once for what it reads
 * next, and for the robots at the next step's sensing.
 */
public interface Experiment {
    /** Steps completed: 0 in {@link LoopFunctions#init} and in the first {@link LoopFunctions#preStep}. */
    long step();

    /** The length of a step, ms. */
    long stepMs();

    /** The run's seed. */
    long seed();

    /** The experiment's own random numbers: seeded by the run's seed, used by nothing else. */
    RandomGenerator random();

    /** The {@code <param>}s of {@code <loopFunctions>}, in file order. */
    Map<String, String> parameters();

    /** Parameter {@code name}, or {@code fallback} when the file gives none. */
    default String parameter(String name, String fallback) {
        return parameters().getOrDefault(name, fallback);
    }

    /** Parameter {@code name} as a number; a value that is not one is an IllegalArgumentException naming it. */
    default double parameter(String name, double fallback) {
        String value = parameters().get(name);
        if (value == null) {
            return fallback;
        }
        try {
            return Double.parseDouble(value.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("loop functions parameter " + name + " is '" + value
                    + "', not a number");
        }
    }

    /** The arena's width and height, mm. */
    double arenaWidthMm();

    double arenaHeightMm();

    // ---- robots --------------------------------------------------------------------------------------------

    int robots();

    String robotName(int robot);

    /** Its type's name ({@code foot-bot}, {@code e-puck}, ...). */
    String robotType(int robot);

    double robotXMm(int robot);

    double robotYMm(int robot);

    double robotHeadingDeg(int robot);

    /** False once it has left the run. */
    boolean present(int robot);

    /** Its LEDs' colours as it last set them (empty: it has none). */
    int[] leds(int robot);

    /** The object it holds in its gripper, or -1. */
    int carrying(int robot);

    /**
     * Puts it at a pose (its next step starts there), letting go of what it holds (that stays where it was); false,
     * and nothing moved, where it would overlap something.
     */
    boolean moveRobot(int robot, double xMm, double yMm, double headingDeg);

    /**
     * A text message to it, from {@code loop}, in its next step's messages (as another robot's; a world with loop
     * functions may have no robot named {@code loop}). At most 10,000 wait for one robot (fewer for one away).
     */
    void tell(int robot, String text);

    // ---- objects -------------------------------------------------------------------------------------------

    int objects();

    String objectName(int object);

    double objectXMm(int object);

    double objectYMm(int object);

    double objectHeadingDeg(int object);

    /** The robot holding it, or -1. */
    int carrier(int object);

    /**
     * Puts it at a pose, let go of by whoever held it; false, and nothing moved, where it would overlap a wall, an
     * obstacle, a robot or another object. An object out of the world is an IllegalStateException ({@link #addObject}).
     */
    boolean moveObject(int object, double xMm, double yMm, double headingDeg);

    /** False once {@link #removeObject} took it out of the world (until {@link #addObject} puts it back). */
    boolean objectPresent(int object);

    /**
     * Takes it out of the world, let go of by whoever held it: nothing meets, senses or grips it from the step's moves
     * on (in a pre-step, this step's; in a post-step, the next), and the viewers leave it out (ARGoS's
     * {@code RemoveEntity}). A world's objects are its file's: one taken out
     * keeps its number, and its last pose.
     */
    void removeObject(int object);

    /**
     * Puts an object {@link #removeObject} took out back into the world, at a pose (ARGoS's {@code AddEntity}, of an
     * object the file declared); false, and it stays out, where it would overlap something. An object in the world is
     * an IllegalStateException.
     */
    boolean addObject(int object, double xMm, double yMm, double headingDeg);

    // ---- floor and lights ----------------------------------------------------------------------------------

    /** The floor's colour at a point, as ground sensors read it (the file's floor with this code's paint over it). */
    int floorColour(double xMm, double yMm);

    /** Paints a disc over the floor (over everything painted before). */
    void paintDisc(double xMm, double yMm, double radiusMm, int rgb);

    /** Paints an axis-aligned rectangle over the floor, its lower-left corner at (x, y). */
    void paintRectangle(double xMm, double yMm, double widthMm, double heightMm, int rgb);

    /** Takes away everything this code painted: the file's floor again. */
    void erasePaint();

    int lights();

    String lightName(int light);

    boolean lightOn(int light);

    /** Switches a light on or off. */
    void switchLight(int light, boolean on);

    // ---- drawing for the viewers ----------------------------------------------------------------------------

    /**
     * Draws over the world for the viewers (ARGoS's Qt user functions' drawings): extends the trace {@code name}, a
     * line of colour {@code rgb} (its first point's), to a point; a new name begins a new trace. Not sensed, in no
     * result; recorded and replayed. A drawing holds at most 1,024 traces and 100,000 points (then
     * {@link #eraseTraces} first); a name has 1 to 64 characters.
     */
    void trace(String name, double xMm, double yMm, int rgb);

    /** Erases every trace drawn. */
    void eraseTraces();

    // ---- the run -------------------------------------------------------------------------------------------

    /**
     * A number of the run, as a robot's {@code report}: recorded with the step, a column of a sweep's tables (its
     * newest value), plotted like the built-in metrics; a name of 1 to 64 letters, digits, {@code _ . -}.
     */
    void report(String name, double value);

    /** Ends the run after this step, as planned, with {@code reason} as its end's reason. */
    void end(String reason);

    /**
     * Where this run's own output files go: the run's {@code --output-dir} (a sweep gives each run its own,
     * {@code DIR/outputs/run-N/}), else the working directory. A file the code writes there is its own (ARGoS's
     * foraging writes {@code foraging.txt}).
     */
    Path outputDirectory();
}
