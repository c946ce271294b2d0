"""What an agent observes and does, as Gymnasium spaces, and the batch's arrays as observations."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from gymnasium import spaces

from robosim.rl.host import Batch, Welcome

#: The bounds of a message's numbers (the link carries any finite float32; the declared space is this).
MESSAGE_BOUND = 1.0


@dataclass(frozen=True)
class Layout:
    """Which parts an observation has (``sonar`` and ``contact`` always; ``pose`` and ``messages`` if asked; with
    ``sensors=True``, one part per sensor of the robots' environment file, by its name), and each agent's spaces:
    its sonars (mm, 0 to its farthest range), contact (0 or 1), pose (x, y mm within the arena, heading 0 to 360
    degrees), the last message heard from each robot (zeros if none), each of its sensors (a box of its count of
    values within its range, as the sensor's description in RoboSim's registry says: ``scripts/describe.sh
    SENSOR``); its action: linear velocity (mm/s) and rotational velocity (deg/s) within its type's limits, then its
    message's numbers (-1 to 1), then, with ``actuators=True``, its devices' fields (``Welcome.actuators``)."""

    welcome: Welcome
    pose: bool

    @cached_property
    def sensor_blocks(self) -> dict[str, tuple[int, int]]:
        """Each sensor name's block of ``Batch.readings``' columns, (start, width): where the host's welcome puts it,
        as wide as the most values a robot's sensor of that name gives."""
        blocks: dict[str, tuple[int, int]] = {}
        for own in self.welcome.sensors:
            for s in own:
                start, width = blocks.get(s["name"], (int(s["offset"]), 0))
                blocks[s["name"]] = (start, max(width, int(s["count"])))
        return blocks

    def observation_space(self, robot: int) -> spaces.Dict:
        w = self.welcome
        parts: dict[str, spaces.Space] = {
            "sonar": spaces.Box(0.0, w.sonar_max_mm[robot], (len(w.sonar_angles_deg[robot]),), np.float32),
            "contact": spaces.Box(0.0, 1.0, (1,), np.float32),
        }
        if self.pose:
            x0, y0, x1, y1 = w.arena_mm
            parts["pose"] = spaces.Box(np.array([x0, y0, 0.0], np.float32), np.array([x1, y1, 360.0], np.float32),
                                       dtype=np.float32)
        if w.message_size:
            parts["messages"] = spaces.Box(-np.inf, np.inf, (len(w.robots), w.message_size), np.float32)
        for s in w.sensors[robot]:
            parts[s["name"]] = spaces.Box(np.asarray(s["low"], np.float32), np.asarray(s["high"], np.float32),
                                          (int(s["count"]),), np.float32)
        return spaces.Dict(parts)

    def action_space(self, robot: int) -> spaces.Box:
        """Its velocities within its type's limits, its message's numbers, then (``actuators=True``) its devices'
        fields, each within its device's bounds (0 to 0 where another robot's device lies)."""
        w = self.welcome
        high = np.array([w.max_speed_mm_s[robot], w.max_turn_deg_s[robot]] + [MESSAGE_BOUND] * w.message_size
                        + [0.0] * (w.action_fields - 2 - w.message_size), np.float32)
        low = -high
        for d in w.actuators[robot]:
            start, count = int(d["offset"]), int(d["count"])
            low[start:start + count] = d["low"]
            high[start:start + count] = d["high"]
        return spaces.Box(low, high, dtype=np.float32)

    def observations(self, batch: Batch) -> dict[str, np.ndarray]:
        """The batch's observations, part by part, each (K, N, ...): views where they can be, one copy for contact
        (as float32); a robot with fewer sonars than the most has zeros beyond its own."""
        out = {"sonar": batch.sonar, "contact": batch.contact[..., None].astype(np.float32)}
        if self.pose:
            out["pose"] = batch.pose
        if batch.messages is not None:
            out["messages"] = batch.messages
        if batch.readings is not None:
            for name, (start, width) in self.sensor_blocks.items():
                out[name] = batch.readings[:, :, start:start + width]
        return out

    def agent_observation(self, parts: dict[str, np.ndarray], world: int, robot: int) -> dict[str, np.ndarray]:
        """Robot ``robot`` of world ``world``'s observation: its own arrays (copies, which the next step leaves): its
        own sonars and its own sensors, each as many values as it gives."""
        counts = {"sonar": len(self.welcome.sonar_angles_deg[robot])}
        counts.update({s["name"]: int(s["count"]) for s in self.welcome.sensors[robot]})
        sensors = {s["name"] for s in self.welcome.sensors[robot]}
        blocks = self.sensor_blocks
        return {name: (a[world, robot, :counts[name]] if name in counts else a[world, robot]).copy()
                for name, a in parts.items() if name not in blocks or name in sensors}
