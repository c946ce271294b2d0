"""A RoboSim run as an MCAP file of ROS 2 messages: the bridge's topics (``robosim.ros2.messages``), each message
in ROS 2 CDR under a ``ros2msg`` schema (the type's definition with its dependencies, as ``ros2 bag record`` writes
it), logged at its simulated time, so that ``ros2 bag play``, Foxglove, Lichtblick and PlotJuggler open it."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from mcap.writer import Writer

from robosim.ros2.messages import STORE, Messages, Topic


class Recorder:
    """Writes the messages of a world's steps into a new MCAP file ``path`` (an existing file is refused)."""

    def __init__(self, path: str | os.PathLike[str], messages: Messages) -> None:
        self.path = Path(path)
        self._messages = messages
        try:
            self._file = open(self.path, "xb")  # noqa: SIM115 (closed by close())
        except FileExistsError:
            raise ValueError(f"{self.path}: exists already; give another MCAP file") from None
        except OSError as e:
            raise ValueError(f"{self.path}: cannot be written ({e.strerror})") from None
        self._writer = Writer(self._file)
        self._writer.start(profile="ros2", library="robosim")
        self._schemas: dict[str, int] = {}
        self._channels: dict[str, int] = {}
        self._sequence = 0
        self.written = 0

    def _channel(self, topic: Topic) -> int:
        channel = self._channels.get(topic.name)
        if channel is None:
            schema = self._schemas.get(topic.type)
            if schema is None:
                definition = STORE.generate_msgdef(topic.type, ros_version=2)[0]
                schema = self._writer.register_schema(topic.type, "ros2msg", definition.encode())
                self._schemas[topic.type] = schema
            channel = self._writer.register_channel(topic.name, "cdr", schema)  # (no QoS: a player's defaults)
            self._channels[topic.name] = channel
        return channel

    def write(self, step: int, messages: list[tuple[Topic, bytearray]]) -> None:
        """The messages of the state after ``step`` steps, logged at that simulated time."""
        when = step * self._messages.step_ms * 1_000_000
        for topic, data in messages:
            self._sequence += 1
            self._writer.add_message(self._channel(topic), log_time=when, data=data, publish_time=when,
                                     sequence=self._sequence)
        self.written += len(messages)

    def close(self) -> None:
        if self._file.closed:
            return
        try:
            self._writer.finish()
        finally:
            self._file.close()

    def __enter__(self) -> Recorder:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()
