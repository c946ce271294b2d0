package robosim.runner;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The class loader of one run's control code in a warm JVM ({@link RunHost}): the classes of the user's class path
 * ({@code --classpath}, {@code ROBOSIM_CLASSPATH}) and RoboSim's bundled control code ({@code robosim.examples}) are
 * defined again by each run's loader, so that the static state of control code (a counter, a cache, a random
 * generator) starts afresh with every run, as in a JVM of its own. Every other class (the robot API, the Hardware
 * Simulator, the Environment, the libraries) comes from the parent, loaded once for all runs: that is what makes a
 * warm run cheap. A class of the user's path that is also on the parent's is still defined here (child first), so
 * the scripts may put those entries on the JVM's class path too. A class RoboSim's own jars have is RoboSim's, as
 * in a JVM of its own, where the user's entries come after RoboSim's: a user's entry never shadows it, and an entry
 * that is one of RoboSim's own (it holds the robot API, the Hardware Simulator, the protocol or the Environment) is
 * left to the parent altogether. Closed at the run's end.
 */
public final class ControlClassLoader extends URLClassLoader {
    static {
        ClassLoader.registerAsParallelCapable();
    }

    /** RoboSim's own control code, in the Hardware Simulator's jar: defined again per run like the user's. */
    private static final String BUNDLED = "robosim.examples.";
    /** Classes of RoboSim's own modules: an entry that holds one of them is RoboSim's, not the user's. */
    private static final List<String> ROBOSIMS = List.of("robosim/api/RobotControl.class",
            "robosim/hardware/HardwareSimulator.class", "robosim/protocol/Protocol.class",
            "robosim/environment/EnvironmentMain.class");

    /** A loader for one run: {@code classPath}'s entries (a directory, a jar, or {@code dir/*}: its jars) first. */
    public ControlClassLoader(String name, List<Path> classPath, ClassLoader parent) {
        super(name, urls(classPath), parent);
        for (URL u : getURLs()) {
            String s = u.toString();
            own.add(s.endsWith("/") ? s : "jar:" + s + "!/");
        }
    }

    /** How the URLs of this loader's entries' classes start (a directory's URL, a jar's {@code jar:...!/}). */
    private final List<String> own = new ArrayList<>();

    /**
     * The entries of a class path as {@code ROBOSIM_CLASSPATH} writes them ({@code :}-separated, absolute, a
     * {@code dir/*} meaning every jar in dir); none for null or empty.
     */
    public static List<Path> entries(String classPath) {
        List<Path> out = new ArrayList<>();
        if (classPath == null) {
            return out;
        }
        for (String e : classPath.split(java.io.File.pathSeparator)) {
            if (!e.isBlank()) {
                out.add(Path.of(e));
            }
        }
        return out;
    }

    private static URL[] urls(List<Path> classPath) {
        List<URL> urls = new ArrayList<>();
        try {
            for (Path e : classPath) {
                if (e.getFileName() != null && e.getFileName().toString().equals("*")) {
                    try (DirectoryStream<Path> jars = Files.newDirectoryStream(e.getParent(), "*.{jar,JAR}")) {
                        for (Path jar : jars) {
                            if (!robosims(jar)) {
                                urls.add(jar.toUri().toURL());
                            }
                        }
                    }
                } else if (!robosims(e)) {
                    urls.add(e.toUri().toURL());
                }
            }
        } catch (MalformedURLException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return urls.toArray(new URL[0]);
    }

    /** True if class path entry {@code e} (a directory or a jar) holds one of RoboSim's own modules. */
    private static boolean robosims(Path e) throws IOException {
        if (Files.isDirectory(e)) {
            return ROBOSIMS.stream().anyMatch(c -> Files.isRegularFile(e.resolve(c)));
        }
        if (!Files.isRegularFile(e)) {
            return false; // (nothing there: nothing to load from it)
        }
        try (java.util.jar.JarFile jar = new java.util.jar.JarFile(e.toFile())) {
            return ROBOSIMS.stream().anyMatch(c -> jar.getEntry(c) != null);
        } catch (java.util.zip.ZipException notAJar) {
            return false;
        }
    }

    @Override
    protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
        synchronized (getClassLoadingLock(name)) {
            Class<?> c = findLoadedClass(name);
            if (c == null) {
                c = defineOwn(name);
            }
            if (c == null) {
                return super.loadClass(name, resolve); // (the parent's: found there first)
            }
            if (resolve) {
                resolveClass(c);
            }
            return c;
        }
    }

    /** True if {@code resource} is in one of this loader's entries (on the parent's class path too). */
    private boolean ownEntry(URL resource) {
        String r = resource.toString();
        for (String prefix : own) {
            if (r.startsWith(prefix)) {
                return true;
            }
        }
        return false;
    }

    /**
     * {@code name} defined by this loader when it is bundled control code, or one of the user's path that RoboSim's
     * own jars do not have (the parent finds it nowhere, or in one of the user's entries); else null.
     */
    private Class<?> defineOwn(String name) throws ClassNotFoundException {
        String file = name.replace('.', '/') + ".class";
        URL parents = getParent() == null ? null : getParent().getResource(file);
        if (findResource(file) != null && (parents == null || ownEntry(parents))) {
            return findClass(name);
        }
        if (!name.startsWith(BUNDLED) || parents == null) {
            return null;
        }
        try (InputStream in = parents.openStream()) {
            byte[] bytes = in.readAllBytes();
            return defineClass(name, bytes, 0, bytes.length); // (its package defined with it)
        } catch (IOException e) {
            throw new ClassNotFoundException(name + ": " + e.getMessage(), e);
        }
    }
}
