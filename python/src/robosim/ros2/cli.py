"""The command line of ``python -m robosim.ros2``: ``bridge``, ``router`` and ``export``."""

from __future__ import annotations

import argparse
import logging
import signal
import struct
import sys
import time
from typing import Any, BinaryIO

from robosim.frames import MAX_FRAME, LinkError, unpack
from robosim.hostprocess import HostError

LOG = logging.getLogger("robosim.ros2")
DEFAULT_ROUTER_LISTEN = "tcp/127.0.0.1:7447"


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python -m robosim.ros2", description="RoboSim and ROS 2 over Zenoh, as "
                                     "rmw_zenoh speaks it (python/README.md, \"From ROS 2\").")
    verbs = parser.add_subparsers(dest="verb", required=True, metavar="bridge|router|export")
    bridge = verbs.add_parser("bridge", help="run a world whose control=\"ros2\" robots ROS 2 nodes drive",
                              description="Runs WORLD in a RoboSim JVM; its robots with control=\"ros2\" are driven "
                              "by their cmd_vel topics, and every topic of robosim.ros2.messages is published, as a "
                              "ROS 2 node /robosim on rmw_zenoh would. Ends after --steps, or at SIGTERM or Ctrl-C.")
    bridge.add_argument("world", metavar="WORLD", help="the environment file")
    bridge.add_argument("--domain", type=int, default=None, help="the ROS domain (default: $ROS_DOMAIN_ID, else 0)")
    bridge.add_argument("--mode", choices=("peer", "client"), default="peer",
                        help="the Zenoh session's mode (default: peer, as rmw_zenoh's nodes)")
    bridge.add_argument("--connect", action="append", metavar="ENDPOINT",
                        help="a Zenoh router to connect to (repeatable; default: tcp/localhost:7447, rmw_zenoh's)")
    bridge.add_argument("--listen", action="append", metavar="ENDPOINT",
                        help="where other peers may connect (default: tcp/localhost:0, an ephemeral loopback port)")
    pace = bridge.add_mutually_exclusive_group()
    pace.add_argument("--real-time-factor", type=float, default=1.0, metavar="F",
                      help="simulated seconds per wall-clock second (default 1; 0: as fast as it goes)")
    pace.add_argument("--lockstep", action="store_true",
                      help="step only when every driven robot has had a cmd_vel since the last /clock")
    bridge.add_argument("--command-timeout", type=float, default=0.5, metavar="S",
                        help="a robot whose newest cmd_vel is older than S simulated seconds stands still "
                        "(default 0.5)")
    bridge.add_argument("--steps", type=int, default=None, help="end after N steps (default: run until stopped)")
    bridge.add_argument("--mcap", metavar="OUT.mcap", help="also write every message into a new MCAP file")
    bridge.add_argument("--pose-log", metavar="FILE.csv", help="write every step's poses into a new file (the "
                        "CSV of headless.sh --pose-log)")
    bridge.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                        help="a parameter of the world (repeatable)")
    bridge.add_argument("--seed", type=int, default=None, help="the run's seed (default: the file's)")
    bridge.add_argument("--map-resolution", type=float, default=0.05, metavar="M",
                        help="the /map's cell size, m (default 0.05)")
    bridge.add_argument("--no-map-transform", action="store_true",
                        help="publish no map -> NAME/odom: a node of yours localizes the robots (AMCL, slam_toolbox)")
    router = verbs.add_parser("router", help="a Zenoh router for the bridge and ROS 2 nodes (as rmw_zenohd)",
                              description="Runs a Zenoh router until SIGTERM or Ctrl-C. Zenoh has no authentication "
                              "here: listen beyond loopback only on a network you trust.")
    router.add_argument("--listen", action="append", metavar="ENDPOINT",
                        help=f"where nodes connect (repeatable; default: {DEFAULT_ROUTER_LISTEN})")
    export = verbs.add_parser("export", help="write frames read from stdin into an MCAP file (record-tool.sh export)",
                              description="Reads the bridge's frames (a 4-byte big-endian length, then one "
                              "MessagePack value: the world, then steps) from stdin, as record-tool.sh export sends "
                              "a recording's, and writes their messages into a new MCAP file.")
    export.add_argument("--mcap", metavar="OUT.mcap", required=True, help="the MCAP file to write (a new file)")
    export.add_argument("--map-resolution", type=float, default=0.05, metavar="M",
                        help="the /map's cell size, m (default 0.05)")
    return parser


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(asctime)s %(name)s %(levelname)s %(message)s",
                        stream=sys.stderr)
    try:
        if args.verb == "router":
            return _router(args)
        if args.verb == "export":
            return _export(args)
        return _bridge(args)
    except ValueError as e:
        print(f"robosim.ros2: {e}", file=sys.stderr)
        return 2
    except HostError as e:
        print(f"robosim.ros2: {e}", file=sys.stderr)
        return 1


def _stop_on_signals(stop: Any) -> None:
    for kind in (signal.SIGTERM, signal.SIGINT):
        signal.signal(kind, lambda *_: stop())


def _bridge(args: argparse.Namespace) -> int:
    from robosim.ros2.bridge import DEFAULT_ROUTER, Bridge, Options, domain_from_environment

    params = []
    for p in args.param:
        name, equals, value = p.partition("=")
        if not equals or not name:
            raise ValueError(f"--param takes NAME=VALUE, got {p!r:.80}")
        params.append((name, value))
    if args.steps is not None and args.steps < 1:
        raise ValueError(f"--steps is 1 or more, got {args.steps}")
    options = Options(domain=domain_from_environment() if args.domain is None else args.domain, mode=args.mode,
                      connect=tuple(args.connect or [DEFAULT_ROUTER]),
                      listen=tuple(args.listen or ["tcp/localhost:0"]), real_time_factor=args.real_time_factor,
                      lockstep=args.lockstep, command_timeout_s=args.command_timeout, steps=args.steps,
                      mcap=args.mcap, pose_log=args.pose_log, params=tuple(params), seed=args.seed,
                      map_resolution_m=args.map_resolution, map_transform=not args.no_map_transform)
    with Bridge(args.world, options) as bridge:
        _stop_on_signals(bridge.stop)
        steps = bridge.run()
        LOG.info("the bridge ends after %d steps (%.1f steps/s after the first)", steps, bridge.rate)
    return 0


def _router(args: argparse.Namespace) -> int:
    import zenoh

    from robosim.ros2.bridge import session_config

    listen = args.listen or [DEFAULT_ROUTER_LISTEN]
    stopped = []
    _stop_on_signals(lambda: stopped.append(True))  # (a handler that takes no lock)
    with zenoh.open(session_config("router", [], listen)) as session:
        LOG.info("Zenoh router %s listening on %s", session.info.zid(), ", ".join(listen))
        print("zenoh router listening on " + ", ".join(listen), flush=True)
        while not stopped:
            time.sleep(0.5)
    return 0


def _read_frame(stream: BinaryIO) -> Any:
    head = stream.read(4)
    if not head:
        return None
    if len(head) != 4:
        raise LinkError("the frames stop inside a frame's length")
    (length,) = struct.unpack(">I", head)
    if not 1 <= length <= MAX_FRAME:
        raise LinkError(f"a frame of {length} bytes announced (1 to {MAX_FRAME})")
    body = stream.read(length)
    if len(body) != length:
        raise LinkError("the frames stop inside a frame")
    return unpack(body)


def _export(args: argparse.Namespace) -> int:
    from robosim.ros2.messages import Messages
    from robosim.ros2.recorder import Recorder

    stream = sys.stdin.buffer
    try:
        world = _read_frame(stream)
        if not isinstance(world, dict):
            raise LinkError("the first frame is not a world")
        messages = Messages(world, sensed=[r["name"] for r in world["robots"]], map_resolution_m=args.map_resolution)
        steps = 0
        with Recorder(args.mcap, messages) as recorder:
            frame = _read_frame(stream)
            while frame is not None:
                batch = (messages.latched(frame["poses"]) if steps == 0 else []) + messages.step(frame)
                recorder.write(int(frame["step"]), batch)
                steps += 1
                frame = _read_frame(stream)
        LOG.info("%s: %d steps, %d messages", args.mcap, steps, recorder.written)
        return 0
    except (LinkError, KeyError, TypeError) as e:
        print(f"robosim.ros2 export: the frames on stdin are not the bridge's: {e}", file=sys.stderr)
        return 1
