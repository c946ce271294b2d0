package robosim.environment.core;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;
import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;
import robosim.protocol.Floor;
import robosim.protocol.Light;
import robosim.protocol.Printable;
import robosim.protocol.Report;
import robosim.protocol.WorldObject;

/**
 * A world's loop functions at work ({@link LoopSpec}), and the {@link Experiment} they see: owned by the
 * {@link SimulationCore}, which calls them between its phases ({@link #start}, {@link #preStep}, {@link #postStep},
 * {@link #destroy}), so they run on the one thread that steps the world, in every layout. Keeps what they change that
 * the file did not say: the paint over the floor, the lights switched, the metrics of this step, the end asked for.
 * Whatever the code throws is an {@link ExperimentFailure}, after which it is called no more.
 */
final class ExperimentCode implements Experiment {
    /** Mixed into the run's seed for the experiment's own generator, so it draws what no sensor draws. */
    private static final long SEED_MIX = 0x6c6f6f7066756e63L; // "loopfunc"

    private final LoopSpec spec;
    private final EnvironmentMap map;
    private final RobotActuators actuators;
    private final MessageRouter router;
    private final StepSensing sensing;
    private final SplittableRandom random;
    /** The code while it may be called; null once it threw (and before it was made). */
    private LoopFunctions code;
    /** The code made, whatever happened since: its destroy is called once at the end, even after a throw. */
    private LoopFunctions made;
    private final Floor fileFloor;
    private List<Floor.Region> paint = List.of();
    private Floor floor;
    private final List<Light> fileLights;
    private List<Light> lights;
    private final Map<String, Double> reports = new LinkedHashMap<>();
    /** What the code drew over the world, and the piece of it the last step completed drew. */
    private final robosim.protocol.Traces.Log drawing = new robosim.protocol.Traces.Log();
    private robosim.protocol.Traces stepTraces = robosim.protocol.Traces.NONE;
    /** The metrics reported for the last step completed (from its pre-step, or init, to its post-step). */
    private List<Report> stepReports = List.of();
    private String endReason;
    private long step;
    private Path outputDirectory = Path.of("");
    private boolean started;
    private boolean destroyed;

    ExperimentCode(LoopSpec spec, EnvironmentMap map, RobotActuators actuators, MessageRouter router,
            StepSensing sensing) {
        this.spec = spec;
        this.map = map;
        this.actuators = actuators;
        this.router = router;
        this.sensing = sensing;
        this.random = new SplittableRandom(map.spec().seed() ^ SEED_MIX);
        this.fileFloor = map.spec().scenery().floor();
        this.floor = fileFloor;
        this.fileLights = map.spec().scenery().lights();
        this.lights = fileLights;
    }

    /**
     * Makes the code and starts it, before step 0: {@code kept}, the instance of an earlier run of the same world,
     * {@link LoopFunctions#reset}; else the spec's given instance, or a new instance of its class, initialised. Its
     * files go to {@code directory}.
     */
    void start(Path directory, LoopFunctions kept) {
        if (started) {
            return;
        }
        started = true;
        outputDirectory = directory;
        try {
            java.nio.file.Files.createDirectories(directory.toAbsolutePath());
        } catch (java.io.IOException | RuntimeException e) {
            throw new ExperimentFailure("loop functions " + spec.className() + ": cannot make their output directory "
                    + directory + ": " + e, e);
        }
        if (kept != null) {
            code = kept;
            made = kept;
            call("reset", () -> code.reset(this));
            return;
        }
        if (spec.given() != null) {
            code = spec.given();
            made = code;
            call("init", () -> code.init(this));
            return;
        }
        if (robosim.protocol.ControlScripts.isScript(spec.className())) {
            code = new LoopScript(spec.className());
            made = code;
            call("init", () -> code.init(this));
            return;
        }
        try { // (the class looked at before any of its code runs: a world file may name any class)
            code = Class.forName(spec.className(), false, robosim.protocol.ControlClasses.loader())
                    .asSubclass(LoopFunctions.class).getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
            Throwable why = e instanceof java.lang.reflect.InvocationTargetException t ? t.getCause() : e;
            throw new ExperimentFailure("loop functions " + spec.className() + " could not be made: " + why, why);
        }
        made = code;
        call("init", () -> code.init(this));
    }

    /** The code's instance, for a later run of the same world to reset (null before {@link #start}). */
    LoopFunctions code() {
        return code;
    }

    /** Before step {@code k}'s moves. */
    void preStep(long k) {
        step = k;
        call("preStep", preStep);
    }

    /** After step {@code k}'s moves and sensing: its post-step, then whether the experiment is finished. */
    void postStep(long k) {
        step = k + 1;
        call("postStep", postStep);
        if (endReason == null && code != null) {
            call("finished", finished);
            if (done) {
                endReason = "the experiment is finished (" + spec.className() + ")";
            }
        }
        stepReports = takeReports();
        stepTraces = drawing.since();
    }

    /** Once the run is over, however it ended (a throw of the code's too): the code's destroy, once. */
    void destroy() {
        if (made != null && !destroyed) {
            destroyed = true;
            code = made; // (called once more after a throw: its files are closed)
            call("destroy", () -> code.destroy(this));
        }
    }

    /** Why the experiment asked to end, or null while it goes on. */
    String endReason() {
        return endReason;
    }

    /** The metrics reported for the last step completed, each name's newest value, in the order first reported. */
    List<Report> reports() {
        return stepReports;
    }

    private List<Report> takeReports() {
        if (reports.isEmpty()) {
            return List.of();
        }
        List<Report> out = new ArrayList<>(reports.size());
        reports.forEach((name, value) -> out.add(new Report(name, value)));
        reports.clear();
        return out;
    }

    /** What the code drew over the world in the last step completed (from its pre-step, or init, to its post-step). */
    robosim.protocol.Traces tracesOfStep() {
        return stepTraces;
    }

    /** The whole drawing, as of the last step completed's end (or now, before step 0). */
    robosim.protocol.Traces tracesWhole() {
        return drawing.whole();
    }

    /** What the code painted over the floor, oldest first (the same list until it paints again). */
    List<Floor.Region> paint() {
        return paint;
    }

    /** The lights as the code left them switched (the file's own list until it switches one). */
    List<Light> lightsNow() {
        return lights;
    }

    /** The calls made every step, made once (a step allocates nothing to call them), and what finished said. */
    private final Call preStep = () -> code.preStep(this);
    private final Call postStep = () -> code.postStep(this);
    private final Call finished = () -> done = code.finished(this);
    private boolean done;

    private interface Call {
        void run() throws Exception;
    }

    private void call(String what, Call c) {
        if (code == null) {
            return;
        }
        try {
            c.run();
        } catch (Exception | LinkageError | StackOverflowError e) {
            if (e instanceof InterruptedException) {
                Thread.currentThread().interrupt(); // (the run's end, kept for whoever waits next)
            }
            code = null; // (called no more)
            throw new ExperimentFailure("loop functions " + spec.className() + " failed in " + what
                    + " at step " + step + ": " + Printable.of(String.valueOf(e), 300), e);
        }
    }

    // ---- the Experiment it sees -----------------------------------------------------------------------------

    @Override
    public long step() {
        return step;
    }

    @Override
    public long stepMs() {
        return map.spec().timeStepMs();
    }

    @Override
    public long seed() {
        return map.spec().seed();
    }

    @Override
    public RandomGenerator random() {
        return random;
    }

    @Override
    public Map<String, String> parameters() {
        return spec.parameters();
    }

    @Override
    public double arenaWidthMm() {
        return map.spec().arena().maxXMm() - map.spec().arena().minXMm();
    }

    @Override
    public double arenaHeightMm() {
        return map.spec().arena().maxYMm() - map.spec().arena().minYMm();
    }

    @Override
    public int robots() {
        return map.robotCount();
    }

    @Override
    public String robotName(int robot) {
        return map.name(robot);
    }

    @Override
    public String robotType(int robot) {
        return map.properties(robot).type();
    }

    @Override
    public double robotXMm(int robot) {
        return map.xMm(robot);
    }

    @Override
    public double robotYMm(int robot) {
        return map.yMm(robot);
    }

    @Override
    public double robotHeadingDeg(int robot) {
        return map.headingDeg(robot);
    }

    @Override
    public boolean present(int robot) {
        return !map.isGone(robot);
    }

    @Override
    public int[] leds(int robot) {
        return actuators.ledsOf(robot);
    }

    @Override
    public int carrying(int robot) {
        return map.carried(robot);
    }

    @Override
    public boolean moveRobot(int robot, double xMm, double yMm, double headingDeg) {
        finite("moveRobot", xMm, yMm, headingDeg);
        if (map.isGone(robot)) {
            return false;
        }
        Placement around = placement(robot, -1);
        if (around.overlapOfDisc(xMm, yMm, map.radiusMm(robot)) != null) {
            return false;
        }
        int held = map.carried(robot);
        if (held >= 0) {
            map.carry(held, -1); // (it lets go: what it held stays where it was)
        }
        map.setPose(robot, xMm, yMm, robosim.geometry.Kinematics.turn(0, headingDeg));
        return true;
    }

    @Override
    public void tell(int robot, String text) {
        java.util.Objects.checkIndex(robot, map.robotCount());
        router.fromLoop(robot, map, LoopSpec.SENDER, text);
    }

    @Override
    public int objects() {
        return map.objectCount();
    }

    @Override
    public String objectName(int object) {
        return map.spec().scenery().objects().get(object).name();
    }

    @Override
    public double objectXMm(int object) {
        return map.objectXMm(object);
    }

    @Override
    public double objectYMm(int object) {
        return map.objectYMm(object);
    }

    @Override
    public double objectHeadingDeg(int object) {
        return map.objectHeadingDeg(object);
    }

    @Override
    public int carrier(int object) {
        return map.carrier(object);
    }

    @Override
    public boolean objectPresent(int object) {
        return !map.objectGone(object);
    }

    @Override
    public void removeObject(int object) {
        map.objectGone(object, true);
    }

    @Override
    public boolean addObject(int object, double xMm, double yMm, double headingDeg) {
        finite("addObject", xMm, yMm, headingDeg);
        if (!map.objectGone(object)) {
            throw new IllegalStateException("object " + object + " (" + objectName(object) + ") is in the world: "
                    + "moveObject moves it");
        }
        WorldObject back = map.spec().scenery().objects().get(object).at(xMm, yMm,
                robosim.geometry.Kinematics.turn(0, headingDeg));
        if (placement(-1, object).overlapOf(back) != null) {
            return false;
        }
        map.setObjectPose(object, back.xMm(), back.yMm(), back.headingDeg());
        map.objectGone(object, false);
        return true;
    }

    @Override
    public boolean moveObject(int object, double xMm, double yMm, double headingDeg) {
        finite("moveObject", xMm, yMm, headingDeg);
        if (map.objectGone(object)) {
            throw new IllegalStateException("object " + object + " (" + objectName(object) + ") is out of the world: "
                    + "addObject puts it back");
        }
        WorldObject moved = map.spec().scenery().objects().get(object).at(xMm, yMm,
                robosim.geometry.Kinematics.turn(0, headingDeg));
        if (placement(-1, object).overlapOf(moved) != null) {
            return false;
        }
        map.carry(object, -1);
        map.setObjectPose(object, moved.xMm(), moved.yMm(), moved.headingDeg());
        return true;
    }

    /** The world as it stands, but robot {@code robot} and object {@code object} (-1: none left out). */
    private Placement placement(int robot, int object) {
        Placement p = new Placement(map.spec().arena(), map.spec().obstacles());
        for (int i = 0; i < map.robotCount(); i++) {
            if (i != robot && !map.isGone(i)) {
                p.addRobot(map.name(i), map.xMm(i), map.yMm(i), map.radiusMm(i));
            }
        }
        List<WorldObject> objects = map.spec().scenery().objects();
        for (int o = 0; o < objects.size(); o++) {
            if (o != object && !map.objectGone(o)) {
                p.addObject(objects.get(o).at(map.objectXMm(o), map.objectYMm(o), map.objectHeadingDeg(o)));
            }
        }
        return p;
    }

    @Override
    public int floorColour(double xMm, double yMm) {
        return floor.colourAt(map.spec().arena(), xMm, yMm);
    }

    @Override
    public void paintDisc(double xMm, double yMm, double radiusMm, int rgb) {
        paint(new Floor.Region(new Floor.Disc(xMm, yMm, radiusMm), rgb));
    }

    @Override
    public void paintRectangle(double xMm, double yMm, double widthMm, double heightMm, int rgb) {
        paint(new Floor.Region(new Floor.Rectangle(xMm, yMm, widthMm, heightMm), rgb));
    }

    private void paint(Floor.Region region) {
        if (fileFloor.regions().size() + paint.size() >= robosim.protocol.Limits.MAX_FLOOR_REGIONS) {
            throw new IllegalStateException("the floor holds at most " + robosim.protocol.Limits.MAX_FLOOR_REGIONS
                    + " painted regions: erase before painting more");
        }
        List<Floor.Region> more = new ArrayList<>(paint.size() + 1);
        more.addAll(paint);
        more.add(region);
        paint = List.copyOf(more);
        floorChanged();
    }

    @Override
    public void erasePaint() {
        if (!paint.isEmpty()) {
            paint = List.of();
            floorChanged();
        }
    }

    private void floorChanged() {
        List<Floor.Region> all = new ArrayList<>(fileFloor.regions());
        all.addAll(paint);
        floor = new Floor(fileFloor.rgb(), all, fileFloor.image());
        sensing.scenery(floor, lights);
    }

    @Override
    public int lights() {
        return lights.size();
    }

    @Override
    public String lightName(int light) {
        return lights.get(light).name();
    }

    @Override
    public boolean lightOn(int light) {
        return lights.get(light).on();
    }

    @Override
    public void switchLight(int light, boolean on) {
        Light l = lights.get(light);
        if (l.on() == on) {
            return;
        }
        List<Light> now = new ArrayList<>(lights);
        now.set(light, new Light(l.name(), l.xMm(), l.yMm(), l.heightMm(), l.rgb(), l.intensity(), on));
        lights = List.copyOf(now);
        sensing.scenery(floor, lights);
    }

    @Override
    public void trace(String name, double xMm, double yMm, int rgb) {
        drawing.add(name, xMm, yMm, rgb);
    }

    @Override
    public void eraseTraces() {
        drawing.erase();
    }

    @Override
    public void report(String name, double value) {
        String bad = Report.problem(name, value);
        if (bad != null) {
            throw new IllegalArgumentException(bad);
        }
        if (!reports.containsKey(name) && reports.size() >= Report.MAX_PER_STEP) {
            throw new IllegalStateException("at most " + Report.MAX_PER_STEP + " metrics a step");
        }
        reports.put(name, value);
    }

    @Override
    public void end(String reason) {
        if (endReason == null) {
            endReason = reason == null || reason.isBlank() ? "the experiment ended (" + spec.className() + ")"
                    : Printable.of(reason, 200);
        }
    }

    @Override
    public Path outputDirectory() {
        return outputDirectory;
    }

    private static void finite(String what, double x, double y, double h) {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(h)) {
            throw new IllegalArgumentException(what + ": a pose of finite numbers, got (" + x + ", " + y + ", " + h
                    + ")");
        }
    }
}
