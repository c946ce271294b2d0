package robosim.environment.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.core.WorldSpec;

/** An environment file's placeholders ({@code ${name:default}}) and {@code <param>}s, and the values given for them. */
class ParametersTest {
    @TempDir
    Path dir;

    private static final String WORLD = """
            <environment timeStepMs="${step:500}" seed="3">
              <param name="speed" value="400"/>
              <param name="mode" value="${mode:calm}"/>
              <arena width="10" height="5"/>
              <robots>
                <robot name="r1" type="ArRobot" control="x.Y" x="${x:1.5}" y="1" heading="0">
                  <param name="speed" value="250"/>
                  <param name="role" value="scout"/>
                </robot>
                <robot name="r2" type="ArRobot" control="x.Y" x="4" y="1" heading="0"/>
              </robots>
            </environment>
            """;

    private Path write(String xml) throws IOException {
        Path f = dir.resolve("world.xml");
        Files.writeString(f, xml);
        return f;
    }

    private String failure(String xml, Map<String, String> given) throws IOException {
        Path f = write(xml);
        EnvironmentFileException e = assertThrows(EnvironmentFileException.class,
                () -> new EnvironmentLoader().load(f, given));
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        assertTrue(e.getMessage().startsWith(f.toString()), "names the file: " + e.getMessage());
        return e.getMessage();
    }

    @Test
    void aFileRunsAloneOnItsDefaults() throws Exception {
        WorldSpec w = new EnvironmentLoader().load(write(WORLD));
        assertEquals(500, w.timeStepMs());
        assertEquals(1500, w.robots().get(0).xMm(), 1e-9);
        assertEquals(Map.of("speed", "250", "mode", "calm", "role", "scout"), w.parameters().of("r1"));
        assertEquals(List.of("speed", "mode"), List.copyOf(w.parameters().of("r2").keySet()));
        assertEquals("400", w.parameters().of("r2").get("speed"));
        assertEquals("400", w.parameters().of("joined-later").get("speed"), "a robot that joins gets the world's");
    }

    @Test
    void givenValuesReplacePlaceholdersAndTheWorldsParamsButNotARobotsOwn() throws Exception {
        WorldSpec w = new EnvironmentLoader().load(write(WORLD), Map.of("x", "2", "speed", "600", "mode", "a<\"b\">&c"));
        assertEquals(2000, w.robots().get(0).xMm(), 1e-9);
        assertEquals("600", w.parameters().of("r2").get("speed"));
        assertEquals("250", w.parameters().of("r1").get("speed"), "the robot's own <param> is over the world's");
        assertEquals("a<\"b\">&c", w.parameters().of("r2").get("mode"), "a value is text, never markup");
    }

    @Test
    void aDollarBraceOfTheFilesOwnIsWrittenTwice() throws Exception {
        WorldSpec w = new EnvironmentLoader().load(write(WORLD.replace("\"scout\"", "\"$${scout}\"")));
        assertEquals("${scout}", w.parameters().of("r1").get("role"));
    }

    @Test
    void aNameTheFileDoesNotHaveIsRefusedNamingThoseItHas() throws Exception {
        String e = failure(WORLD, Map.of("sped", "600"));
        assertTrue(e.endsWith("no parameter 'sped' here (its parameters: mode, speed, step, x)"), e);
    }

    @Test
    void aPlaceholderWithoutDefaultNeedsAValueAndSaysWhere() throws Exception {
        String xml = WORLD.replace("${x:1.5}", "${x}");
        String e = failure(xml, Map.of());
        assertTrue(e.contains("world.xml:6:54:") && e.contains("${x} has no default"), e);
        assertEquals(3000, new EnvironmentLoader().load(write(xml), Map.of("x", "3")).robots().get(0).xMm(), 1e-9);
    }

    @Test
    void badPlaceholdersAndParams() throws Exception {
        assertTrue(failure(WORLD.replace("${x:1.5}", "${1x:1.5}"), Map.of()).contains("is not a placeholder"));
        assertTrue(failure(WORLD.replace("${x:1.5}", "${x:1.5"), Map.of()).contains("without its closing"));
        assertTrue(failure(WORLD.replace("${x:1.5}", "${x:${y}}"), Map.of()).contains("do not nest"));
        assertTrue(failure(WORLD.replace("value=\"scout\"", "value=\"" + "v".repeat(5000) + "\""), Map.of())
                .contains("longer than 4096 bytes"));
        assertTrue(failure(WORLD.replace("\"role\" value=\"scout\"", "\"role\""), Map.of()).contains("needs a value"));
        assertTrue(failure(WORLD.replace("name=\"mode\"", "name=\"speed\""), Map.of()).contains("given twice"));
        assertTrue(failure(WORLD, Map.of("x", "abc")).contains("'abc' is not a double"));
        assertTrue(failure(WORLD, Map.of("speed", "v".repeat(5000))).contains(": --param speed: a name of 1 to 64"));
    }

    @Test
    void everyPlaceholderFaultIsReportedAtOnceAndTheFileIsReadNoFurther() throws Exception {
        // (the robot outside the arena is not reported: the text to read is not known while a placeholder is at fault)
        Path f = write(WORLD.replace("${x:1.5}", "${x}").replace("x=\"4\"", "x=\"${1x:40}\"")
                .replace("name=\"role\"", "name=\"${role\""));
        EnvironmentFileException e = assertThrows(EnvironmentFileException.class,
                () -> new EnvironmentLoader().load(f, Map.of()));
        assertEquals(List.of(
                f + ":6:54: ${x} has no default (write ${x:VALUE}) and no value was given for it (--param x=VALUE)",
                f + ":8:20: '${' without its closing '}' on its line (placeholders do not nest; $${ is a '${' of the "
                        + "file's own)",
                f + ":10:54: '${1x:40}' is not a placeholder: a name is 1 to 64 letters, digits, '_', '.' or '-', "
                        + "not a digit first"), e.getMessage().lines().toList());
    }
}
