"""A scene's plan: the room (floor, walls with their openings) and where each object stands.

Room frame: metres, Z up, the floor at z = 0, the room's inside spanning ``x`` in [0, depth] and ``y`` in
[0, width]; walls stand outside that box. Each wall has a frame: an ``origin`` (a corner on the room side),
``along`` (the direction its length runs) and ``inward`` (the normal into the room). An object stands against
a wall with its back to it and its front (+X in its own frame, the project's convention) facing ``inward``, so
its yaw is that of ``inward``, and ``along`` is the image of its own +Y: a run of objects along a wall is laid
out in the objects' own Y.

Walls, in order around the room: ``north`` (x = 0, facing +X), ``east`` (y = width, facing -Y), ``south``
(x = depth, facing -X), ``west`` (y = 0, facing +Y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

WALLS = ("north", "east", "south", "west")


@dataclass(frozen=True)
class Wall:
    name: str
    origin: np.ndarray  # (3,) a corner on the room side, floor level
    along: np.ndarray  # (3,) unit, the wall's length runs this way from origin
    inward: np.ndarray  # (3,) unit normal into the room
    length: float

    @property
    def yaw(self) -> float:
        """Radians: the yaw that turns an object's front (+X) to face into the room."""
        return math.atan2(float(self.inward[1]), float(self.inward[0]))


@dataclass(frozen=True)
class Opening:
    """A hole through a wall: ``start``..``end`` along it, ``bottom``..``top`` above the floor."""

    wall: str
    start: float
    end: float
    bottom: float
    top: float
    what: str  # the id of the placed object that fills it (a door, a window)


@dataclass(frozen=True)
class Fixture:
    """A static box built into the room that is no object of its own: a worktop carried over the
    under-counter appliances of a run. ``lo``..``hi`` room frame; ``color``: linear RGB it is drawn in where
    a reader shows flat colours (its look's colour as worn: base colour times tint); ``wears``: ``(placed id,
    slot)`` of the object whose material it wears (a cabinet's ``top``: the same wood or stone), or ``None``.
    ``grain``: the room axis (0 X, 1 Y) its texture's grain runs along (the run's)."""

    name: str
    lo: np.ndarray
    hi: np.ndarray
    color: tuple[float, float, float]
    wears: tuple[str, str] | None = None
    grain: int = 0


@dataclass
class Room:
    width: float  # Y
    depth: float  # X
    height: float
    wall_thickness: float
    openings: list[Opening] = field(default_factory=list)
    fixtures: list[Fixture] = field(default_factory=list)

    def wall(self, name: str) -> Wall:
        w, d = self.width, self.depth
        ex, ey = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
        frames = {"north": (np.zeros(3), ey, ex, w), "east": (np.array([0.0, w, 0.0]), ex, -ey, d),
                  "south": (np.array([d, w, 0.0]), -ey, -ex, w), "west": (np.array([d, 0.0, 0.0]), -ex, ey, d)}
        origin, along, inward, length = frames[name]
        return Wall(name, origin, along, inward, float(length))

    def wall_boxes(self) -> list[tuple[str, np.ndarray, np.ndarray]]:
        """``(name, lo, hi)`` boxes of the floor, the ceiling and every wall with its openings cut out
        (a wall with openings is split into the boxes around them), room frame."""
        t, w, d, h = self.wall_thickness, self.width, self.depth, self.height
        out = [("floor", np.array([-t, -t, -t]), np.array([d + t, w + t, 0.0])),
               ("ceiling", np.array([-t, -t, h]), np.array([d + t, w + t, h + t]))]
        for name in WALLS:
            holes = sorted((o for o in self.openings if o.wall == name), key=lambda o: o.start)
            wall = self.wall(name)
            for k, (s0, s1, z0, z1) in enumerate(_pieces(wall.length, h, holes, t)):
                lo_pt = wall.origin + wall.along * s0 - wall.inward * t + np.array([0, 0, z0])
                hi_pt = wall.origin + wall.along * s1 + np.array([0, 0, z1])
                out.append((f"wall_{name}_{k}", np.minimum(lo_pt, hi_pt), np.maximum(lo_pt, hi_pt)))
        return out


def _pieces(length: float, height: float, holes: list[Opening], t: float) -> list[tuple[float, float, float, float]]:
    """The ``(s0, s1, z0, z1)`` rectangles of a wall of ``length`` (plus the corner ``t`` at each end)
    around its ``holes``: full-height piers between holes, and a lintel and a sill piece over and under each."""
    out, s = [], -t
    for o in holes:
        if o.start > s:
            out.append((s, o.start, 0.0, height))
        if o.bottom > 0:
            out.append((o.start, o.end, 0.0, o.bottom))
        if o.top < height:
            out.append((o.start, o.end, o.top, height))
        s = o.end
    if s < length + t:
        out.append((s, length + t, 0.0, height))
    return out


def yaw_matrix(yaw: float) -> np.ndarray:
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def pose_matrix(position, yaw: float) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = yaw_matrix(yaw)
    m[:3, 3] = position
    return m


def box_corners(lo, hi) -> np.ndarray:
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    return np.array([[(lo, hi)[i][0], (lo, hi)[j][1], (lo, hi)[k][2]] for i in (0, 1) for j in (0, 1) for k in (0, 1)])


def moved_box(lo, hi, pose: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """World AABB of the box ``lo``..``hi`` given in a frame at ``pose``."""
    c = box_corners(lo, hi) @ pose[:3, :3].T + pose[:3, 3]
    return c.min(0), c.max(0)


def boxes_overlap(a_lo, a_hi, b_lo, b_hi, tol: float = 1e-3) -> bool:
    """Whether two AABBs overlap by more than ``tol`` on every axis."""
    return bool(np.all(np.minimum(a_hi, b_hi) - np.maximum(a_lo, b_lo) > tol))
