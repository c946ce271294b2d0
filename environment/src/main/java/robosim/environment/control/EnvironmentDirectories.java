package robosim.environment.control;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.environment.config.EnvironmentFileException;

/**
 * The directories whose files the control port's {@code load} may read ({@code --env-dir}, by default
 * the directory of the Environment's first file), and the check of a requested path against them. A
 * path outside them is refused before the file system is asked anything (no answer tells whether a file
 * exists elsewhere); inside, the path is followed through links and must still be inside. The loader
 * then reads only a regular file under its size cap. Immutable; any thread.
 */
public final class EnvironmentDirectories {
    /** Each directory as given (absolute, normalised) and as it really is (links followed). */
    private final List<Path> given = new ArrayList<>();
    private final List<Path> real = new ArrayList<>();

    /** @throws IOException naming a directory that does not exist or is not a directory */
    public EnvironmentDirectories(List<Path> directories) throws IOException {
        for (Path d : directories) {
            if (!Files.isDirectory(d)) {
                throw new IOException("--env-dir " + d + ": not a directory");
            }
            given.add(d.toAbsolutePath().normalize());
            real.add(d.toRealPath());
        }
        if (given.isEmpty()) {
            throw new IOException("no environment directory given");
        }
    }

    /** The directory of {@code file}, the default. */
    public static EnvironmentDirectories of(Path file) throws IOException {
        Path dir = file.toAbsolutePath().normalize().getParent();
        return new EnvironmentDirectories(List.of(dir == null ? Path.of("/") : dir));
    }

    /**
     * The file {@code request} names, links followed, if {@code load} may read it; else an
     * {@link EnvironmentFileException} naming the path and what is wrong with it.
     */
    public Path resolve(String request) throws EnvironmentFileException {
        Path asked;
        try {
            asked = Path.of(request).toAbsolutePath().normalize();
        } catch (InvalidPathException e) {
            throw new EnvironmentFileException(request + ": not a path");
        }
        if (!inside(asked, given) && !inside(asked, real)) {
            throw new EnvironmentFileException(asked + ": outside the environment directories " + given
                    + " (the Environment's --env-dir)");
        }
        Path target;
        try {
            target = asked.toRealPath();
        } catch (NoSuchFileException e) {
            throw new EnvironmentFileException(asked + ": file not found");
        } catch (IOException e) {
            throw new EnvironmentFileException(asked + ": cannot be read");
        }
        if (!inside(target, real)) {
            throw new EnvironmentFileException(asked + ": links outside the environment directories " + given);
        }
        return target;
    }

    private static boolean inside(Path p, List<Path> roots) {
        for (Path r : roots) {
            if (p.startsWith(r) && !p.equals(r)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public String toString() {
        return given.toString();
    }
}
