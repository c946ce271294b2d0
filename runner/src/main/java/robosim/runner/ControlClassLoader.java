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
 * the scripts may put those entries on the JVM's class path too. Closed at the run's end.
 */
public final class ControlClassLoader extends URLClassLoader {
    static {
        ClassLoader.registerAsParallelCapable();
    }

    /** RoboSim's own control code, in the Hardware Simulator's jar: defined again per run like the user's. */
    private static final String BUNDLED = "robosim.examples.";

    /** A loader for one run: {@code classPath}'s entries (a directory, a jar, or {@code dir/*}: its jars) first. */
    public ControlClassLoader(String name, List<Path> classPath, ClassLoader parent) {
        super(name, urls(classPath), parent);
    }

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
                            urls.add(jar.toUri().toURL());
                        }
                    }
                } else {
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

    @Override
    public URL getResource(String name) {
        URL own = findResource(name); // (the user's resources beside the user's classes, as for their classes)
        return own != null ? own : super.getResource(name);
    }

    /** {@code name} defined by this loader when it is one of the user's path or bundled control code; else null. */
    private Class<?> defineOwn(String name) throws ClassNotFoundException {
        String file = name.replace('.', '/') + ".class";
        if (findResource(file) != null) {
            return findClass(name);
        }
        if (!name.startsWith(BUNDLED) || getParent() == null) {
            return null;
        }
        try (InputStream in = getParent().getResourceAsStream(file)) {
            if (in == null) {
                return null;
            }
            byte[] bytes = in.readAllBytes();
            String pkg = name.substring(0, name.lastIndexOf('.'));
            if (getDefinedPackage(pkg) == null) {
                definePackage(pkg, null, null, null, null, null, null, null);
            }
            return defineClass(name, bytes, 0, bytes.length);
        } catch (IOException e) {
            throw new ClassNotFoundException(name + ": " + e.getMessage(), e);
        }
    }
}
