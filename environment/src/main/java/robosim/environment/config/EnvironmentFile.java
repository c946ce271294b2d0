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
    public FloorXml floor;
    @JacksonXmlElementWrapper(localName = "lights")
    @JacksonXmlProperty(localName = "light")
    public List<LightXml> lights = new ArrayList<>();
    public ObjectsXml objects = new ObjectsXml();
    @JacksonXmlElementWrapper(localName = "robots")
    @JacksonXmlProperty(localName = "robot")
    public List<RobotXml> robots = new ArrayList<>();
    /** Robots or objects placed at random or on a grid ({@code <distribute>}), after those the file places. */
    @JacksonXmlElementWrapper(useWrapping = false)
    @JacksonXmlProperty(localName = "distribute")
    public List<DistributeXml> distribute = new ArrayList<>();
    @JacksonXmlElementWrapper(useWrapping = false)
    @JacksonXmlProperty(localName = "join")
    public List<JoinXml> joins = new ArrayList<>();
    /** The experiment's own code, run inside the world while it steps. */
    public LoopFunctionsXml loopFunctions;
    /** Parameters for every robot's control code. */
    @JacksonXmlElementWrapper(useWrapping = false)
    @JacksonXmlProperty(localName = "param")
    public List<ParamXml> params = new ArrayList<>();

    /**
     * {@code <loopFunctions class="robosim.examples.ForagingLoopFunctions"><param name="items" value="15"/>
     * </loopFunctions>}: the experiment's {@code robosim.loop.LoopFunctions} and their parameters.
     */
    public static final class LoopFunctionsXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true, localName = "class")
        public String className;
        @JacksonXmlElementWrapper(useWrapping = false)
        @JacksonXmlProperty(localName = "param")
        public List<ParamXml> params = new ArrayList<>();
    }

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
        /** The robot type's devices the joining robots have on, by name; absent = all. */
        @JacksonXmlProperty(isAttribute = true)
        public String devices;
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

    /**
     * {@code <rectangle name="wall" x="1" y="2" width="3" height="0.2"/>}: lower-left corner, metres; on the floor, a
     * painted region of its {@code colour}.
     */
    public static final class RectangleXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String colour;
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

    /** {@code <polygon name="rock" points="1,1 2,1 1.5,2"/>}: vertices in metres; on the floor, of its {@code colour}. */
    public static final class PolygonXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public String colour;
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
        /** Its type's devices it has on, by name ({@code "proximity light"}); absent = all. */
        @JacksonXmlProperty(isAttribute = true)
        public String devices;
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

    /**
     * {@code <floor colour="white" image="floor.png">} holding painted regions, {@code <rectangle>}, {@code <circle>}
     * and {@code <polygon>} with a {@code colour} each, in any order (a later one over an earlier one); the image, a
     * PNG beside the file, is stretched over the whole arena under them.
     */
    public static final class FloorXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String colour;
        @JacksonXmlProperty(isAttribute = true)
        public String image;
        public final List<FileElement> regions = new ArrayList<>();

        @JacksonXmlProperty(localName = "rectangle")
        public void setRectangle(RectangleXml r) {
            regions.add(r);
        }

        @JacksonXmlProperty(localName = "circle")
        public void setCircle(CircleXml c) {
            regions.add(c);
        }

        @JacksonXmlProperty(localName = "polygon")
        public void setPolygon(PolygonXml p) {
            regions.add(p);
        }
    }

    /** {@code <circle x="1" y="2" radius="0.3" colour="black"/>}: a painted disc of the floor, metres. */
    public static final class CircleXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double radius;
        @JacksonXmlProperty(isAttribute = true)
        public String colour;
    }

    /** {@code <light name="lamp" x="1" y="2" height="1" colour="yellow" intensity="3" on="true"/>}: metres. */
    public static final class LightXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double height;
        @JacksonXmlProperty(isAttribute = true)
        public String colour;
        @JacksonXmlProperty(isAttribute = true)
        public Double intensity;
        @JacksonXmlProperty(isAttribute = true)
        public Boolean on;
    }

    /** {@code <objects>} holding {@code <box>} and {@code <cylinder>} elements in any order, kept in file order. */
    public static final class ObjectsXml {
        public final List<ObjectXml> all = new ArrayList<>();

        @JacksonXmlProperty(localName = "box")
        public void setBox(BoxXml b) {
            all.add(b);
        }

        @JacksonXmlProperty(localName = "cylinder")
        public void setCylinder(CylinderXml c) {
            all.add(c);
        }
    }

    /** What a box and a cylinder both have: a name, a centre and heading, metres and degrees, and their physics. */
    public abstract static class ObjectXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String name;
        @JacksonXmlProperty(isAttribute = true)
        public Double x;
        @JacksonXmlProperty(isAttribute = true)
        public Double y;
        @JacksonXmlProperty(isAttribute = true)
        public Double heading;
        @JacksonXmlProperty(isAttribute = true)
        public Double height;
        /** kg; absent = 1. */
        @JacksonXmlProperty(isAttribute = true)
        public Double mass;
        /** Coefficient of friction with the floor; absent = 0.5. */
        @JacksonXmlProperty(isAttribute = true)
        public Double friction;
        @JacksonXmlProperty(isAttribute = true)
        public Boolean movable;
        @JacksonXmlProperty(isAttribute = true)
        public Boolean gripable;
        @JacksonXmlProperty(isAttribute = true)
        public String colour;
    }

    /** {@code <box name="b1" x="1" y="2" width="0.3" depth="0.2" height="0.1" heading="30" movable="true"/>}. */
    public static final class BoxXml extends ObjectXml {
        @JacksonXmlProperty(isAttribute = true)
        public Double width;
        @JacksonXmlProperty(isAttribute = true)
        public Double depth;
    }

    /** {@code <cylinder name="c1" x="1" y="2" radius="0.1" height="0.2" movable="true" gripable="true"/>}. */
    public static final class CylinderXml extends ObjectXml {
        @JacksonXmlProperty(isAttribute = true)
        public Double radius;
    }

    /**
     * {@code <distribute>}: {@code <position method="uniform" min="x,y" max="x,y"/>} (or {@code gaussian mean= stdDev=},
     * {@code grid center= distances= layout=}, {@code constant values=}), {@code <orientation method="uniform" min="0"
     * max="360"/>} (or {@code gaussian mean= stdDev=}, {@code constant values=}) and {@code <entity quantity="10"
     * maxTrials="100" baseNum="0">} holding one {@code <robot>}, {@code <box>} or {@code <cylinder>} whose name is the
     * base of each one's ({@code fb} makes {@code fb0}, {@code fb1}, ...).
     */
    public static final class DistributeXml extends FileElement {
        public MethodXml position;
        public MethodXml orientation;
        public EntityXml entity;
    }

    /** One way of drawing a distribution's positions or headings; the attributes its method reads. */
    public static final class MethodXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public String method;
        @JacksonXmlProperty(isAttribute = true)
        public String min;
        @JacksonXmlProperty(isAttribute = true)
        public String max;
        @JacksonXmlProperty(isAttribute = true)
        public String mean;
        @JacksonXmlProperty(isAttribute = true)
        public String stdDev;
        @JacksonXmlProperty(isAttribute = true)
        public String values;
        @JacksonXmlProperty(isAttribute = true)
        public String center;
        @JacksonXmlProperty(isAttribute = true)
        public String distances;
        @JacksonXmlProperty(isAttribute = true)
        public String layout;
    }

    /** A distribution's entities: how many, the tries each may take, and the one template they are made from. */
    public static final class EntityXml extends FileElement {
        @JacksonXmlProperty(isAttribute = true)
        public Integer quantity;
        @JacksonXmlProperty(isAttribute = true)
        public Integer maxTrials;
        @JacksonXmlProperty(isAttribute = true)
        public Integer baseNum;
        public RobotXml robot;
        public BoxXml box;
        public CylinderXml cylinder;
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
