"""A RoboSim world's steps as ROS 2 messages: which topics a world has, and each step's messages on them, serialized
as ROS 2 CDR by rosbags (its Kilted type store: the message definitions, and the RIHS01 type hashes rmw_zenoh puts in
key expressions). The live bridge and the MCAP files take their messages from here, so both have the same topics.

Frames and units follow REP 103 and REP 105. The topics, their types and what each holds: python/README.md, "From
ROS 2" (``Messages.topics`` is the list)."""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
from rosbags.typesys import Stores, get_typestore
from rosbags.typesys.store import Nodetype

from robosim.ros2.graph import DEFAULT_QOS, LATCHED_QOS, Qos

#: The type store: ROS 2 Kilted's message definitions.
STORE = get_typestore(Stores.ROS2_KILTED)

CLOCK = "rosgraph_msgs/msg/Clock"
TF = "tf2_msgs/msg/TFMessage"
GRID = "nav_msgs/msg/OccupancyGrid"
MARKERS = "visualization_msgs/msg/MarkerArray"
ODOMETRY = "nav_msgs/msg/Odometry"
TWIST = "geometry_msgs/msg/Twist"
TWIST_STAMPED = "geometry_msgs/msg/TwistStamped"
SCAN = "sensor_msgs/msg/LaserScan"
RANGE = "sensor_msgs/msg/Range"
VALUES = "std_msgs/msg/Float64MultiArray"
TEXT = "std_msgs/msg/String"

#: Sensors of these kinds make the scan (the first the robot has).
SCAN_KINDS = ("laser",)
#: A ROS name's token: a letter, then letters, digits and single underscores.
_TOKEN = re.compile(r"[A-Za-z](?:_?[A-Za-z0-9])*_?")
#: A robot's topics of its own, which no sensor of it may be named.
_OWN = ("odom", "cmd_vel", "scan", "received")


@dataclass(frozen=True)
class Topic:
    """A topic: its full name, its type, its QoS, and whether the bridge publishes it (else it subscribes)."""

    name: str
    type: str
    qos: Qos = DEFAULT_QOS
    out: bool = True


def make(typename: str, **fields: Any) -> Any:
    """A message of ``typename`` with ``fields``; every other field zero, empty or a zero message."""
    cls = STORE.types[typename]
    for name, (kind, detail) in STORE.fielddefs[typename][1]:
        if name in fields:
            continue
        if kind == Nodetype.NAME:
            fields[name] = make(detail)
        elif kind == Nodetype.BASE:
            fields[name] = "" if detail[0] == "string" else False if detail[0] == "bool" else 0
        elif kind == Nodetype.ARRAY and detail[0][0] == Nodetype.BASE and detail[0][1][0] != "string":
            fields[name] = np.zeros(detail[1], dtype=_NUMPY[detail[0][1][0]])
        elif kind == Nodetype.ARRAY:
            fields[name] = [make(detail[0][1]) if detail[0][0] == Nodetype.NAME else "" for _ in range(detail[1])]
        elif detail[0][0] == Nodetype.BASE and detail[0][1][0] != "string":
            fields[name] = np.zeros(0, dtype=_NUMPY[detail[0][1][0]])
        else:
            fields[name] = []
    return cls(**fields)


_NUMPY = {"bool": np.bool_, "byte": np.uint8, "char": np.uint8, "int8": np.int8, "uint8": np.uint8,
          "int16": np.int16, "uint16": np.uint16, "int32": np.int32, "uint32": np.uint32, "int64": np.int64,
          "uint64": np.uint64, "float32": np.float32, "float64": np.float64}


def serialize(message: Any, typename: str, size: int | None = None) -> bytearray:
    """``message`` as ROS 2 CDR (little-endian, with its 4-byte header), by rosbags' serializer of its type (what
    ``Typestore.serialize_cdr`` does, its type's serializer looked up once, not once a message); ``size``, its size
    without the header where the caller knows it (a message of fixed size, made again and again)."""
    definition = _DEFINITIONS.get(typename)
    if definition is None:
        definition = _DEFINITIONS[typename] = STORE.get_msgdef(typename)
    data = bytearray(4 + (definition.getsize_cdr(0, message, STORE) if size is None else size))
    data[1] = 1  # (the encapsulation: CDR, little-endian)
    definition.serialize_cdr_le(memoryview(data)[4:], 0, message, STORE)
    return data


def cdr_size(message: Any, typename: str) -> int:
    """``message``'s size in CDR without the 4-byte header."""
    return int(STORE.get_msgdef(typename).getsize_cdr(0, message, STORE))


_DEFINITIONS: dict[str, Any] = {}


def stamp(step: int, step_ms: int) -> Any:
    """The simulated time after ``step`` steps, as ``builtin_interfaces/msg/Time``."""
    ns = step * step_ms * 1_000_000
    return STORE.types["builtin_interfaces/msg/Time"](sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def quaternion(yaw: float) -> Any:
    return STORE.types["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))


def _doubles(raw: bytes) -> list[float]:
    return list(struct.unpack(f"<{len(raw) // 8}d", raw))


class _Robot:
    """One robot's part of the world: its frames, where it started, its topics and how its senses become messages."""

    def __init__(self, spec: dict[str, Any], index: int, sensed: bool) -> None:
        self.name = str(spec["name"])
        if not _TOKEN.fullmatch(self.name):
            raise ValueError(f"robot {self.name!r:.80} cannot be a ROS namespace: a ROS name is a letter, then "
                             f"letters, digits and single underscores (rename it in the world's file)")
        self.index = index
        self.driven = bool(spec.get("driven", False))
        self.sensed = sensed
        self.odom_frame = f"{self.name}/odom"
        self.base_frame = f"{self.name}/base_link"
        self.sonars = [tuple(float(v) for v in s) for s in spec.get("sonars", [])]
        self.rays = [tuple(float(v) for v in r) for r in spec.get("rays", [])]
        self.sensors = [(str(s["name"]), str(s["kind"]), dict(s.get("attributes", {})))
                        for s in spec.get("sensors", [])]
        for name, _, _ in self.sensors if sensed else []:
            if not _TOKEN.fullmatch(name) or name in _OWN:
                raise ValueError(f"robot {self.name}'s sensor {name!r:.80} cannot be a ROS topic of its own: a ROS "
                                 f"name is a letter, then letters, digits and single underscores, and not one of "
                                 f"{', '.join(_OWN)} (rename it in the world's file)")
        self.start: tuple[float, float, float] | None = None
        self.last: tuple[float, float, float] | None = None
        self.odom = Topic(f"/{self.name}/odom", ODOMETRY)
        self.cmd_vel = [Topic(f"/{self.name}/cmd_vel", TWIST, out=False),
                        Topic(f"/{self.name}/cmd_vel", TWIST_STAMPED, out=False)]
        self.scan_source = next((n for n, k, _ in self.sensors if k in SCAN_KINDS), None)
        has_scan = self.scan_source is not None or bool(self.sonars)
        self.scan = Topic(f"/{self.name}/scan", SCAN) if sensed and has_scan else None
        self.sensor_topics: dict[str, Topic] = {}
        if sensed:
            for name, kind, _ in self.sensors:
                if name != self.scan_source:
                    self.sensor_topics[name] = Topic(f"/{self.name}/{name}", RANGE if kind == "proximity" else VALUES)
        self.received = Topic(f"/{self.name}/received", TEXT) if sensed else None
        #: Its odom -> base_link transform in /tf, and its odometry message and size (made at the first step).
        self.transform: Any = None
        self.odometry: Any = None
        self.odometry_size = 0
        #: Each proximity sensor's messages, one a ray, and their size, by the sensor's name (made at its first
        #: reading).
        self.range_messages: dict[str, list[Any]] = {}

    def topics(self) -> list[Topic]:
        out = [self.odom]
        if self.driven:
            out.extend(self.cmd_vel)
        if self.scan is not None:
            out.append(self.scan)
        out.extend(self.sensor_topics.values())
        if self.received is not None:
            out.append(self.received)
        return out


class Messages:
    """The ROS 2 messages of a world's steps (``world``: the bridge's world frame, ``BridgeFrames`` in RoboSim's
    Java), for the robots in ``sensed`` with their senses' topics too (default: the driven ones)."""

    def __init__(self, world: dict[str, Any], sensed: Iterable[str] | None = None,
                 map_resolution_m: float = 0.05, map_transform: bool = True) -> None:
        self.step_ms = int(world["step_ms"])
        self.arena = [float(v) / 1000 for v in world["arena"]]
        self.obstacles = [(str(n), [float(v) / 1000 for v in xy]) for n, xy in world["obstacles"]]
        chosen = None if sensed is None else set(sensed)
        self.robots = [_Robot(r, i, bool(r.get("driven")) if chosen is None else r["name"] in chosen)
                       for i, r in enumerate(world["robots"])]
        self.by_name = {r.name: r for r in self.robots}
        if not map_resolution_m > 0:
            raise ValueError(f"a map's resolution is a positive number of metres, got {map_resolution_m}")
        self.resolution = map_resolution_m
        #: Whether ``map -> NAME/odom`` is published (not where a node of the user's localizes the robots).
        self.map_transform = map_transform
        self.clock = Topic("/clock", CLOCK)
        self.tf = Topic("/tf", TF, Qos(depth=100))
        self.tf_static = Topic("/tf_static", TF, LATCHED_QOS)
        self.map = Topic("/map", GRID, LATCHED_QOS)
        self.markers = Topic("/obstacles", MARKERS, LATCHED_QOS)
        self._covariance = np.zeros(36)
        #: /tf's message and its size, made at the first step.
        self._tf: tuple[Any, int] | None = None

    def topics(self) -> list[Topic]:
        """Every topic, the world's first, then each robot's, in the world's order."""
        out = [self.clock, self.tf, self.tf_static, self.map, self.markers]
        for r in self.robots:
            out.extend(r.topics())
        return out

    def driven(self) -> list[str]:
        return [r.name for r in self.robots if r.driven]

    # ---- what is published once --------------------------------------------------------------------------------

    def latched(self, poses: bytes) -> list[tuple[Topic, bytearray]]:
        """The latched topics' messages, given the robots' start poses (a step frame's ``poses``)."""
        values = _doubles(poses)
        zero = stamp(0, self.step_ms)
        transforms = []
        for r in self.robots:
            x, y, h = values[3 * r.index: 3 * r.index + 3]
            r.start = (x / 1000, y / 1000, math.radians(h))
            if self.map_transform:
                transforms.append(self._transform(zero, "map", r.odom_frame, *r.start))
            for name, kind, _ in r.sensors:
                if kind == "proximity" and name in r.sensor_topics:
                    for k, (rx, ry, angle, _) in enumerate(r.rays):
                        transforms.append(self._transform(zero, r.base_frame, f"{r.name}/{name}_{k}", rx / 1000,
                                                          ry / 1000, math.radians(angle)))
        tf_static = make(TF, transforms=transforms)
        return [(self.tf_static, serialize(tf_static, TF)), (self.map, serialize(self.grid(zero), GRID)),
                (self.markers, serialize(self.outlines(zero), MARKERS))]

    def grid(self, when: Any) -> Any:
        """The obstacles as an occupancy grid over the arena: a cell whose centre lies in an obstacle is 100."""
        min_x, min_y, max_x, max_y = self.arena
        width = max(1, math.ceil((max_x - min_x) / self.resolution - 1e-9))
        height = max(1, math.ceil((max_y - min_y) / self.resolution - 1e-9))
        cells = np.zeros((height, width), dtype=np.int8)
        for _, xy in self.obstacles:
            points = list(zip(xy[0::2], xy[1::2], strict=True))
            for row in range(height):
                y = min_y + (row + 0.5) * self.resolution
                crossings = sorted(x0 + (y - y0) * (x1 - x0) / (y1 - y0)
                                   for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=True)
                                   if (y0 <= y) != (y1 <= y))
                for a, b in zip(crossings[0::2], crossings[1::2], strict=False):
                    first = max(0, math.ceil((a - min_x) / self.resolution - 0.5))
                    last = min(width - 1, math.floor((b - min_x) / self.resolution - 0.5))
                    if first <= last:
                        cells[row, first:last + 1] = 100
        pose = STORE.types["geometry_msgs/msg/Pose"](
            position=STORE.types["geometry_msgs/msg/Point"](x=min_x, y=min_y, z=0.0), orientation=quaternion(0.0))
        info = make("nav_msgs/msg/MapMetaData", map_load_time=when, resolution=self.resolution, width=width,
                    height=height, origin=pose)
        return make(GRID, header=self._header(when, "map"), info=info, data=cells.reshape(-1))

    def outlines(self, when: Any) -> Any:
        """The obstacles' outlines, a closed line strip each, 2 cm wide."""
        point = STORE.types["geometry_msgs/msg/Point"]
        markers = []
        for i, (name, xy) in enumerate(self.obstacles):
            points = [point(x=x, y=y, z=0.0) for x, y in zip(xy[0::2], xy[1::2], strict=True)]
            markers.append(make("visualization_msgs/msg/Marker", header=self._header(when, "map"), ns=name, id=i,
                                type=4, action=0, pose=make("geometry_msgs/msg/Pose", orientation=quaternion(0.0)),
                                scale=make("geometry_msgs/msg/Vector3", x=0.02),
                                color=make("std_msgs/msg/ColorRGBA", r=0.5, g=0.5, b=0.5, a=1.0),
                                points=points + points[:1]))
        return make(MARKERS, markers=markers)

    # ---- what is published every step ------------------------------------------------------------------------

    def step(self, frame: dict[str, Any]) -> list[tuple[Topic, bytearray]]:
        """The messages of one step's frame (``BridgeFrames.step``): the clock, /tf, every robot's odometry, and the
        senses of those with topics for them."""
        step = int(frame["step"])
        values = _doubles(frame["poses"])
        when = stamp(step, self.step_ms)
        out: list[tuple[Topic, bytearray]] = [(self.clock, serialize(STORE.types[CLOCK](clock=when), CLOCK))]
        if self._tf is None:  # (the messages of every step, made once: their frames stay, their numbers change)
            for r in self.robots:
                r.transform = self._transform(when, r.odom_frame, r.base_frame, 0.0, 0.0, 0.0)
                r.odometry = self._odometry(r, when)
                r.odometry_size = cdr_size(r.odometry, ODOMETRY)
            tf = make(TF, transforms=[r.transform for r in self.robots])
            self._tf = (tf, cdr_size(tf, TF))
        seconds = self.step_ms / 1000
        odometry = []
        for r in self.robots:
            x, y, h = values[3 * r.index: 3 * r.index + 3]
            if r.start is None:
                r.start = (x / 1000, y / 1000, math.radians(h))
            here = self._in_odom(r, x / 1000, y / 1000, math.radians(h))
            ahead = turn = 0.0
            if r.last is not None:
                lx, ly, lyaw = r.last
                ahead = ((here[0] - lx) * math.cos(lyaw) + (here[1] - ly) * math.sin(lyaw)) / seconds
                turn = math.remainder(here[2] - lyaw, math.tau) / seconds
            r.last = here
            half = here[2] / 2
            transform = r.transform
            transform.header.stamp = when
            transform.transform.translation.x, transform.transform.translation.y = here[0], here[1]
            transform.transform.rotation.z, transform.transform.rotation.w = math.sin(half), math.cos(half)
            message = r.odometry
            message.header.stamp = when
            pose = message.pose.pose
            pose.position.x, pose.position.y = here[0], here[1]
            pose.orientation.z, pose.orientation.w = math.sin(half), math.cos(half)
            message.twist.twist.linear.x, message.twist.twist.angular.z = ahead, turn
            odometry.append((r.odom, serialize(message, ODOMETRY, r.odometry_size)))
        out.append((self.tf, serialize(self._tf[0], TF, self._tf[1])))
        out.extend(odometry)
        states = frame.get("robots") or {}
        for name, state in states.items():
            r = self.by_name.get(name)
            if r is not None and r.sensed:
                out.extend(self._senses(r, when, state))
        return out

    def _in_odom(self, r: _Robot, x: float, y: float, yaw: float) -> tuple[float, float, float]:
        """A pose in the world as the robot's odometry frame has it (its start pose the origin)."""
        assert r.start is not None
        sx, sy, syaw = r.start
        dx, dy = x - sx, y - sy
        c, s = math.cos(syaw), math.sin(syaw)
        return dx * c + dy * s, -dx * s + dy * c, math.remainder(yaw - syaw, math.tau)

    def _odometry(self, r: _Robot, when: Any) -> Any:
        """A robot's odometry message at the odometry frame's origin, still (``step`` moves it)."""
        types = STORE.types
        pose = types["geometry_msgs/msg/PoseWithCovariance"](
            pose=types["geometry_msgs/msg/Pose"](position=types["geometry_msgs/msg/Point"](x=0.0, y=0.0, z=0.0),
                                                 orientation=quaternion(0.0)), covariance=self._covariance)
        vector = types["geometry_msgs/msg/Vector3"]
        twist = types["geometry_msgs/msg/TwistWithCovariance"](
            twist=types[TWIST](linear=vector(x=0.0, y=0.0, z=0.0), angular=vector(x=0.0, y=0.0, z=0.0)),
            covariance=self._covariance)
        return types[ODOMETRY](header=self._header(when, r.odom_frame), child_frame_id=r.base_frame, pose=pose,
                               twist=twist)

    def _senses(self, r: _Robot, when: Any, state: dict[str, Any]) -> list[tuple[Topic, bytearray]]:
        out: list[tuple[Topic, bytearray]] = []
        readings = state.get("readings") or {}
        if r.scan is not None:
            scan = self._scan(r, when, state, readings)
            if scan is not None:
                out.append((r.scan, serialize(scan, SCAN)))
        ranges = state.get("ranges") or {}
        for name, kind, _ in r.sensors:
            topic = r.sensor_topics.get(name)
            if topic is None or name not in readings:
                continue
            if kind == "proximity" and name in ranges:
                rays = r.range_messages.get(name)
                if rays is None:  # (a message a ray, made once: its frame and bounds stay, its stamp and range change)
                    made = [STORE.types[RANGE](header=self._header(when, f"{r.name}/{name}_{k}"), radiation_type=1,
                                               field_of_view=0.0, min_range=0.0, max_range=reach / 1000, range=0.0,
                                               variance=0.0) for k, (_, _, _, reach) in enumerate(r.rays)]
                    rays = r.range_messages[name] = [(m, cdr_size(m, RANGE)) for m in made]
                for (message, size), metres in zip(rays, _doubles(ranges[name]), strict=False):
                    message.header.stamp = when
                    message.range = metres if metres <= message.max_range else math.inf
                    out.append((topic, serialize(message, RANGE, size)))
            else:
                out.append((topic, serialize(self._values(kind, _doubles(readings[name])), VALUES)))
        if r.received is not None:
            for _, text in state.get("received") or []:
                out.append((r.received, serialize(STORE.types[TEXT](data=str(text)), TEXT)))
        return out

    def _scan(self, r: _Robot, when: Any, state: dict[str, Any], readings: dict[str, bytes]) -> Any:
        if r.scan_source is not None:
            if r.scan_source not in readings:
                return None
            attributes = next(a for n, _, a in r.sensors if n == r.scan_source)
            fov = math.radians(float(attributes.get("fovDeg", 180)))
            step = math.radians(float(attributes.get("resolutionDeg", 1)))
            ranges = np.asarray(_doubles(readings[r.scan_source]), dtype=np.float32) / 1000
            return make(SCAN, header=self._header(when, r.base_frame), angle_min=-fov / 2,
                        angle_max=-fov / 2 + step * max(0, len(ranges) - 1), angle_increment=step,
                        scan_time=self.step_ms / 1000, range_min=0.0,
                        range_max=float(attributes.get("rangeM", 8)), ranges=ranges)
        sonar = _doubles(state.get("sonar") or b"")
        if not sonar or len(sonar) != len(r.sonars):
            return None
        return _sonar_scan(self._header(when, r.base_frame), r.sonars, sonar, self.step_ms / 1000)

    @staticmethod
    def _values(kind: str, values: list[float]) -> Any:
        dim = STORE.types["std_msgs/msg/MultiArrayDimension"](label=kind, size=len(values), stride=len(values))
        layout = STORE.types["std_msgs/msg/MultiArrayLayout"](dim=[dim], data_offset=0)
        return STORE.types[VALUES](layout=layout, data=np.asarray(values, dtype=np.float64))

    @staticmethod
    def _header(when: Any, frame: str) -> Any:
        return STORE.types["std_msgs/msg/Header"](stamp=when, frame_id=frame)

    @staticmethod
    def _transform(when: Any, parent: str, child: str, x: float, y: float, yaw: float) -> Any:
        types = STORE.types
        return types["geometry_msgs/msg/TransformStamped"](
            header=types["std_msgs/msg/Header"](stamp=when, frame_id=parent), child_frame_id=child,
            transform=types["geometry_msgs/msg/Transform"](
                translation=types["geometry_msgs/msg/Vector3"](x=x, y=y, z=0.0), rotation=quaternion(yaw)))


def _sonar_scan(header: Any, sonars: list[tuple[float, ...]], ranges_mm: list[float], seconds: float) -> Any:
    """A sonar ring as a laser scan from the robot's centre: each transducer's beam at its angle, its range from the
    rim plus the transducer's distance from the centre; a ring unevenly spaced is binned at its smallest spacing,
    NaN where no transducer points (REP 117: no reading)."""
    angles = [math.remainder(math.radians(s[2]), math.tau) for s in sonars]
    order = sorted(range(len(angles)), key=lambda i: angles[i])
    first = angles[order[0]]
    gaps = [angles[b] - angles[a] for a, b in zip(order, order[1:], strict=False)]
    increment = min((g for g in gaps if g > 1e-9), default=math.tau)
    bins = int(round((angles[order[-1]] - first) / increment)) + 1
    values = np.full(bins, np.nan, dtype=np.float32)
    for i in order:
        rim = math.hypot(sonars[i][0], sonars[i][1])
        values[int(round((angles[i] - first) / increment))] = (ranges_mm[i] + rim) / 1000
    farthest = max((s[4] + math.hypot(s[0], s[1])) for s in sonars) / 1000
    return make(SCAN, header=header, angle_min=first, angle_max=first + increment * (bins - 1),
                angle_increment=increment, scan_time=seconds, range_min=0.0, range_max=farthest, ranges=values)
