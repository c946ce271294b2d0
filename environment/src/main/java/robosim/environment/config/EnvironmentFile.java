package robosim.environment.config;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlElementWrapper;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement;
import java.util.ArrayList;
import java.util.List;

/**
 * The XML environment file as written (metres and degrees); see {@code test-envs/README.md}.
 * Boxed fields stay null when an attribute is missing, so the loader can name it.
 */
@JacksonXmlRootElement(localName = "environment")
public final class EnvironmentFile {
    @JacksonXmlProperty(isAttribute = true)
    public String name;
    @JacksonXmlProperty(isAttribute = true)
    public Long timeStepMs;
    @JacksonXmlProperty(isAttribute = true)
    public Long seed;
    /** How far messages between robots carry, metres (centre to centre); absent = everywhere. */
    @JacksonXmlProperty(isAttribute = true)
    public Double commRangeM;
    /** Largest message payload in bytes; absent = 8192. */
    @JacksonXmlProperty(isAttribute = true)
    public Integer maxMessageBytes;
    public ArenaXml arena;
    public ObstaclesXml obstacles = new ObstaclesXml();
    @JacksonXmlElementWrapper(localName = "robots")
    @JacksonXmlProperty(localName = "robot")
    public List<RobotXml> robots = new ArrayList<>();

    /** {@code <arena width="12" height="8"/>}: metres, lower-left corner at the origin unless x/y say. */
    public static final class ArenaXml {
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
        public final List<Object> all = new ArrayList<>();

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
    public static final class RectangleXml {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
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
    public static final class PolygonXml {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String points;
    }

    /** {@code <robot name="robot1" type="ArRobot" control="robosim.examples.BackAndForth" x="1" y="1" heading="0"/>}. */
    public static final class RobotXml {
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
    }
}
