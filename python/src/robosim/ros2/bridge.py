"""The ROS 2 bridge: a RoboSim world whose robots with ``control="ros2"`` are driven by ROS 2 topics, published and
subscribed over Zenoh as ``rmw_zenoh`` does it (``robosim.ros2.graph``), so that ROS 2 nodes on ``rmw_zenoh`` see one
node, ``/robosim``, with the world's topics (``robosim.ros2.messages``).

The world runs in a RoboSim JVM (the simulation host, in one JVM: the same steps as any other layout) driven over the
simulation link's ``drive`` call: each step, every driven robot's command (its newest ``cmd_vel``), one step, then
the step's frame, turned into messages and published.

Threads: the caller of ``run`` owns time (it alone steps the world, publishes and writes the MCAP file); Zenoh's own
threads call ``_heard`` with each ``cmd_vel`` sample, which only checks it and keeps it as the robot's newest
command, under ``_lock`` for a few assignments; a signal's handler only sets ``_stopping``."""

from __future__ import annotations

import functools
import logging
import math
import os
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import zenoh
import zenoh.ext

from robosim.ros2.graph import RMW_ZENOH_VERSION, TRANSIENT_LOCAL, Attachment, Node, gid, topic_keyexpr
from robosim.ros2.messages import STORE, TWIST, Messages, Topic
from robosim.ros2.recorder import Recorder
from robosim.testing import Simulation, SimulationHost

LOG = logging.getLogger("robosim.ros2")

#: A ``geometry_msgs/msg/Twist`` in CDR: the 4-byte header and six float64s.
TWIST_BYTES = 4 + 6 * 8
#: The most a ``geometry_msgs/msg/TwistStamped`` on ``cmd_vel`` may be, bytes (its frame's name is free text).
TWIST_STAMPED_MAX_BYTES = 1024
#: The router a node of rmw_zenoh connects to by default.
DEFAULT_ROUTER = "tcp/localhost:7447"


def session_config(mode: str, connect: list[str], listen: list[str]) -> zenoh.Config:
    """A Zenoh session's configuration as rmw_zenoh's default session's: ``mode`` (``peer``, its default;
    ``client``; ``router``, to be the router itself), the routers or peers to ``connect`` to, the endpoints to
    ``listen`` on, multicast scouting off, timestamps on (the latched topics' cache needs them)."""
    if mode not in ("peer", "client", "router"):
        raise ValueError(f"a Zenoh mode is peer, client or router, got {mode!r}")
    config = zenoh.Config()
    config.insert_json5("mode", f'"{mode}"')
    config.insert_json5("connect/endpoints", _json_list(connect))
    config.insert_json5("listen/endpoints", _json_list(listen))
    config.insert_json5("scouting/multicast/enabled", "false")
    config.insert_json5("timestamping/enabled", "true")
    if mode != "router":  # (a peer needs no router to start, and tries it again until it answers, as rmw_zenoh's)
        config.insert_json5("connect/timeout_ms", "-1")
        config.insert_json5("connect/exit_on_failure", "false")
    return config


def _json_list(endpoints: list[str]) -> str:
    for e in endpoints:
        if not isinstance(e, str) or '"' in e or "\\" in e or not e:
            raise ValueError(f"not a Zenoh endpoint: {e!r:.80}")
    return "[" + ", ".join(f'"{e}"' for e in endpoints) + "]"


@dataclass
class _Command:
    """A driven robot's newest command: m/s and rad/s within its type's limits, when it came (the steps done then),
    and what was refused, by kind."""

    top_speed: float
    top_turn: float
    ahead: float = 0.0
    turn: float = 0.0
    step: int = -1
    refused: dict[str, int] = field(default_factory=dict)
    gone: bool = False


@dataclass(frozen=True)
class Options:
    """How the bridge runs: the ROS domain, the Zenoh session, the pace, how long a command holds, the run's length,
    a live MCAP file, a pose log, the world's parameters and seed, the map's cell size, whether it publishes
    ``map -> NAME/odom``."""

    domain: int = 0
    mode: str = "peer"
    connect: tuple[str, ...] = (DEFAULT_ROUTER,)
    listen: tuple[str, ...] = ("tcp/localhost:0",)
    real_time_factor: float = 1.0
    lockstep: bool = False
    command_timeout_s: float = 0.5
    steps: int | None = None
    mcap: str | None = None
    pose_log: str | None = None
    params: tuple[tuple[str, str], ...] = ()
    seed: int | None = None
    map_resolution_m: float = 0.05
    map_transform: bool = True
    node_name: str = "robosim"


def domain_from_environment() -> int:
    """``ROS_DOMAIN_ID`` (0 to 232, as ROS 2 takes it), or 0 when unset; a ValueError naming a bad one."""
    raw = os.environ.get("ROS_DOMAIN_ID", "").strip()
    if not raw:
        return 0
    if not raw.isdigit() or int(raw) > 232:
        raise ValueError(f"ROS_DOMAIN_ID is a whole number from 0 to 232, got {raw!r:.40}")
    return int(raw)


#: The world's step timeout, s: a day. A driven robot asks for its next step only once the bridge gives its command,
#: and the Environment counts the time from the last step's end, so it must wait as long as the bridge may (waiting
#: in lock-step for a node, stopped in a debugger, paused at a slow pace).
STEP_WAIT_S = 86_400.0
#: The least time between two lines of one kind about one robot (or the router), s: a flood is said, not echoed.
SAY_EVERY_S = 10.0
#: The most a sample may be that the bridge's session takes, bytes (it hears only commands; Zenoh's default is 1 GiB).
MAX_RECEIVED_BYTES = 65_536


class Bridge:
    """A world's simulation and its ROS 2 node. ``run()`` steps it until ``options.steps`` (or forever, until
    ``stop()``); ``close()`` ends both."""

    def __init__(self, world: str | os.PathLike[str], options: Options, host: SimulationHost | None = None) -> None:
        if not (options.real_time_factor >= 0 and math.isfinite(options.real_time_factor)):
            raise ValueError(f"a real-time factor is 0 (as fast as it goes) or more, got {options.real_time_factor}")
        if not (0 <= options.domain <= 232):
            raise ValueError(f"a ROS domain is 0 to 232, got {options.domain}")
        if not options.command_timeout_s > 0:
            raise ValueError(f"a command's timeout is a positive number of seconds, got {options.command_timeout_s}")
        self.options = options
        builder = Simulation.of(Path(world))
        for name, value in options.params:
            builder.param(name, value)
        if options.seed is not None:
            builder.seed(options.seed)
        if options.pose_log is not None:
            builder.pose_log(options.pose_log)
        if host is not None:
            builder.host(host)
        builder.step_timeout(STEP_WAIT_S)
        builder.history(False)  # (each step's messages reach the nodes: none kept, a long run does not grow with them)
        self.simulation = builder.start()
        self._stopping = False
        self._lock = threading.Lock()
        #: When a line of each kind about each robot (or the router) was last said, monotonic seconds.
        self._said: dict[tuple[str, str], float] = {}
        self._fresh = threading.Condition(self._lock)
        self.session: zenoh.Session | None = None
        self.recorder: Recorder | None = None
        self.steps = 0
        #: The seconds ``run`` took after the first step, and its steps a second.
        self.seconds = 0.0
        self.rate = 0.0
        try:
            self.messages = Messages(self.simulation.world(), map_resolution_m=options.map_resolution_m,
                                     map_transform=options.map_transform)
            driven = self.messages.driven()
            if not driven:
                raise ValueError(f"{world}: no robot is driven by ROS 2 (give one control=\"ros2\")")
            limits = {r["name"]: r for r in self.simulation.world()["robots"]}
            self.commands = {name: _Command(float(limits[name]["max_speed_mm_s"]) / 1000,
                                            math.radians(float(limits[name]["max_turn_deg_s"]))) for name in driven}
            self.step_s = self.messages.step_ms / 1000
            self._hold_steps = max(1, round(options.command_timeout_s / self.step_s))
            if options.mcap is not None:
                self.recorder = Recorder(options.mcap, self.messages)
            self._open(options)
        except BaseException:
            self.close()
            raise

    # ---- the Zenoh side --------------------------------------------------------------------------------------

    def _open(self, options: Options) -> None:
        config = session_config(options.mode, list(options.connect), list(options.listen))
        config.insert_json5("transport/link/rx/max_message_size", str(MAX_RECEIVED_BYTES))
        self.session = zenoh.open(config)
        self._events = self.session.info.declare_transport_events_listener(self._transport_event, history=True)
        zid = str(self.session.info.zid())
        self.node = Node(options.domain, zid, 0, options.node_name)
        self._tokens = [self.session.liveliness().declare_token(self.node.token())]
        self._publishers: dict[str, tuple[Any, Attachment]] = {}
        self._subscribers = []
        for entity, topic in enumerate(self.messages.topics(), start=1):
            type_hash = STORE.hash_rihs01(topic.type)
            key = topic_keyexpr(options.domain, topic.name, topic.type, type_hash)
            token = self.node.endpoint_token(entity, "MP" if topic.out else "MS", topic.name, topic.type, type_hash,
                                             topic.qos)
            if topic.out:
                if topic.qos.durability == TRANSIENT_LOCAL:
                    publisher = zenoh.ext.declare_advanced_publisher(
                        self.session, key, cache=zenoh.ext.CacheConfig(max_samples=topic.qos.depth),
                        publisher_detection=True,
                        sample_miss_detection=zenoh.ext.MissDetectionConfig(sporadic_heartbeat=0.5))
                elif topic is self.messages.clock:  # (a node in lock-step answers each: none is dropped)
                    publisher = self.session.declare_publisher(key, congestion_control=zenoh.CongestionControl.BLOCK)
                else:
                    publisher = self.session.declare_publisher(key)
                self._publishers[topic.name] = (publisher, Attachment(gid(token)))
            else:
                robot = topic.name.split("/")[1]
                self._subscribers.append(self.session.declare_subscriber(key, self._listener(robot, topic.type)))
            self._tokens.append(self.session.liveliness().declare_token(token))
        LOG.info("ROS 2 node /%s on domain %d (%s mode, %s; rmw_zenoh %s's conventions): %d topics, driving %s",
                 options.node_name, options.domain, options.mode, ", ".join(options.connect) or "no router",
                 RMW_ZENOH_VERSION, len({t.name for t in self.messages.topics()}), ", ".join(self.commands))

    def _transport_event(self, event: Any) -> None:
        if "router" not in str(event.transport.whatami).lower():
            return
        if "put" in str(event.kind).lower():
            if self._due("router", "connected"):
                LOG.info("connected to the Zenoh router %s", event.transport.zid)
        elif self._due("router", "gone"):
            LOG.warning("the Zenoh router %s went away: the world goes on, publishing to whoever is still "
                        "connected, and the session connects again when a router is back", event.transport.zid)

    def _due(self, who: str, kind: str) -> bool:
        """Whether a line of ``kind`` about ``who`` may be said now (none in the last ``SAY_EVERY_S``); if so, it is."""
        now = time.monotonic()
        with self._lock:
            last = self._said.get((who, kind))
            if last is not None and now - last < SAY_EVERY_S:
                return False
            self._said[(who, kind)] = now
            return True

    def _listener(self, robot: str, kind: str) -> Callable[[Any], None]:
        def heard(sample: Any) -> None:
            try:
                size = len(sample.payload)
                if size > TWIST_STAMPED_MAX_BYTES:  # (measured before a copy is made)
                    self._refuse(robot, "size", f"a cmd_vel of {size} bytes, beyond any command's")
                    return
                self._heard(robot, kind, sample.payload.to_bytes())
            except Exception as e:  # (Zenoh's thread must not die of one sample)
                self._refuse(robot, "fault", f"a cmd_vel the bridge could not take: {type(e).__name__}")
        return heard

    def _heard(self, robot: str, kind: str, payload: bytes) -> None:
        """A ``cmd_vel`` of ``kind`` (``Twist``, or ``TwistStamped`` as Nav2 may send) checked before it is decoded:
        its size, its encoding, its values finite; then the robot's newest command, held to its type's limits."""
        if kind == TWIST:
            fits = len(payload) == TWIST_BYTES
            shape = f"a geometry_msgs/msg/Twist in CDR ({TWIST_BYTES} bytes)"
        else:
            fits = TWIST_BYTES < len(payload) <= TWIST_STAMPED_MAX_BYTES
            shape = f"a geometry_msgs/msg/TwistStamped in CDR (at most {TWIST_STAMPED_MAX_BYTES} bytes)"
        if not fits or payload[:2] not in (b"\x00\x01", b"\x00\x00"):
            self._refuse(robot, "size", f"a cmd_vel of {len(payload)} bytes, not {shape}")
            return
        message = STORE.deserialize_cdr(payload, kind)
        twist = message if kind == TWIST else message.twist
        values = (twist.linear.x, twist.linear.y, twist.linear.z, twist.angular.x, twist.angular.y, twist.angular.z)
        if not all(math.isfinite(v) for v in values):
            self._refuse(robot, "nan", "a cmd_vel with a value that is not a finite number")
            return
        with self._fresh:
            command = self.commands[robot]
            if command.gone:
                return
            command.ahead = max(-command.top_speed, min(command.top_speed, twist.linear.x))
            command.turn = max(-command.top_turn, min(command.top_turn, twist.angular.z))
            command.step = self.steps
            self._fresh.notify_all()

    def _refuse(self, robot: str, kind: str, why: str) -> None:
        """Counts a refusal; says it, with the count so far, if nothing of its kind was said of the robot in the last
        ``SAY_EVERY_S`` (a flood is a line every 10 s, whatever its rate); the end of the run says every count."""
        with self._lock:
            count = self.commands[robot].refused.get(kind, 0) + 1
            self.commands[robot].refused[kind] = count
        if self._due(robot, kind):
            LOG.warning("%s: %s: refused (%d so far); the robot keeps its last command", robot, why, count)

    def _publish(self, step: int, messages: list[tuple[Topic, bytearray]], record: bool = True) -> None:
        now = time.time_ns()  # (a step's messages are sent together: one source time)
        publishers = self._publishers
        for topic, data in messages:
            publisher, attachment = publishers[topic.name]
            publisher.put(data, attachment=attachment.next(now))
        if record and self.recorder is not None:
            self.recorder.write(step, messages)

    def _publish_frame(self, frame: dict[str, Any]) -> list[tuple[Topic, bytearray]]:
        """Publishes a step's messages; them."""
        messages = self.messages.step(frame)
        self._publish(int(frame["step"]), messages)
        return messages

    # ---- time ------------------------------------------------------------------------------------------------

    def _command_of(self, robot: str) -> list[float]:
        """The robot's command for the next step, mm/s and deg/s: its newest, or standing still once it is older
        than the command timeout (in simulated time: a node that stops publishing stops its robot)."""
        c = self.commands[robot]
        if c.step < 0 or self.steps - c.step >= self._hold_steps:
            return [0.0, 0.0]
        return [c.ahead * 1000, math.degrees(c.turn)]

    def _await_commands(self, last: list[tuple[Topic, bytearray]]) -> bool:
        """Lock-step: waits until every driven robot in the world has a command given since the last step's clock;
        False if stopped first. While a robot has never had a command, it sends the last step's ``/clock`` and that
        robot's own topics again every second (not ``/tf``, nor messages received: they would count twice), so that
        a node that starts after the bridge hears the step it is to answer; once every robot's node has answered,
        never again (a slow node would answer twice). Every 10 s it says whom it waits for."""
        said = waited = time.monotonic()
        while True:
            with self._fresh:
                late = [r for r, c in self.commands.items() if not c.gone and c.step < self.steps]
                if not late:
                    return True
                if self._stopping:
                    return False
                self._fresh.wait(0.2)
                silent = {f"/{r}/" for r, c in self.commands.items() if not c.gone and c.step < 0}
            if silent and time.monotonic() - waited >= 1:
                waited = time.monotonic()
                self._publish(self.steps, [(t, b) for t, b in last if t is self.messages.clock or (
                    t.name[:t.name.rfind("/") + 1] in silent and not t.name.endswith("/received"))], record=False)
            if time.monotonic() - said >= 10:
                said = time.monotonic()
                LOG.info("lock-step: step %d waits for a cmd_vel of %s", self.steps, ", ".join(late))

    def stop(self) -> None:
        """Ends ``run`` at the next step: any thread, or a signal's handler (it takes no lock, so a signal that comes
        while the loop holds one cannot wait for it)."""
        self._stopping = True

    def _pace(self, due: float) -> bool:
        """Waits until ``due`` (monotonic seconds), a tenth of a second at a time; False if stopped first."""
        while not self._stopping:
            left = due - time.monotonic()
            if left <= 0:
                return True
            time.sleep(min(left, 0.1))
        return False

    def _left(self, frame: dict[str, Any]) -> None:
        """Driven robots without senses in ``frame``: those that have left the world said once, and no longer
        commanded or waited for; the others (their senses late, on a machine too loaded) said."""
        for robot, command in self.commands.items():
            if not command.gone and robot not in frame["robots"]:
                why = self.simulation.ended(robot)
                if why is not None:
                    with self._lock:
                        command.gone = True
                    LOG.warning("%s has left the world (%s): it is no longer driven", robot, why)
                elif self._due(robot, "late"):
                    LOG.warning("%s: its senses did not come with step %d: its topics skip the step", robot,
                                int(frame["step"]))

    def run(self) -> int:
        """Steps the world until its steps are done, every driven robot has left it, or ``stop()``; the steps run.
        A robot's control failing (a driven robot's cannot) is a ControlFailed."""
        first = self.simulation.drive({})  # (step 0: every robot still, so its senses exist before a node answers)
        self.steps = int(first["step"])
        last = self.messages.step(first)
        self._publish(self.steps, self.messages.latched(first["poses"]) + last)
        start = time.monotonic()
        begun = self.steps
        rate = self.options.real_time_factor
        pipelined = rate == 0 and not self.options.lockstep
        pending: dict[str, Any] | None = None  # (as fast as it goes: a step turned into messages while the next runs)
        while not self._stopping and (self.options.steps is None or self.steps < self.options.steps):
            if self.options.lockstep:
                if not self._await_commands(last):
                    break
            elif rate > 0 and not self._pace(start + (self.steps - begun + 1) * self.step_s / rate):
                break
            with self._lock:
                commands = {r: self._command_of(r) for r, c in self.commands.items() if not c.gone}
            frame = self.simulation.drive(commands, meanwhile=None if pending is None
                                          else functools.partial(self._publish_frame, pending))
            pending = None
            with self._lock:
                self.steps = int(frame["step"])
            if pipelined:
                pending = frame
            else:  # (paced or in lock-step, a node hears a step as soon as it is done)
                last = self._publish_frame(frame)
            if len(frame["robots"]) < len(commands):
                self._left(frame)
                if all(c.gone for c in self.commands.values()):
                    LOG.info("every driven robot has left the world: the bridge ends")
                    break
        if pending is not None:
            self._publish_frame(pending)
        for robot, command in self.commands.items():  # (every refusal counted, each said at the end)
            if command.refused:
                LOG.warning("%s: %d cmd_vel refused in all (%s)", robot, sum(command.refused.values()),
                            ", ".join(f"{kind} {n}" for kind, n in sorted(command.refused.items())))
        self.seconds = time.monotonic() - start
        self.rate = (self.steps - begun) / self.seconds if self.seconds > 0 else 0.0
        return self.steps

    def close(self) -> None:
        """Ends the node (its tokens withdrawn), the MCAP file and the simulation, each whatever the others did."""
        for closing in (self._close_session, self._close_recorder, self._close_simulation):
            try:
                closing()
            except Exception as e:  # (a Ctrl-C reaches the host's JVM too; a session that broke; a full disk)
                LOG.warning("while closing: %s", e)

    def _close_session(self) -> None:
        if self.session is not None:
            session, self.session = self.session, None
            session.close()

    def _close_recorder(self) -> None:
        if self.recorder is not None:
            self.recorder.close()

    def _close_simulation(self) -> None:
        self.simulation.close()

    def __enter__(self) -> Bridge:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
