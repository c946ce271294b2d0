package robosim.runner;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.zip.CRC32;

/**
 * The class-data archives of the child JVMs, by the rules {@code scripts/common.sh} applies to the JVM a
 * script starts (its {@code robosim_cds_opts}; runner/README.md, "How the scripts behave"). A child maps
 * the dynamic CDS archive {@code KEY.jsa} of its main class, class path and JVM options (the key) when
 * one is there and newer than every jar of the class path; else, unless another live process is writing
 * it, the child writes it at its exit ({@code -XX:ArchiveClassesAtExit}) into a file of its own,
 * {@code KEY.ID.tmp}, next to an empty {@code KEY.ID.start} that dates its start ({@code ID} is this JVM's
 * pid, a dash and a count). When the child has ended, {@link Launch#finish()} renames the file to
 * {@code KEY.jsa} (an atomic rename: a JVM never maps a file being written) if it is whole (the JVM
 * writes the archive's header last) and no jar changed since the start, else removes it. A claim whose
 * owner died first is settled so by the next start of its key.
 *
 * <p>The directory comes from {@code ROBOSIM_CDS_DIR}, set by the scripts (empty or absent: no archives,
 * e.g. {@code ROBOSIM_CDS=off}, JDK 17, or a runner started without a script). A class path with a
 * directory (the JVM refuses to archive those, and says so on every run) or options of the user's own
 * about class-data sharing turn archives off for the child. The JVM's {@code cds} log is off: it warns
 * about classes it cannot archive. Writing an archive is a cache: when it fails, the run goes on without.
 */
final class ClassDataArchives {
    /** The magic number a finished dynamic archive starts with (in the machine's byte order). */
    private static final int DYNAMIC_ARCHIVE_MAGIC = 0xf00baba8;
    /** The JVM's warnings while writing or mapping an archive (classes it skips, an archive it cannot use). */
    static final String QUIET = "-Xlog:cds*=off";
    /** A claim older than this is taken as abandoned even when its owner's pid is alive (a reused pid). */
    private static final long CLAIM_MAX_AGE_MS = TimeUnit.HOURS.toMillis(1);
    private static final List<String> USERS_OWN = List.of("Xshare", "SharedArchiveFile", "ArchiveClassesAtExit",
            "AOTCache", "AOTMode", "AOTConfiguration");

    /** How one child uses its archive: its JVM options, and what to do once it has ended. */
    interface Launch {
        List<String> options();

        /** Puts the archive the ended child wrote in place, or removes it; never throws. */
        void finish();
    }

    /** A child that maps an archive, or (no options) runs without. */
    private record Maps(List<String> options) implements Launch {
        @Override
        public void finish() {
        }
    }

    private static final Launch NONE = new Maps(List.of());

    private final Path dir;
    private final long owner = ProcessHandle.current().pid();
    private final AtomicInteger claims = new AtomicInteger();

    /** Archives in {@code dir}; null for none. */
    ClassDataArchives(Path dir) {
        this.dir = dir;
    }

    /** The archives the scripts chose ({@code ROBOSIM_CDS_DIR}), or none. */
    static ClassDataArchives fromEnvironment() {
        String dir = System.getenv("ROBOSIM_CDS_DIR");
        boolean usable = dir != null && !dir.isBlank() && !dir.contains(File.pathSeparator)
                && Runtime.version().feature() >= 19;
        return new ClassDataArchives(usable ? Path.of(dir) : null);
    }

    /** The archive options for a child running {@code mainClass} on {@code classPath} with {@code jvmOptions}. */
    Launch launch(String mainClass, String classPath, List<String> jvmOptions) {
        if (dir == null || jvmOptions.stream().anyMatch(o -> USERS_OWN.stream().anyMatch(o::contains))) {
            return NONE;
        }
        try {
            List<Path> jars = new ArrayList<>();
            for (String entry : classPath.split(File.pathSeparator)) {
                Path p = Path.of(entry);
                if (!Files.isRegularFile(p)) {
                    return NONE;
                }
                jars.add(p);
            }
            String key = key(mainClass, classPath, jvmOptions);
            Files.createDirectories(dir);
            Path archive = dir.resolve(key + ".jsa");
            boolean beingWritten = settle(key, jars, archive);
            if (Files.isRegularFile(archive) && !changedSince(jars, Files.getLastModifiedTime(archive))) {
                return new Maps(List.of("-XX:SharedArchiveFile=" + archive, QUIET));
            }
            if (beingWritten) {
                return NONE;
            }
            String id = owner + "-" + claims.incrementAndGet();
            Path start = Files.createFile(dir.resolve(key + "." + id + ".start"));
            Path written = dir.resolve(key + "." + id + ".tmp");
            return new Claim(List.of("-XX:ArchiveClassesAtExit=" + written, QUIET), jars, start, written, archive);
        } catch (IOException | RuntimeException e) {
            return NONE; // (a cache: a run never fails for want of it)
        }
    }

    /** MAIN's simple name, a dash and a checksum of the main class, class path and options. */
    static String key(String mainClass, String classPath, List<String> jvmOptions) {
        CRC32 crc = new CRC32();
        crc.update(String.join("\n", mainClass, classPath, String.join(" ", jvmOptions))
                .getBytes(StandardCharsets.UTF_8));
        return mainClass.substring(mainClass.lastIndexOf('.') + 1) + "-" + crc.getValue();
    }

    /**
     * Settles the claims on {@code key}'s archive whose owner (the pid their ID starts with) has ended, or
     * that are over an hour old, as {@link Claim#finish()} does; returns whether a live one is left (a
     * process is writing the archive).
     */
    private boolean settle(String key, List<Path> jars, Path archive) {
        boolean live = false;
        try (DirectoryStream<Path> starts = Files.newDirectoryStream(dir, key + ".*.start")) {
            for (Path start : starts) {
                String id = start.getFileName().toString();
                id = id.substring(key.length() + 1, id.length() - ".start".length());
                String pid = id.split("-")[0];
                long age = System.currentTimeMillis() - Files.getLastModifiedTime(start).toMillis();
                if (age < CLAIM_MAX_AGE_MS && pid.chars().allMatch(Character::isDigit)
                        && ProcessHandle.of(Long.parseLong(pid)).map(ProcessHandle::isAlive).orElse(false)) {
                    live = true;
                } else {
                    new Claim(List.of(), jars, start, dir.resolve(key + "." + id + ".tmp"), archive).finish();
                }
            }
        } catch (IOException | RuntimeException e) {
            return true;
        }
        return live;
    }

    private static boolean changedSince(List<Path> jars, FileTime time) throws IOException {
        for (Path jar : jars) {
            if (Files.getLastModifiedTime(jar).compareTo(time) > 0) {
                return true;
            }
        }
        return false;
    }

    /** Whether {@code file} starts with a dynamic archive's magic number: the JVM wrote it whole. */
    static boolean whole(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            byte[] head = in.readNBytes(4);
            return head.length == 4
                    && ByteBuffer.wrap(head).order(ByteOrder.nativeOrder()).getInt() == DYNAMIC_ARCHIVE_MAGIC;
        } catch (IOException e) {
            return false;
        }
    }

    /** A child that writes the archive: its claim, put in place or removed by {@link #finish()}. */
    private record Claim(List<String> options, List<Path> jars, Path start, Path written, Path archive)
            implements Launch {
        @Override
        public void finish() {
            try {
                if (whole(written) && !changedSince(jars, Files.getLastModifiedTime(start))) {
                    Files.move(written, archive, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } else {
                    Files.deleteIfExists(written);
                }
                Files.deleteIfExists(start);
            } catch (IOException | RuntimeException e) {
                // a cache: the next script that starts settles what is left
            }
        }
    }
}
