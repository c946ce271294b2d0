"""The robot link's frames: a 4-byte big-endian length (1 to 1 MiB) and one MessagePack value."""

from __future__ import annotations

import socket
import struct
from typing import Any

import msgpack

#: The largest frame either side sends or takes, bytes.
MAX_FRAME = 1 << 20

_LENGTH = struct.Struct(">I")


class LinkError(Exception):
    """The link broke: a frame that is not one, a call refused as malformed, a connection that ended."""


class LinkClosed(LinkError):
    """The simulator closed the link (at the simulation's end it may, instead of answering ``over``)."""


def pack(value: Any) -> bytes:
    """One frame holding ``value`` (floats as float64, texts as MessagePack str)."""
    body: bytes = msgpack.packb(value, use_bin_type=True)
    if not 1 <= len(body) <= MAX_FRAME:
        raise LinkError(f"a frame of {len(body)} bytes (1 to {MAX_FRAME})")
    return _LENGTH.pack(len(body)) + body


def unpack(body: bytes) -> Any:
    """The one value of a frame's body; more than one, or none, is a LinkError."""
    try:
        return msgpack.unpackb(body, raw=False, strict_map_key=True)
    except msgpack.ExtraData as e:
        raise LinkError("a frame holds more than one value") from e
    except (ValueError, msgpack.UnpackException) as e:
        raise LinkError(f"a frame that is not MessagePack: {e}") from e


class Frames:
    """Frames over one connected socket: one ``send`` of a whole frame, reads that stop at the frame's end."""

    def __init__(self, sock: socket.socket) -> None:
        self._sock = sock
        self._in = sock.makefile("rb")

    def send(self, value: Any) -> None:
        self._sock.sendall(pack(value))

    def send_packed(self, frame: bytes) -> None:
        """Sends a frame made already (:func:`pack`)."""
        self._sock.sendall(frame)

    def receive(self) -> Any:
        """The next frame's value; a LinkError when the connection ends or the frame is out of bounds."""
        head = self._read(_LENGTH.size)
        (length,) = _LENGTH.unpack(head)
        if not 1 <= length <= MAX_FRAME:
            raise LinkError(f"a frame of {length} bytes announced (1 to {MAX_FRAME})")
        return unpack(self._read(length))

    def _read(self, n: int) -> bytes:
        data = self._in.read(n)
        if data is None or len(data) < n:
            raise LinkClosed("the simulator closed the link")
        return data


def handshake(host: str, port: int, hello: dict[str, Any], called: str,
              timeout_s: float) -> tuple[Frames, dict[str, Any]]:
    """Connects to a link at ``host``:``port`` and says ``hello`` (its ``link`` and ``version`` say which, ``called``
    names it in an error: ``"robot link"``): the frames and the simulator's welcome, checked as that link's. The
    connection's reads wait as long as they take after it (a call lasts as long as the simulation takes)."""
    sock = socket.create_connection((host, port), timeout=timeout_s)
    try:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        frames = Frames(sock)
        frames.send(hello)
        welcome = frames.receive()
        if not isinstance(welcome, dict):
            raise LinkError(f"{host}:{port}: a welcome that is not a map: {welcome!r:.80}")
        if "error" in welcome:
            raise LinkError(f"{host}:{port}: the simulator refused the link: {welcome['error']}")
        if welcome.get("link") != hello["link"] or welcome.get("version") != hello["version"]:
            raise LinkError(f"{host}:{port}: not a {called} version {hello['version']}'s welcome: {welcome!r:.120}")
        sock.settimeout(None)
        return frames, welcome
    except BaseException:
        sock.close()
        raise
