package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The class-data archive rules for the runner's children, on files alone (no JVM writes an archive here):
 * who writes, who maps, when a written archive is put in place and when it is dropped.
 */
class ClassDataArchivesTest {
    private static final String MAIN = "robosim.environment.EnvironmentMain";
    private static final List<String> OPTIONS = List.of("-XX:+UseSerialGC");

    @TempDir
    Path tmp;
    private Path dir;
    private Path jar;
    private String classPath;

    @BeforeEach
    void jars() throws IOException {
        dir = tmp.resolve("cds");
        jar = Files.writeString(tmp.resolve("environment.jar"), "jar");
        Path other = Files.writeString(tmp.resolve("protocol.jar"), "jar");
        classPath = jar + File.pathSeparator + other;
        Instant anHourAgo = Instant.now().minusSeconds(3600);
        Files.setLastModifiedTime(jar, FileTime.from(anHourAgo));
        Files.setLastModifiedTime(other, FileTime.from(anHourAgo));
    }

    @Test
    void theFirstChildWritesTheArchiveAtItsExitAndTheNextMapsIt() throws IOException {
        ClassDataArchives archives = new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC);
        ClassDataArchives.Launch first = archives.launch(MAIN, classPath, OPTIONS);
        Path written = writtenBy(first);
        assertTrue(first.options().containsAll(ClassDataArchives.QUIET), first.options().toString());
        assertTrue(written.getFileName().toString().startsWith("EnvironmentMain-"), written.toString());

        writeWholeArchive(written);
        first.finish();
        Path archive = dir.resolve(ClassDataArchives.key(MAIN, classPath, OPTIONS) + ".jsa");
        assertEquals(List.of(archive), files(), "only the archive is left");
        assertEquals(mapping(archive),
                archives.launch(MAIN, classPath, OPTIONS).options());
    }

    @Test
    void whileOneChildWritesTheArchiveTheOthersRunWithout() throws IOException {
        ClassDataArchives archives = new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC);
        writtenBy(archives.launch(MAIN, classPath, OPTIONS));
        assertEquals(List.of(), archives.launch(MAIN, classPath, OPTIONS).options());
        assertEquals(List.of(), new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC).launch(MAIN, classPath, OPTIONS).options(),
                "another runner of the same key waits too");
        writtenBy(archives.launch(MAIN, classPath, List.of("-XX:+UseParallelGC"))); // another key
    }

    @Test
    void anArchiveWhoseWriterDiedBeforePuttingItInPlaceIsPutInPlaceByTheNextLaunch() throws Exception {
        Process ended = new ProcessBuilder("true").start();
        ended.waitFor();
        String key = ClassDataArchives.key(MAIN, classPath, OPTIONS);
        Files.createDirectories(dir);
        Files.createFile(dir.resolve(key + "." + ended.pid() + "-1.start"));
        writeWholeArchive(dir.resolve(key + "." + ended.pid() + "-1.tmp"));
        Path archive = dir.resolve(key + ".jsa");
        assertEquals(mapping(archive),
                new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC).launch(MAIN, classPath, OPTIONS).options());
        assertEquals(List.of(archive), files());
    }

    @Test
    void anArchiveCutShortIsDroppedNeverPutInPlace() throws IOException {
        ClassDataArchives.Launch first = new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC).launch(MAIN, classPath, OPTIONS);
        Files.write(writtenBy(first), new byte[4096]); // (the JVM writes the header, with its magic, last)
        first.finish();
        assertEquals(List.of(), files());
    }

    @Test
    void anArchiveOfAJarThatChangedDuringTheRunIsDropped() throws IOException {
        ClassDataArchives.Launch first = new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC).launch(MAIN, classPath, OPTIONS);
        writeWholeArchive(writtenBy(first));
        Files.setLastModifiedTime(jar, FileTime.from(Instant.now().plusSeconds(5)));
        first.finish();
        assertEquals(List.of(), files());
    }

    @Test
    void anArchiveOlderThanAJarIsNotMappedButWrittenAgain() throws IOException {
        ClassDataArchives archives = new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC);
        ClassDataArchives.Launch first = archives.launch(MAIN, classPath, OPTIONS);
        writeWholeArchive(writtenBy(first));
        first.finish();
        Files.setLastModifiedTime(jar, FileTime.from(Instant.now().plusSeconds(5))); // a rebuild
        writtenBy(archives.launch(MAIN, classPath, OPTIONS));
    }

    @Test
    void noArchivesWithoutADirectoryForAClassDirectoryOrWithTheUsersOwnSharingOptions() throws IOException {
        assertEquals(List.of(), new ClassDataArchives(null, ClassDataArchives.Kind.DYNAMIC).launch(MAIN, classPath, OPTIONS).options());
        ClassDataArchives archives = new ClassDataArchives(dir, ClassDataArchives.Kind.DYNAMIC);
        assertEquals(List.of(), archives.launch(MAIN, classPath + File.pathSeparator + tmp, OPTIONS).options());
        for (String own : List.of("-Xshare:off", "-XX:SharedArchiveFile=app.jsa", "-XX:AOTCache=app.aot")) {
            assertEquals(List.of(), archives.launch(MAIN, classPath, List.of(own)).options(), own);
        }
        assertFalse(Files.exists(dir), "nothing written");
    }

    @Test
    void onJdk25TheTrainingRunRecordsAConfigurationAndTheCacheIsAssembledFromItOnce() throws Exception {
        // (the assembler, in place of java: one that waits until it is stopped, as one that fails would end)
        Path assemblerJava = Files.writeString(tmp.resolve("java"), "#!/bin/sh\nexec sleep 600\n");
        assertTrue(assemblerJava.toFile().setExecutable(true));
        ClassDataArchives archives = new ClassDataArchives(dir, ClassDataArchives.Kind.AOT, assemblerJava.toString());
        ClassDataArchives.Launch first = archives.launch(MAIN, classPath, OPTIONS);
        String prefix = "-XX:AOTConfiguration=";
        Path configuration = Path.of(first.options().stream().filter(o -> o.startsWith(prefix)).findFirst()
                .orElseThrow(() -> new AssertionError("should record: " + first.options())).substring(prefix.length()));
        assertTrue(first.options().containsAll(List.of("-XX:AOTMode=record", "-XX:-DisplayVMOutput")),
                "a training run prints nothing of the JVM's own: " + first.options());
        assertEquals(List.of(), archives.launch(MAIN, classPath, OPTIONS).options(), "one training run at a time");
        assertFalse(archives.launch(RunHost.class.getName(), classPath, OPTIONS, false).options()
                .contains("-XX:-DisplayVMOutput"), "a warm worker's JVM still says why it died");

        Files.write(configuration, ByteBuffer.allocate(4096).order(ByteOrder.nativeOrder())
                .putInt(ClassDataArchives.CONFIGURATION_MAGIC).array());
        first.finish();
        List<Path> claims = files().stream().filter(p -> p.getFileName().toString().startsWith("EnvironmentMain"))
                .toList();
        assertEquals(2, claims.size(), "the assembler's claim and configuration: " + claims);
        Path start = claims.stream().filter(p -> p.toString().endsWith(".start")).findFirst().orElseThrow();
        ProcessHandle assembler = ProcessHandle.of(Long.parseLong(Files.readString(start).strip())).orElseThrow();
        assertEquals(List.of(), archives.launch(MAIN, classPath, OPTIONS).options(), "no training beside an assembler");

        assembler.destroy(); // (an assembly that fails)
        assembler.onExit().get(60, java.util.concurrent.TimeUnit.SECONDS);
        ClassDataArchives.Launch again = archives.launch(MAIN, classPath, OPTIONS);
        assertTrue(again.options().contains("-XX:AOTMode=record"), "trained again: " + again.options());
        assertEquals(1, files().stream().filter(p -> p.getFileName().toString().startsWith("EnvironmentMain")).count(),
                "the failed assembly left nothing, and was not tried again: " + files());
    }

    @Test
    void theAssemblerTakesTheOptionsTheCacheDependsOnNotThoseThatWriteFiles() {
        assertEquals(List.of("-XX:+UseSerialGC", "-Xmx1g", "-Dx=1"), ClassDataArchives.quiet(List.of("-XX:+UseSerialGC",
                "-Xlog:gc:file=gc.log", "-Xmx1g", "-XX:StartFlightRecording=filename=a.jfr", "-Dx=1",
                "-XX:+HeapDumpOnOutOfMemoryError", "-javaagent:a.jar")));
    }

    @Test
    void onJdk25ACacheIsMappedWithTheAotOption() throws IOException {
        String key = ClassDataArchives.key(MAIN, classPath, OPTIONS);
        Files.createDirectories(dir);
        Path cache = dir.resolve(key + ".aot");
        Files.write(cache, new byte[16]);
        List<String> options = new ClassDataArchives(dir, ClassDataArchives.Kind.AOT).launch(MAIN, classPath, OPTIONS)
                .options();
        assertEquals("-XX:AOTCache=" + cache, options.get(0));
        assertTrue(options.containsAll(ClassDataArchives.QUIET), options.toString());
    }

    private static List<String> mapping(Path archive) {
        List<String> options = new java.util.ArrayList<>(List.of("-XX:SharedArchiveFile=" + archive));
        options.addAll(ClassDataArchives.QUIET);
        return options;
    }

    /** The file {@code launch} writes its archive to (and checks that it writes one). */
    private static Path writtenBy(ClassDataArchives.Launch launch) {
        String prefix = "-XX:ArchiveClassesAtExit=";
        String option = launch.options().stream().filter(o -> o.startsWith(prefix)).findFirst()
                .orElseThrow(() -> new AssertionError("should write an archive: " + launch.options()));
        return Path.of(option.substring(prefix.length()));
    }

    /** What a JVM leaves when it has written an archive: its magic number first, in the machine's order. */
    private static void writeWholeArchive(Path file) throws IOException {
        ByteBuffer whole = ByteBuffer.allocate(4096).order(ByteOrder.nativeOrder()).putInt(0xf00baba8);
        Files.write(file, whole.array());
        assertTrue(ClassDataArchives.whole(file, ClassDataArchives.Kind.DYNAMIC.magic));
    }

    private List<Path> files() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.sorted().toList();
        }
    }
}
