package robosim.sweep;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.exc.InvalidFormatException;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.dataformat.xml.XmlMapper;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlElementWrapper;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.protocol.Printable;

/**
 * A sweep file as written ({@code <sweep>}, {@code docs/EXPERIMENTS.md}), and its reading: every fault is one
 * line naming the file, where and what is wrong, before any run starts (a world that does not load: a line for each
 * of its faults, each naming the sweep file first).
 */
@JacksonXmlRootElement(localName = "sweep")
public final class SweepFile {
    private static final XmlMapper MAPPER = XmlMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
            .build();
    /** The largest sweep file, bytes. */
    static final int MAX_FILE_BYTES = 1024 * 1024;
    /** The most runs one sweep may have. */
    static final int MAX_RUNS = 1_000_000;

    @JacksonXmlProperty(isAttribute = true)
    public String world;
    @JacksonXmlProperty(isAttribute = true)
    public Long steps;
    @JacksonXmlProperty(isAttribute = true)
    public Integer repeat;
    @JacksonXmlProperty(isAttribute = true)
    public String layout;
    @JacksonXmlProperty(isAttribute = true)
    public Long runTimeoutS;
    @JacksonXmlProperty(isAttribute = true)
    public String jvm;
    public SeedsXml seeds;
    @JacksonXmlElementWrapper(useWrapping = false)
    @JacksonXmlProperty(localName = "param")
    public List<ParamXml> params = new ArrayList<>();
    public MetricsXml metrics;

    /** {@code <seeds from="1" to="10"/>}: every seed from one to the other, both included. */
    public static final class SeedsXml {
        @JacksonXmlProperty(isAttribute = true)
        public Long from;
        @JacksonXmlProperty(isAttribute = true)
        public Long to;
    }

    /**
     * {@code <param name="speed" values="200 400 600"/>}: one of the world's parameters and its values, separated by
     * spaces or commas ({@code "200, 400, 600"} too; a value holds neither).
     */
    public static final class ParamXml {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String values;
    }

    /** {@code <metrics areaCellM="0.5">} holding {@code <metric>}s: which metrics the tables hold. */
    public static final class MetricsXml {
        @JacksonXmlProperty(isAttribute = true)
        public Double areaCellM;
        @JacksonXmlElementWrapper(useWrapping = false)
        @JacksonXmlProperty(localName = "metric")
        public List<MetricXml> all = new ArrayList<>();
    }

    /**
     * {@code <metric name="distance_m"/>} (a built-in), {@code <metric report="found" over="sum"/>} (what the control
     * code reported, each robot's newest value, summed over the robots unless {@code over} says {@code mean},
     * {@code min}, {@code max} or {@code each}; {@code count="true"}: a count, its interval a bootstrap one) or
     * {@code <metric class="my.Metric"/>} (one's own, from the recording).
     */
    public static final class MetricXml {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String report;
        @JacksonXmlProperty(isAttribute = true)
        public String over;
        @JacksonXmlProperty(isAttribute = true, localName = "class")
        public String className;
        @JacksonXmlProperty(isAttribute = true)
        public String count;
    }

    /** Reads and checks {@code file}: the world loads with every combination of the values, every name is known. */
    public static Sweep read(Path file) throws SweepException {
        Sweep sweep = readAgain(file);
        checkWorld(file, sweep);
        return sweep;
    }

    /**
     * Reads {@code file} as {@link #read} does, without loading its world for every combination: for a sweep whose
     * output directory holds the same sweep file and world as when {@link #read} checked them (a Slurm task, the
     * gather job, status), which every run then loads again anyway.
     */
    static Sweep readAgain(Path file) throws SweepException {
        String where = file.toString();
        SweepFile xml;
        try {
            if (!Files.isRegularFile(file)) {
                throw new NoSuchFileException(where);
            }
            if (Files.size(file) > MAX_FILE_BYTES) {
                throw new SweepException(where + ": larger than the " + MAX_FILE_BYTES + " bytes a sweep file may have");
            }
            xml = MAPPER.readValue(Files.readAllBytes(file), SweepFile.class);
        } catch (NoSuchFileException e) {
            throw new SweepException(where + ": file not found");
        } catch (UnrecognizedPropertyException e) {
            throw new SweepException(where + at(e.getLocation()) + ": unknown element or attribute '"
                    + e.getPropertyName() + "' (known here: " + e.getKnownPropertyIds() + ")");
        } catch (InvalidFormatException e) {
            throw new SweepException(where + at(e.getLocation()) + ": value '" + e.getValue() + "' is not a "
                    + e.getTargetType().getSimpleName().toLowerCase());
        } catch (JsonProcessingException e) {
            throw new SweepException(where + at(e.getLocation()) + ": malformed XML: "
                    + e.getOriginalMessage().lines().findFirst().orElse(""));
        } catch (IOException e) {
            throw new SweepException(where + ": cannot read: " + e.getMessage());
        }
        if (xml == null) {
            throw new SweepException(where + ": empty file");
        }
        return xml.check(file);
    }

    /**
     * The sweep of {@code xml}, an earlier text of sweep file {@code file} (its copy in an output directory), read as
     * if it were {@code file}'s (its world relative to {@code file}), without loading its world.
     */
    static Sweep readEarlier(Path file, byte[] xml) throws SweepException {
        try {
            SweepFile earlier = MAPPER.readValue(xml, SweepFile.class);
            if (earlier == null) {
                throw new SweepException(file + ": its earlier copy is empty");
            }
            return earlier.check(file);
        } catch (IOException e) {
            throw new SweepException(file + ": its earlier copy cannot be read: " + e.getMessage());
        }
    }

    private static String at(JsonLocation location) {
        return location == null || location.getLineNr() < 0 ? ""
                : ":" + location.getLineNr() + ":" + location.getColumnNr();
    }

    private Sweep check(Path file) throws SweepException {
        String where = file + ": <sweep>";
        if (world == null || world.isBlank()) {
            throw new SweepException(where + " needs world=\"FILE.xml\" (the environment file, relative to this file)");
        }
        Path worldFile = file.toAbsolutePath().getParent().resolve(world).normalize();
        if (steps == null || steps <= 0) {
            throw new SweepException(where + " needs steps=\"N\" > 0, got " + steps);
        }
        int repeats = repeat == null ? 1 : repeat;
        if (repeats < 1) {
            throw new SweepException(where + " repeat must be >= 1, got " + repeats);
        }
        Sweep.Layout runLayout;
        try {
            runLayout = layout == null ? Sweep.Layout.ONE_JVM : Sweep.Layout.of(layout);
        } catch (IllegalArgumentException e) {
            throw new SweepException(where + " layout \"" + layout + "\" is not one of " + Sweep.Layout.names());
        }
        long timeout = runTimeoutS == null ? 0 : runTimeoutS;
        if (timeout < 0) {
            throw new SweepException(where + " runTimeoutS must be >= 0 (0: no limit), got " + timeout);
        }
        List<String> jvmOptions = jvm == null ? Sweep.SHORT_RUNS : jvm.isBlank() ? List.of()
                : List.of(jvm.trim().split("\\s+"));
        for (String o : jvmOptions) {
            if (!o.startsWith("-") || o.equals("-cp") || o.equals("-classpath") || o.startsWith("--class-path")) {
                throw new SweepException(where + " jvm=\"" + jvm + "\": '" + o + "' is not a JVM option this can take "
                        + "(options start with '-'; the class path is ROBOSIM_CLASSPATH's)");
            }
        }
        if (seeds == null || seeds.from == null || seeds.to == null) {
            throw new SweepException(file + ": <seeds from=\"1\" to=\"10\"/> is needed (the seeds each combination runs "
                    + "with)");
        }
        if (seeds.from > seeds.to) {
            throw new SweepException(file + ": <seeds from=\"" + seeds.from + "\" to=\"" + seeds.to
                    + "\"> is an empty range");
        }
        if (seeds.to - seeds.from < 0 || seeds.to - seeds.from >= MAX_RUNS) { // (the first: it overflowed)
            throw new SweepException(file + ": <seeds from=\"" + seeds.from + "\" to=\"" + seeds.to
                    + "\"> holds more than " + MAX_RUNS + " seeds");
        }
        Map<String, List<String>> values = new LinkedHashMap<>();
        for (ParamXml p : params) {
            if (p.name == null || p.name.isBlank()) {
                throw new SweepException(file + ": <param> needs a name (one of the world's parameters)");
            }
            if (RunMetrics.reserved(p.name)) {
                throw new SweepException(file + ": <param name=\"" + p.name + "\">: a row's own column or a built-in "
                        + "metric has that name" + (p.name.equals("seed") ? " (the seeds are <seeds from to>: each run "
                        + "gets its seed as the world's, whatever the file says)" : "; give the world's parameter another"));
            }
            String given = p.values == null ? "" : p.values.replaceAll("^[\\s,]+|[\\s,]+$", "");
            List<String> list = given.isEmpty() ? List.of() : List.of(given.split("[\\s,]+"));
            if (list.isEmpty()) {
                throw new SweepException(file + ": <param name=\"" + p.name + "\"> needs values=\"A B ...\" (at least one)");
            }
            if (values.put(p.name, list) != null) {
                throw new SweepException(file + ": <param name=\"" + p.name + "\"> is given twice");
            }
            if (Set.copyOf(list).size() != list.size()) {
                throw new SweepException(file + ": <param name=\"" + p.name + "\"> names a value twice: " + p.values.trim());
            }
        }
        Sweep sweep = new Sweep(file.toAbsolutePath(), worldFile, steps, seeds.from, seeds.to, repeats, values,
                runLayout, timeout, jvmOptions, metrics(file), areaCell(file));
        if (sweep.runs() > MAX_RUNS) {
            throw new SweepException(file + ": " + sweep.runs() + " runs, at most " + MAX_RUNS);
        }
        return sweep;
    }

    private List<MetricChoice> metrics(Path file) throws SweepException {
        List<MetricChoice> out = new ArrayList<>();
        if (metrics == null) {
            return out;
        }
        for (MetricXml m : metrics.all) {
            int given = (m.name == null ? 0 : 1) + (m.report == null ? 0 : 1) + (m.className == null ? 0 : 1);
            if (given != 1) {
                throw new SweepException(file + ": <metric> needs one of name=\"BUILT-IN\" (" + String.join(", ",
                        robosim.environment.metrics.Metrics.names()) + "), report=\"NAME\" or class=\"CLASS\"");
            }
            MetricChoice.Over over = m.over == null ? null : MetricChoice.Over.of(m.over);
            if (m.over != null && (m.report == null || over == null)) {
                throw new SweepException(file + ": <metric over=\"" + Printable.of(m.over, 40) + "\">: " + (m.report == null
                        ? "over goes with report=\"NAME\" (a value the robots report)"
                        : "over is one of " + MetricChoice.Over.names()));
            }
            if (m.count != null && (m.report == null || !List.of("true", "false").contains(m.count))) {
                throw new SweepException(file + ": <metric count=\"" + Printable.of(m.count, 40) + "\">: " + (m.report
                        == null ? "count goes with report=\"NAME\" (a built-in metric says its own kind)"
                        : "count is true (a count: never below zero, a bootstrap interval) or false"));
            }
            MetricChoice choice = MetricChoice.of(m.name, m.report, m.className, over, "true".equals(m.count));
            String bad = choice.problem();
            if (bad != null) {
                throw new SweepException(file + ": <metric>: " + bad);
            }
            out.add(choice);
        }
        if (out.isEmpty()) {
            throw new SweepException(file + ": <metrics> names no <metric> (leave it out for every built-in one)");
        }
        return out;
    }

    private double areaCell(Path file) throws SweepException {
        double cell = metrics == null || metrics.areaCellM == null ? RunMetrics.DEFAULT_AREA_CELL_M : metrics.areaCellM;
        if (!(cell > 0) || Double.isInfinite(cell)) {
            throw new SweepException(file + ": <metrics> areaCellM must be > 0 m, got " + cell);
        }
        return cell;
    }

    /**
     * The world loads with each combination of the values (which also refuses a parameter it does not have, naming
     * those it has); the first that does not is refused with each of its faults on a line of its own.
     */
    private static void checkWorld(Path file, Sweep sweep) throws SweepException {
        EnvironmentLoader loader = new EnvironmentLoader();
        try {
            java.util.SortedSet<String> known = loader.parameterNames(sweep.world());
            known.removeIf(RunMetrics::reserved); // (a sweep may not set those: seed is <seeds>)
            for (String name : sweep.values().keySet()) {
                if (!known.contains(name)) {
                    throw new SweepException(file + ": <param name=\"" + Printable.of(name, 64) + "\">: not a "
                            + "parameter of " + sweep.world() + " (the parameters a sweep may set there: "
                            + (known.isEmpty() ? "none" : String.join(", ", known)) + ")");
                }
            }
            for (Map<String, String> combination : sweep.combinations()) {
                robosim.environment.core.WorldSpec spec = loader.load(sweep.world(), combination);
                String cells = RunMetrics.cellProblem(spec.arena(), sweep.areaCellM());
                if (cells != null) {
                    throw new SweepException(file + ": <metrics areaCellM>: " + cells);
                }
                String control = robosim.runner.HeadlessRunner.missingControl(sweep.world(), spec);
                if (control != null) {
                    throw new SweepException(file + ": its world " + control + "; no run was started");
                }
            }
        } catch (EnvironmentFileException e) {
            throw new SweepException(e.getMessage().lines().map(fault -> file + ": " + fault)
                    .collect(java.util.stream.Collectors.joining("\n")));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SweepException(file + ": stopped while its world's Python was checked; no run was started");
        }
    }
}
