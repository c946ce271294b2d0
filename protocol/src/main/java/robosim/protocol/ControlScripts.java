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
    /** The environment variable naming the Python interpreter; unset or empty, {@code python3} on the PATH. */
    public static final String INTERPRETER_VARIABLE = "ROBOSIM_PYTHON";

    private ControlScripts() {
    }

    /** Whether {@code control} names a script (not a control class). */
    public static boolean isScript(String control) {
        return control.startsWith(PYTHON);
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

    /** How long the interpreter gets to show it can run a script ({@link #interpreterProblem}), s. */
    private static final long CHECK_S = 60;
    /** The interpreter last found able to import robosim (a sweep's many worlds ask once). */
    private static volatile String checked;

    /**
     * Why the interpreter ({@link #interpreter}) could not run a script here (not found; cannot import the package in
     * {@code python/}), or null: it is asked, {@code INTERPRETER -c "import robosim"}, until it has answered yes once in
     * this JVM.
     */
    public static String interpreterProblem() throws InterruptedException {
        String interpreter = interpreter();
        if (interpreter.equals(checked)) {
            return null;
        }
        String hint = " (pip install ./python into it, or set " + INTERPRETER_VARIABLE + " to a Python that has it)";
        Process p;
        try {
            p = new ProcessBuilder(interpreter, "-c", "import robosim").redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        } catch (java.io.IOException e) {
            return "cannot run the Python interpreter " + Printable.of(interpreter, 200) + ": "
                    + Printable.of(e.getMessage(), 200) + hint;
        }
        try {
            if (!p.waitFor(CHECK_S, java.util.concurrent.TimeUnit.SECONDS)) {
                return Printable.of(interpreter, 200) + " -c 'import robosim' did not end within " + CHECK_S + " s";
            }
        } finally {
            p.destroyForcibly(); // (ended already, or given up on, or this thread interrupted)
        }
        if (p.exitValue() != 0) {
            return Printable.of(interpreter, 200) + " cannot import robosim, the package in python/" + hint;
        }
        checked = interpreter;
        return null;
    }

    /** The interpreter a Python script runs with: {@code ROBOSIM_PYTHON}, else {@code python3} on the PATH. */
    public static String interpreter() {
        String given = System.getenv(INTERPRETER_VARIABLE);
        return given == null || given.isBlank() ? "python3" : given;
    }
}
