"""How a ROS 2 node is seen over Zenoh: the conventions of ``rmw_zenoh`` (ROS 2's Zenoh middleware), as its design
document (``docs/design.md`` of ``ros2/rmw_zenoh``) and its source at release 0.6.7 (Kilted; the same on the wire
through 0.12.0, Rolling) lay them down. One place for all of them: the key expression a topic's samples go under, the
liveliness tokens that make a node and its publishers and subscriptions appear in ``ros2 node list`` and ``ros2 topic
list``, the QoS written into a token, the attachment every sample carries, the type names and RIHS01 type hashes.

A sample without the attachment is dropped by rmw_zenoh's subscribers; a token only makes the graph show an entity
(data flows by the key expression alone)."""

from __future__ import annotations

import hashlib
import struct
import time
from dataclasses import dataclass

#: The liveliness tokens' prefix.
ADMIN_SPACE = "@ros2_lv"
#: The version of rmw_zenoh whose conventions these are (README: "From ROS 2").
RMW_ZENOH_VERSION = "0.6.7"

# QoS enumerations as rmw writes them into a token (rmw/types.h); the history is always keep-last.
RELIABLE = 1
TRANSIENT_LOCAL = 1
VOLATILE = 2


@dataclass(frozen=True)
class Qos:
    """A topic's quality of service, as far as a token says it: reliability, durability, history depth."""

    reliability: int = RELIABLE
    durability: int = VOLATILE
    depth: int = 10

    def keyexpr(self) -> str:
        """The QoS part of a token: ``REL:DUR:HIST,DEPTH:DL:LS:LIV,LEASE`` with every field equal to rmw_zenoh's
        default (reliable, volatile, keep last, depth 42, no deadline, lifespan or lease; automatic liveliness)
        written empty."""
        rel = "" if self.reliability == RELIABLE else str(self.reliability)
        dur = "" if self.durability == VOLATILE else str(self.durability)
        depth = "" if self.depth in (0, 42) else str(self.depth)
        return f"{rel}:{dur}:,{depth}:,:,:,,"


#: The default of a topic (rclcpp's ``QoS(10)``).
DEFAULT_QOS = Qos()
#: A latched topic (``/map``, ``/tf_static``): the last sample kept for those who subscribe later.
LATCHED_QOS = Qos(durability=TRANSIENT_LOCAL, depth=1)


def mangle(name: str) -> str:
    """A name inside a token: each ``/`` as ``%`` (an empty name is ``%``)."""
    return name.replace("/", "%") if name else "%"


def dds_type_name(ros_type: str) -> str:
    """``geometry_msgs/msg/Twist`` as the DDS-style name in key expressions: ``geometry_msgs::msg::dds_::Twist_``."""
    package, kind, name = ros_type.split("/")
    return f"{package}::{kind}::dds_::{name}_"


def topic_keyexpr(domain: int, topic: str, ros_type: str, type_hash: str) -> str:
    """Where a topic's samples go: ``DOMAIN/TOPIC/TYPE/HASH``, the topic's name without its outer slashes (inner
    slashes stay: a namespace is a level of the key)."""
    return f"{domain}/{topic.strip('/')}/{dds_type_name(ros_type)}/{type_hash}"


@dataclass(frozen=True)
class Node:
    """A node as the graph knows it: its domain, its Zenoh session's id, its number in the session, name and
    namespace."""

    domain: int
    zid: str
    node_id: int
    name: str
    namespace: str = "/"
    enclave: str = "/"

    def token(self) -> str:
        """The node's liveliness token (``NN``)."""
        return (f"{ADMIN_SPACE}/{self.domain}/{self.zid}/{self.node_id}/{self.node_id}/NN/{mangle(self.enclave)}/"
                f"{mangle(self.namespace)}/{mangle(self.name)}")

    def endpoint_token(self, entity_id: int, kind: str, topic: str, ros_type: str, type_hash: str, qos: Qos) -> str:
        """A publisher's (``MP``) or subscription's (``MS``) liveliness token."""
        return (f"{ADMIN_SPACE}/{self.domain}/{self.zid}/{self.node_id}/{entity_id}/{kind}/{mangle(self.enclave)}/"
                f"{mangle(self.namespace)}/{mangle(self.name)}/{mangle(topic)}/{dds_type_name(ros_type)}/"
                f"{type_hash}/{qos.keyexpr()}")


def gid(token: str) -> bytes:
    """A publisher's 16-byte global id, from its token (rmw_zenoh hashes the token with XXH3-128; peers only compare
    GIDs, so a BLAKE2b digest of it serves as well and needs no library)."""
    return hashlib.blake2b(token.encode(), digest_size=16).digest()


class Attachment:
    """The attachment of a publisher's samples: its sequence number (from 1, one more each sample), the time of
    sending (ns since the epoch) and its GID, as ``<q q B 16s`` (little-endian; the GID's length before it, 16)."""

    __slots__ = ("_gid", "_sequence")

    def __init__(self, publisher_gid: bytes) -> None:
        if len(publisher_gid) != 16:
            raise ValueError(f"a GID is 16 bytes, got {len(publisher_gid)}")
        self._gid = publisher_gid
        self._sequence = 0

    def next(self, now_ns: int | None = None) -> bytes:
        """The next sample's attachment, sent at ``now_ns`` (default: now)."""
        self._sequence += 1
        return _ATTACHMENT.pack(self._sequence, time.time_ns() if now_ns is None else now_ns, 16, self._gid)


_ATTACHMENT = struct.Struct("<qqB16s")
