package robosim.environment.config;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlElementWrapper;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement;
import java.util.ArrayList;
import java.util.List;

/**
 * The XML environment file as written (metres and degrees); see {@code test-envs/README.md}.
 * Boxed fields stay null when an attribute is missing, so the loader can name it; each element knows where it
 * starts ({@link FileElement}), so a fault in it can say where.
 */
@JacksonXmlRootElement(localName = "environment")
public final class EnvironmentFile extends FileElement {
    @JacksonXmlProperty(isAttribute = true)
    public String name;
    @JacksonXmlProperty(isAttribute = true)
    public Long timeStepMs;
    @JacksonXmlProperty(isAttribute = true)
    public Long seed;
    /** How far messages between robots carry, metres (centre to centre); absent = everywhere. */
    @JacksonXmlProperty(isAttribute = true)
    public Double commRangeM;
    /** How far a tag reaches from the robot's rim, metres; absent = 1. */
    @JacksonXmlProperty(isAttribute = true)
    public Double tagRangeM;
    /** Largest message payload in bytes; absent = 8192. */
    @JacksonXmlProperty(isAttribute = true)
    public Integer maxMessageBytes;
    public ArenaXml arena;
    public ObstaclesXml obstacles = new ObstaclesXml();
    @JacksonXmlElementWrapper(localName = "heatSources")
    @JacksonXmlProperty(localName = "heat")
    public List<HeatXml> heatSources = new ArrayList<>();
    @JacksonXmlElementWrapper(localName = "robots")
    @JacksonXmlProperty(localName = "robot")
    public List<RobotXml> robots = new ArrayList<>();
    @JacksonXmlElementWrapper(useWrapping = false)
    @JacksonXmlProperty(localName = "join")
    public List<JoinXml> joins = new ArrayList<>();
    /** Parameters for every robot's control code. */
    @JacksonXmlElementWrapper(useWrapping = false)
    @JacksonXmlProperty(localName = "param")
    public List<ParamXml> params = new ArrayList<>();

    /** {@code <param name="speed" value="300"/>}: a value the control code reads with {@code Robot.parameter}. */
    public static final class ParamXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String value;
    }

    /**
     * {@code <join allow="scout-*" type="Scout" control="..." max="20" heading="90"><spawn x="1" y="1"
     * width="4" height="3"/></join>}: robots whose names match may join the running world, entering at the
     * first free pose of the spawn region; {@code <sensor>} children as on a robot.
     */
    public static final class JoinXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String allow;
        @JacksonXmlProperty(isAttribute = true)
        public String type;
        @JacksonXmlProperty(isAttribute = true)
        public String control;
        @JacksonXmlProperty(isAttribute = true)
        public Integer max;
        @JacksonXmlProperty(isAttribute = true)
        public Double heading;
        @JacksonXmlProperty(isAttribute = true)
        public Double radius;
        @JacksonXmlProperty(isAttribute = true)
        public Integer sonars;
        @JacksonXmlProperty(isAttribute = true)
        public Double sonarNoiseMm;
        public SpawnXml spawn;
        @JacksonXmlElementWrapper(useWrapping = false)
        @JacksonXmlProperty(localName = "sensor")
        public List<SensorXml> sensors = new ArrayList<>();
    }

    /** {@code <spawn x="1" y="1" width="4" height="3"/>}: lower-left corner and size, metres. */
    public static final class SpawnXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double width;
        @JacksonXmlProperty(isAttribute = true)
        public Double height;
    }

    /** {@code <arena width="12" height="8"/>}: metres, lower-left corner at the origin unless x/y say. */
    public static final class ArenaXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double width;
        @JacksonXmlProperty(isAttribute = true)
        public Double height;
    }

    /**
     * {@code <obstacles>} holding {@code <rectangle>} and {@code <polygon>} elements in any order;
     * setters (called once per element) keep them in file order, as one list.
     */
    public static final class ObstaclesXml {
        public final List<FileElement> all = new ArrayList<>();

        @JacksonXmlProperty(localName = "rectangle")
        public void setRectangle(RectangleXml r) {
            all.add(r);
        }

        @JacksonXmlProperty(localName = "polygon")
        public void setPolygon(PolygonXml p) {
            all.add(p);
        }
    }

    /** {@code <rectangle name="wall" x="1" y="2" width="3" height="0.2"/>}: lower-left corner, metres. */
    public static final class RectangleXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        /** A robot's tag can hit it. */
        @JacksonXmlProperty(isAttribute = true)
        public Boolean taggable;
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double width;
        @JacksonXmlProperty(isAttribute = true)
        public Double height;
    }

    /** {@code <polygon name="rock" points="1,1 2,1 1.5,2"/>}: vertices in metres. */
    public static final class PolygonXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public Boolean taggable;
        @JacksonXmlProperty(isAttribute = true)
        public String points;
    }

    /** {@code <robot name="robot1" type="ArRobot" control="robosim.examples.BackAndForth" x="1" y="1" heading="0"/>}. */
    public static final class RobotXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String type;
        @JacksonXmlProperty(isAttribute = true)
        public String control;
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double heading;
        /** Radius in metres: required for a robot type given by class name, checked against known models. */
        @JacksonXmlProperty(isAttribute = true)
        public Double radius;
        /** How many sonars the robot must report; absent = whatever its type has. */
        @JacksonXmlProperty(isAttribute = true)
        public Integer sonars;
        /** Standard deviation of Gaussian noise on its sonar ranges, mm; absent = none. */
        @JacksonXmlProperty(isAttribute = true)
        public Double sonarNoiseMm;
        /** {@code any-time}: not waited for at the start; it may join the running world at its start pose. */
        @JacksonXmlProperty(isAttribute = true)
        public String join;
        @JacksonXmlElementWrapper(useWrapping = false)
        @JacksonXmlProperty(localName = "sensor")
        public List<SensorXml> sensors = new ArrayList<>();
        /** This robot's own parameters, over the world's. */
        @JacksonXmlElementWrapper(useWrapping = false)
        @JacksonXmlProperty(localName = "param")
        public List<ParamXml> params = new ArrayList<>();
    }

    /**
     * {@code <sensor name="front-laser" type="laser" noise="5" fovDeg="180"/>} inside a robot: any
     * other attribute goes to the sensor's own {@code configure}.
     */
    public static final class SensorXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String type;
        public final java.util.Map<String, String> attributes = new java.util.LinkedHashMap<>();

        @com.fasterxml.jackson.annotation.JsonAnySetter
        public void attribute(String key, String value) {
            attributes.put(key, value);
        }
    }

    /** {@code <heat name="fire" x="5" y="3" intensity="10"/>}: metres; intensity is the reading at the source. */
    public static final class HeatXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double intensity;
    }
}
