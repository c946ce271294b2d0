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
 * the archive {@code KEY.jsa} (JDK 19-24: a dynamic CDS archive) or {@code KEY.aot} (JDK 25 and later: an
 * AOT cache, classes loaded and linked and the methods' profiles) of its main class, class path and JVM
 * options (the key) when one is there and newer than every jar of the class path; else, unless another live
 * process is writing it, the child is its training run, under a claim of its own: an empty {@code KEY.ID.start}
 * that dates its start ({@code ID} is this JVM's pid, a dash and a count) next to what it writes at its exit:
 * the dynamic archive itself ({@code -XX:ArchiveClassesAtExit}, into {@code KEY.ID.tmp}), or the AOT
 * configuration ({@code -XX:AOTMode=record}, into {@code KEY.ID.aotconf}), from which an assembling JVM of its
 * own ({@code -XX:AOTMode=create}, started in the background, its pid in its claim's {@code .start}) writes the
 * cache into {@code KEY.ID.tmp}. When a writer has ended, {@link Launch#finish()} renames its file to the archive
 * (an atomic rename: a JVM never maps a file being written) if it is whole (the JVM writes an archive's header,
 * with its magic number, last) and no jar changed since the start, else removes it. A claim whose owner died
 * first is settled so by the next start of its key.
 *
 * <p>The directory comes from {@code ROBOSIM_CDS_DIR}, set by the scripts (empty or absent: no archives,
 * e.g. {@code ROBOSIM_CDS=off}, JDK 17, or a runner started without a script). A class path with a
 * directory (the JVM refuses to archive those, and says so on every run) or options of the user's own
 * about class-data sharing turn archives off for the child. The JVM's {@code cds} and {@code aot} logs are
 * off: they warn about classes it cannot archive; a training run's JVM prints no output of its own (it would
 * say where it recorded its configuration as it exits). Writing an archive is a cache: when it fails, the run
 * goes on without.
 */
final class ClassDataArchives {
    /** The JVM's warnings while writing or mapping an archive (classes it skips, an archive it cannot use). */
    static final List<String> QUIET = List.of("-Xlog:cds*=off", "-Xlog:aot*=off");
    /** A claim older than this is taken as abandoned even when its owner's pid is alive (a reused pid). */
    private static final long CLAIM_MAX_AGE_MS = TimeUnit.HOURS.toMillis(1);
    private static final List<String> USERS_OWN = List.of("Xshare", "SharedArchiveFile", "ArchiveClassesAtExit",
            "AOTCache", "AOTMode", "AOTConfiguration");
    /** The magic number an AOT configuration starts with when its JVM wrote it whole. */
    static final int CONFIGURATION_MAGIC = 0xcafea07c;

    /** What a JDK archives: where its archive is, how it is written and mapped. */
    enum Kind {
        /** JDK 19-24: the classes an exiting JVM loaded, written by it. */
        DYNAMIC(".jsa", 0xf00baba8),
        /** JDK 25 and later: an AOT cache (JEP 483 and 515), assembled from a training run's configuration. */
        AOT(".aot", 0xf00baba2);

        final String suffix;
        /** The magic number the whole archive starts with (in the machine's byte order). */
        final int magic;

        Kind(String suffix, int magic) {
            this.suffix = suffix;
            this.magic = magic;
        }

        /** The kind of the JDK of feature version {@code feature}, or null (JDK 17, 18: none). */
        static Kind of(int feature) {
            return feature >= 25 ? AOT : feature >= 19 ? DYNAMIC : null;
        }

        List<String> maps(Path archive) {
            return with(QUIET, (this == AOT ? "-XX:AOTCache=" : "-XX:SharedArchiveFile=") + archive);
        }

        /**
         * The options of a training run that writes into {@code tmp} or records into {@code configuration}; with
         * {@code silent}, the JVM prints nothing of its own (on JDK 25 it would print where it recorded its
         * configuration as it exits, after the run's last line).
         */
        List<String> trains(Path tmp, Path configuration, boolean silent) {
            if (this == DYNAMIC) {
                return with(QUIET, "-XX:ArchiveClassesAtExit=" + tmp);
            }
            return silent ? with(QUIET, "-XX:AOTMode=record", "-XX:AOTConfiguration=" + configuration,
                    "-XX:+UnlockDiagnosticVMOptions", "-XX:-DisplayVMOutput")
                    : with(QUIET, "-XX:AOTMode=record", "-XX:AOTConfiguration=" + configuration);
        }

        private static List<String> with(List<String> quiet, String... options) {
            List<String> all = new ArrayList<>(List.of(options));
            all.addAll(quiet);
            return List.copyOf(all);
        }
    }

    /** How one child uses its archive: its JVM options, and what to do once it has ended. */
    interface Launch {
        List<String> options();

        /** Puts the archive the ended child wrote in place (or has it assembled), or removes it; never throws. */
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
    private final Kind kind;
    /** The java that assembles an AOT cache (this JDK's). */
    private final String java;
    private final long owner = ProcessHandle.current().pid();
    private final AtomicInteger claims = new AtomicInteger();

    /** Archives of {@code kind} in {@code dir}, assembled (AOT) by {@code java}; null for none. */
    ClassDataArchives(Path dir, Kind kind, String java) {
        this.dir = kind == null ? null : dir;
        this.kind = kind;
        this.java = java;
    }

    /** Archives of {@code kind} in {@code dir}, assembled by this JDK's java; null for none. */
    ClassDataArchives(Path dir, Kind kind) {
        this(dir, kind, Path.of(System.getProperty("java.home"), "bin", "java").toString());
    }

    /** The archives the scripts chose ({@code ROBOSIM_CDS_DIR}), or none. */
    static ClassDataArchives fromEnvironment() {
        String dir = System.getenv("ROBOSIM_CDS_DIR");
        boolean usable = dir != null && !dir.isBlank() && !dir.contains(File.pathSeparator);
        return new ClassDataArchives(usable ? Path.of(dir) : null, Kind.of(Runtime.version().feature()));
    }

    /** The archive options for a child running {@code mainClass} on {@code classPath} with {@code jvmOptions}. */
    Launch launch(String mainClass, String classPath, List<String> jvmOptions) {
        return launch(mainClass, classPath, jvmOptions, true);
    }

    /**
     * As above; {@code silentTraining} false for a child whose stdout is read for its own lines only (a warm worker:
     * what its JVM says as it dies, out of memory, is the reason of the run it broke).
     */
    Launch launch(String mainClass, String classPath, List<String> jvmOptions, boolean silentTraining) {
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
            Files.createDirectories(dir);
            Key key = new Key(key(mainClass, classPath, jvmOptions), jars, classPath, jvmOptions);
            boolean beingWritten = settle(key);
            Path archive = key.archive(dir, kind);
            if (Files.isRegularFile(archive) && !changedSince(jars, Files.getLastModifiedTime(archive))) {
                return new Maps(kind.maps(archive));
            }
            if (beingWritten) {
                return NONE;
            }
            Claim claim = claim(key);
            return new Training(kind.trains(claim.tmp(), claim.configuration(), silentTraining), claim);
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

    /** A key's name and what its JVMs run on. */
    private record Key(String name, List<Path> jars, String classPath, List<String> jvmOptions) {
        Path archive(Path dir, Kind kind) {
            return dir.resolve(name + kind.suffix);
        }
    }

    /** A new claim of this JVM's on {@code key}'s archive. */
    private Claim claim(Key key) throws IOException {
        String id = owner + "-" + claims.incrementAndGet();
        Path base = dir.resolve(key.name() + "." + id);
        return new Claim(key, Files.createFile(Path.of(base + ".start")), Path.of(base + ".tmp"),
                Path.of(base + ".aotconf"), false);
    }

    /**
     * Settles the claims on {@code key}'s archive whose owner (the pid in their {@code .start}, else the one their ID
     * starts with) has ended, or that are over an hour old, as {@link Claim#settle()} does; returns whether a live
     * one is left (a process is writing the archive).
     */
    private boolean settle(Key key) {
        boolean live = false;
        try (DirectoryStream<Path> starts = Files.newDirectoryStream(dir, key.name() + ".*.start")) {
            for (Path start : starts) {
                String id = start.getFileName().toString();
                id = id.substring(key.name().length() + 1, id.length() - ".start".length());
                String assembler;
                long age;
                try {
                    assembler = Files.readString(start).strip();
                    age = System.currentTimeMillis() - Files.getLastModifiedTime(start).toMillis();
                } catch (java.nio.file.NoSuchFileException settled) {
                    continue; // (settled meanwhile: by its assembler's end, or another start)
                }
                String pid = assembler.isEmpty() ? id.split("-")[0] : assembler;
                if (age < CLAIM_MAX_AGE_MS && !pid.isEmpty() && pid.length() < 19
                        && pid.chars().allMatch(Character::isDigit)
                        && ProcessHandle.of(Long.parseLong(pid)).map(ProcessHandle::isAlive).orElse(false)) {
                    live = true;
                } else {
                    Path base = dir.resolve(key.name() + "." + id);
                    live |= new Claim(key, start, Path.of(base + ".tmp"), Path.of(base + ".aotconf"),
                            !assembler.isEmpty()).settle();
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

    /**
     * {@code options} less those that write files or print (logs, flight recordings, heap dumps, error files, agents,
     * statistics at exit): what a second JVM of the same options, the AOT cache's assembler, takes ({@code
     * robosim_jvm_quiet} in scripts/common.sh).
     */
    static List<String> quiet(List<String> options) {
        List<String> kept = new ArrayList<>();
        for (String o : options) {
            if (!(o.startsWith("-Xlog") || o.startsWith("-Xloggc") || o.startsWith("-verbose")
                    || o.startsWith("-XX:StartFlightRecording") || o.startsWith("-XX:FlightRecorderOptions")
                    || o.startsWith("-XX:+HeapDump") || o.startsWith("-XX:HeapDumpPath") || o.startsWith("-XX:ErrorFile")
                    || o.startsWith("-javaagent") || o.startsWith("-agentlib") || o.startsWith("-agentpath")
                    || o.startsWith("-XX:+Print") || o.startsWith("-XX:NativeMemoryTracking"))) {
                kept.add(o);
            }
        }
        return kept;
    }

    /** Whether {@code file} starts with {@code magic} (in the machine's byte order): the JVM wrote it whole. */
    static boolean whole(Path file, int magic) {
        try (InputStream in = Files.newInputStream(file)) {
            byte[] head = in.readNBytes(4);
            return head.length == 4 && ByteBuffer.wrap(head).order(ByteOrder.nativeOrder()).getInt() == magic;
        } catch (IOException e) {
            return false;
        }
    }

    /** A training child: its options, and its claim settled when it has ended. */
    private record Training(List<String> options, Claim claim) implements Launch {
        @Override
        public void finish() {
            claim.settle();
        }
    }

    /**
     * A claim on a key's archive: its {@code .start}, the archive it writes ({@code tmp}) and, for an AOT cache, the
     * configuration a training run records or the one its assembler reads (an assembler's claim has the assembler's
     * pid in its {@code .start}).
     */
    private final class Claim {
        private final Key key;
        private final Path start;
        private final Path tmp;
        private final Path configuration;
        private final boolean assembly;

        Claim(Key key, Path start, Path tmp, Path configuration, boolean assembly) {
            this.key = key;
            this.start = start;
            this.tmp = tmp;
            this.configuration = configuration;
            this.assembly = assembly;
        }

        Path tmp() {
            return tmp;
        }

        Path configuration() {
            return configuration;
        }

        /**
         * Its writer has ended: puts a whole archive of unchanged jars in place, or has a training run's whole
         * configuration assembled, and removes the rest (an assembly that wrote nothing is not tried again);
         * returns whether an assembler was started. Never throws.
         */
        boolean settle() {
            boolean assembling = false;
            try {
                boolean unchanged = !changedSince(key.jars(), Files.getLastModifiedTime(start));
                if (Files.exists(tmp)) {
                    if (unchanged && whole(tmp, kind.magic)) {
                        Files.move(tmp, key.archive(dir, kind), StandardCopyOption.ATOMIC_MOVE,
                                StandardCopyOption.REPLACE_EXISTING);
                    } else {
                        Files.deleteIfExists(tmp);
                    }
                } else if (!assembly && unchanged && kind == Kind.AOT && whole(configuration, CONFIGURATION_MAGIC)) {
                    assembling = assemble();
                }
                Files.deleteIfExists(configuration);
                Files.deleteIfExists(start);
            } catch (IOException | RuntimeException e) {
                // a cache: the next start of the key settles what is left
            }
            return assembling;
        }

        /**
         * Starts a JVM that assembles the cache from this claim's configuration, under a claim of its own (touched
         * first, so no hourly clean-up takes it), deaf to the Ctrl-C of the terminal it was started from, with the
         * JVM options the cache depends on ({@link #quiet}).
         */
        private boolean assemble() throws IOException {
            Claim claimed = claim(key);
            Claim assembly = new Claim(key, claimed.start, claimed.tmp, claimed.configuration, true);
            try {
                Files.setLastModifiedTime(configuration, FileTime.fromMillis(System.currentTimeMillis()));
                Files.move(configuration, assembly.configuration, StandardCopyOption.ATOMIC_MOVE);
            } catch (IOException e) {
                Files.deleteIfExists(assembly.start); // (another start took it first)
                throw e;
            }
            List<String> command = new ArrayList<>(List.of("sh", "-c", "trap '' INT; exec \"$@\"", "sh", java));
            command.addAll(quiet(key.jvmOptions()));
            command.addAll(List.of("-XX:AOTMode=create", "-XX:AOTConfiguration=" + assembly.configuration,
                    "-XX:AOTCache=" + assembly.tmp, "-cp", key.classPath()));
            command.addAll(QUIET);
            Process assembler;
            try {
                assembler = new ProcessBuilder(command).redirectErrorStream(true)
                        .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            } catch (IOException e) {
                assembly.settle();
                throw e;
            }
            Files.writeString(assembly.start, Long.toString(assembler.pid()));
            assembler.onExit().thenRun(assembly::settle);
            return true;
        }
    }
}
