package robosim.protocol;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

/**
 * Control code that is a script in another language, named where a control class would be: {@code python:PATH}
 * ({@code control="python:wander.py"} in an environment file, a path relative to the file's folder; on a command
 * line, relative to the working folder). The Hardware Simulator runs it with the configured interpreter
 * ({@link #interpreter}) and serves it its robot over the robot link. The one rule for every part that tells a
 * script from a class or checks one before a run.
 */
public final class ControlScripts {
    /** What begins a Python script's name. */
    public static final String PYTHON = "python:";
    /**
     * The control of a robot driven by ROS 2 topics ({@code control="ros2"}): the ROS 2 bridge (Python's
     * {@code robosim.ros2}, python/README.md "From ROS 2") runs such a world and gives each step's command; no other way
     * of running a world does.
     */
    public static final String ROS2 = "ros2";
    /** The environment variable naming the Python interpreter; unset or empty, {@code python3} on the PATH. */
    public static final String INTERPRETER_VARIABLE = "ROBOSIM_PYTHON";

    private ControlScripts() {
    }

    /** Whether {@code control} names a script (not a control class). */
    public static boolean isScript(String control) {
        return control.startsWith(PYTHON);
    }

    /** Whether {@code control} is {@link #ROS2}: the robot is driven by ROS 2 topics through the bridge. */
    public static boolean isRos2(String control) {
        return ROS2.equals(control);
    }

    /** Why a robot driven by ROS 2 topics cannot run here: every way of running a world but the bridge says it. */
    public static String ros2Elsewhere() {
        return "it is driven by ROS 2 topics (control=\"ros2\"): only the ROS 2 bridge runs it, python -m robosim.ros2 "
                + "FILE (python/README.md, \"From ROS 2\")";
    }

    /** The script's path as {@code control} gives it (a script's name, {@link #isScript}). */
    public static Path script(String control) {
        return Path.of(control.substring(PYTHON.length()));
    }

    /**
     * {@code control}, its script's path made absolute against {@code folder} when it is relative (an environment
     * file's scripts are where the file is); anything else as it is.
     */
    public static String resolved(String control, Path folder) {
        if (!isScript(control)) {
            return control;
        }
        try {
            Path p = script(control);
            return p.isAbsolute() || folder == null ? control
                    : PYTHON + folder.toAbsolutePath().normalize().resolve(p).normalize();
        } catch (InvalidPathException e) {
            return control; // (said by problem)
        }
    }

    /** Why the script {@code control} names could not run here (no such file, not readable), or null. */
    public static String problem(String control) {
        String shown = Printable.of(control, 200);
        Path p;
        try {
            p = script(control);
        } catch (InvalidPathException e) {
            return shown + ": not a path (" + e.getReason() + ")";
        }
        if (p.toString().isEmpty()) {
            return shown + ": no script named (python:PATH, a .py file)";
        }
        if (!Files.isRegularFile(p)) {
            return "there is no script " + Printable.of(p.toString(), 200) + " (" + shown + ")";
        }
        if (!Files.isReadable(p)) {
            return "the script " + Printable.of(p.toString(), 200) + " cannot be read";
        }
        return null;
    }

    /** How long the interpreter gets to compile the scripts ({@link #scriptsProblem}), s. */
    private static final long CHECK_S = 60;
    /** The exit code of {@code python -m robosim --check} when a script does not compile. */
    private static final int NOT_COMPILED = 3;
    /** The most of the check's output read, bytes. */
    private static final int MAX_OUTPUT = 64 * 1024;
    /** The scripts compiled already in this JVM, each as its interpreter, path, time and size (a sweep's runs ask once). */
    private static final java.util.Set<String> CHECKED = java.util.concurrent.ConcurrentHashMap.newKeySet();

    /**
     * Why {@code scripts} could not run here, or null: the interpreter ({@link #interpreter}) compiles them, runs
     * none ({@code INTERPRETER -m robosim --check SCRIPT...}). A script that does not compile is its line
     * {@code FILE:LINE: KIND: MESSAGE} (and how many more do not); an interpreter that cannot run the check (not
     * found, without the package in {@code python/}) is said so. Scripts compiled before, unchanged, are not asked
     * again.
     */
    public static String scriptsProblem(java.util.Collection<Path> scripts) throws InterruptedException {
        String interpreter = interpreter();
        java.util.List<String> keys = new java.util.ArrayList<>();
        for (Path p : scripts) {
            try {
                keys.add(interpreter + "\n" + p.toAbsolutePath() + "\n" + Files.getLastModifiedTime(p).toMillis() + "\n"
                        + Files.size(p));
            } catch (java.io.IOException e) {
                keys.add(null); // (asked: the check says what is wrong with it)
            }
        }
        if (!keys.contains(null) && CHECKED.containsAll(keys)) {
            return null;
        }
        String hint = " (pip install ./python into it, or set " + INTERPRETER_VARIABLE + " to a Python that has it)";
        java.util.List<String> command = new java.util.ArrayList<>(java.util.List.of(interpreter, "-m", "robosim",
                "--check"));
        scripts.forEach(p -> command.add(p.toString()));
        Path output;
        try {
            output = Files.createTempFile("robosim-check", ".txt");
        } catch (java.io.IOException e) {
            return "cannot check the Python scripts: " + Printable.of(String.valueOf(e.getMessage()), 200);
        }
        try {
            Process p;
            try {
                p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile())
                        .redirectInput(ProcessBuilder.Redirect.PIPE).start();
                p.getOutputStream().close();
            } catch (java.io.IOException e) {
                return "cannot run the Python interpreter " + Printable.of(interpreter, 200) + ": "
                        + Printable.of(e.getMessage(), 200) + hint;
            }
            try {
                if (!p.waitFor(CHECK_S, java.util.concurrent.TimeUnit.SECONDS)) {
                    return Printable.of(interpreter, 200) + " -m robosim --check did not end within " + CHECK_S + " s";
                }
            } finally {
                p.destroyForcibly(); // (ended already, or given up on, or this thread interrupted)
            }
            java.util.List<String> lines = head(output).lines().filter(l -> !l.isBlank()).toList();
            if (p.exitValue() == 0) {
                if (!keys.contains(null)) {
                    CHECKED.addAll(keys);
                }
                return null;
            }
            if (p.exitValue() == NOT_COMPILED && !lines.isEmpty()) {
                return Printable.of(lines.get(0), 1000) + (lines.size() > 1 ? " (and " + (lines.size() - 1)
                        + " more script" + (lines.size() > 2 ? "s" : "") + " that do not compile)" : "");
            }
            String said = lines.isEmpty() ? "" : ": " + Printable.of(lines.get(lines.size() - 1), 300);
            return said.contains("No module named robosim")
                    ? Printable.of(interpreter, 200) + " cannot import robosim, the package in python/" + hint
                    : Printable.of(interpreter, 200) + " -m robosim --check failed (exit " + p.exitValue() + ")" + said
                            + " (an older robosim package? pip install ./python again)";
        } finally {
            try {
                Files.deleteIfExists(output);
            } catch (java.io.IOException e) {
                // (a temporary file left in the temporary folder)
            }
        }
    }

    /** The first {@link #MAX_OUTPUT} bytes of {@code file}, as text. */
    private static String head(Path file) {
        try (java.io.InputStream in = Files.newInputStream(file)) {
            return new String(in.readNBytes(MAX_OUTPUT), java.nio.charset.StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            return "";
        }
    }

    /** The interpreter a Python script runs with: {@code ROBOSIM_PYTHON}, else {@code python3} on the PATH. */
    public static String interpreter() {
        String given = System.getenv(INTERPRETER_VARIABLE);
        return given == null || given.isBlank() ? "python3" : given;
    }
}
