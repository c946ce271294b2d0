package robosim.examples;

import com.fasterxml.jackson.annotation.JsonIgnoreProperties;
import com.fasterxml.jackson.dataformat.xml.XmlMapper;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlElementWrapper;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * One controllable robot in RobotInfo.xml: its name and where its {@link RemoteControlRobot} listens.
 *
 * <pre>{@code
 * <robotInfo>
 *   <robot name="rc1" host="127.0.0.1" port="9101"/>
 * </robotInfo>
 * }</pre>
 */
public record RobotInfo(String name, String host, int port) {
    /** Where a RemoteControlRobot looks for the file: this system property, else {@link #ENV}, else the default. */
    public static final String PROPERTY = "robosim.robotInfo";
    public static final String ENV = "ROBOSIM_ROBOT_INFO";
    public static final String DEFAULT = "test-envs/RobotInfo.xml";

    /** The file a robot process should read. */
    public static Path configured() {
        String p = System.getProperty(PROPERTY);
        if (p == null || p.isBlank()) {
            p = System.getenv(ENV);
        }
        return Path.of(p == null || p.isBlank() ? DEFAULT : p);
    }

    /**
     * Reads the file; any fault is an IllegalArgumentException whose message names the file, the
     * value and what is wrong, in one line.
     */
    public static List<RobotInfo> load(Path file) {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(file + ": no such file");
        }
        FileXml xml;
        try {
            xml = new XmlMapper().readValue(file.toFile(), FileXml.class);
        } catch (IOException e) {
            String msg = e.getMessage() == null ? e.toString() : e.getMessage().split("\n")[0];
            throw new IllegalArgumentException(file + ": not a RobotInfo file: " + msg);
        }
        List<RobotInfo> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (RobotXml r : xml.robots == null ? List.<RobotXml>of() : xml.robots) {
            if (r.name == null || r.name.isBlank()) {
                throw new IllegalArgumentException(file + ": a <robot> has no name");
            }
            if (!names.add(r.name)) {
                throw new IllegalArgumentException(file + ": robot " + r.name + " is listed twice");
            }
            String host = r.host == null || r.host.isBlank() ? "127.0.0.1" : r.host;
            int port;
            try {
                port = Integer.parseInt(r.port == null ? "" : r.port.trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(file + ": robot " + r.name + ": port \"" + r.port
                        + "\" is not a number");
            }
            if (port < 1 || port > 65535) {
                throw new IllegalArgumentException(file + ": robot " + r.name + ": port " + port
                        + " is not between 1 and 65535");
            }
            out.add(new RobotInfo(r.name, host, port));
        }
        if (out.isEmpty()) {
            throw new IllegalArgumentException(file + ": lists no <robot>");
        }
        return out;
    }

    @JsonIgnoreProperties(ignoreUnknown = false)
    static final class FileXml {
        @JacksonXmlElementWrapper(useWrapping = false)
        @JacksonXmlProperty(localName = "robot")
        public List<RobotXml> robots;
    }

    static final class RobotXml {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String host;
        @JacksonXmlProperty(isAttribute = true)
        public String port;
    }
}
