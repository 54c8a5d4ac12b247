"""Support surfaces of an object at rest: where something can be set down on it.

A support region is the flat top of one of the object's collision hulls (a worktop, a shelf board, a
cooktop grate, a table top, a seat) with the free height above it inside the object (up to the next
hull over it: the shelf above, a cabinet's top; ``None`` where nothing of the object is above).
Regions are found from the collision geometry alone, for every category alike: the hull's top
points (within :data:`FLAT` of its highest point) span a rectangle of at least :data:`MIN_SIDE` on
each side; a round top is shrunk to the rectangle of the same area, so what stands in it stands on
the hull. Coordinates are the object's frame at rest; ``link`` names the link that carries it (a
drawer's floor moves with the drawer).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

FLAT = 0.002  # m: points this close below a hull's top count as its top face
MIN_SIDE = 0.05  # m: a region narrower than a small cup's foot (5 cm) carries nothing
MIN_CLEAR = 0.03  # m: a region with less room above it carries nothing
BAR_GAP = 0.06  # m: no point farther than this from a bar: a pot (a 12 cm base or more) bridges it (range grates)
RESTING = 0.005  # m: a hull whose bottom is this close above a region stands on it (a turntable, a tray)
BLOCKING = 0.2  # a hull that rises through more than this share of a region's area disqualifies it


@dataclass(frozen=True)
class Region:
    """A flat, upward-facing rectangle ``lo``..``hi`` (x, y) at height ``z``, object frame at rest."""

    link: str
    z: float
    lo: tuple[float, float]
    hi: tuple[float, float]
    clear: float | None  # free height above, m; None: nothing of the object is above it

    @property
    def area(self) -> float:
        return (self.hi[0] - self.lo[0]) * (self.hi[1] - self.lo[1])

    def as_dict(self) -> dict:
        return {"link": self.link, "z": round(self.z, 6), "min": [round(v, 6) for v in self.lo],
                "max": [round(v, 6) for v in self.hi],
                "clear": None if self.clear is None else round(self.clear, 6)}


def _hulls(obj) -> list[tuple[str, np.ndarray]]:
    """``(link name, points)`` of every collision hull, object frame at rest."""
    return [(link.name, np.asarray(c, float) + link.origin) for link in obj.links for p in link.pieces
            for c in p.convex if len(c) >= 4]


def hull_boxes(obj) -> tuple[np.ndarray, np.ndarray]:
    """``(lo, hi)``, each ``(n, 3)``: the box of every collision hull of ``obj``, object frame at rest."""
    hulls = _hulls(obj)
    return (np.array([p.min(0) for _, p in hulls]).reshape(-1, 3),
            np.array([p.max(0) for _, p in hulls]).reshape(-1, 3))


def _top_points(points: np.ndarray) -> tuple[float, np.ndarray]:
    z = float(points[:, 2].max())
    return z, points[points[:, 2] >= z - FLAT][:, :2]


def _top(points: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """``(z, lo, hi)`` of a flat top face (a hull's, or the bars of a grate together), or ``None`` if it
    is not big enough."""
    z, top = _top_points(points)
    if len(top) < 3:
        return None
    lo, hi = top.min(0), top.max(0)
    if np.any(hi - lo < MIN_SIDE):
        return None
    on_edges = np.all((np.abs(top - lo) < 1e-6) | (np.abs(top - hi) < 1e-6), axis=1)
    ratio = 1.0 if on_edges.all() else _polygon_area(top) / float(np.prod(hi - lo))  # a box's top: its corners
    if ratio < 0.98:  # not a rectangle (a disc, a hexagon): the centred rectangle of the same area
        mid, half = (lo + hi) / 2, (hi - lo) / 2 * np.sqrt(max(ratio, 0.0)) * np.sqrt(0.5) * np.sqrt(2 / np.pi) * 2
        lo, hi = mid - half, mid + half
        if np.any(hi - lo < MIN_SIDE):
            return None
    return z, lo, hi


def _polygon_area(points: np.ndarray) -> float:
    from scipy.spatial import ConvexHull, QhullError

    try:
        return float(ConvexHull(points).volume)
    except (QhullError, ValueError):
        return 0.0


def _clear_above(z: float, lo: np.ndarray, hi: np.ndarray, boxes: tuple[np.ndarray, np.ndarray],
                 skip: tuple[int, ...]) -> tuple[float | None, bool]:
    """Free height over the rectangle, and whether a hull stands on or rises through too much of it
    (``boxes``: every hull's ``(lo, hi)`` as two ``(n, 3)`` arrays)."""
    h_lo, h_hi = boxes
    overlap = np.minimum(hi, h_hi[:, :2]) - np.maximum(lo, h_lo[:, :2])
    near = np.all(overlap > 1e-4, axis=1)
    near[list(skip)] = False
    if not near.any():
        return None, False
    area, share = float(np.prod(hi - lo)), overlap[:, 0] * overlap[:, 1]
    bottom, top = h_lo[:, 2], h_hi[:, 2]
    above = near & (bottom >= z - 1e-3)
    resting = above & (bottom < z + RESTING)  # standing on it: occupies part of it
    through = near & (bottom < z - 1e-3) & (top > z + 1e-3)
    if np.any(share[resting | through] > BLOCKING * area):
        return None, True
    ceiling = bottom[above & ~resting]
    return (float(ceiling.min() - z) if ceiling.size else None), False


def _bars(hulls) -> list[tuple[str, np.ndarray, list[int]]]:
    """Hulls too narrow to carry anything alone whose tops share a link and a height (the bars of a
    grate, the wires of a rack): ``(link, their top points, their indices)`` per such group."""
    groups: dict[tuple[str, int], list[int]] = {}
    for k, (link, pts) in enumerate(hulls):
        z, top = _top_points(pts)
        if len(top) >= 2 and np.any(top.max(0) - top.min(0) < MIN_SIDE):
            groups.setdefault((link, round(z / FLAT)), []).append(k)
    out = []
    for (link, _), ks in sorted(groups.items()):
        if len(ks) >= 3:
            z = max(float(hulls[k][1][:, 2].max()) for k in ks)
            tops = [_top_points(hulls[k][1])[1] for k in ks]
            if _spans(tops):
                out.append((link, np.vstack([np.c_[t, np.full(len(t), z)] for t in tops]), ks))
    return out


def _spans(tops: list[np.ndarray]) -> bool:
    """Whether bars cover their bounding rectangle closely enough to carry a foot anywhere in it: no point of
    it farther than :data:`BAR_GAP` from a bar (a grate's bars; not a sink's rim round its bowl)."""
    boxes = np.array([(t.min(0), t.max(0)) for t in tops])  # (n, 2, 2)
    lo, hi = boxes[:, 0].min(0), boxes[:, 1].max(0)
    u = np.linspace(0.05, 0.95, 9)
    grid = lo + (hi - lo) * np.stack(np.meshgrid(u, u), -1).reshape(-1, 1, 2)  # (81, 1, 2)
    outside = np.maximum(boxes[None, :, 0] - grid, 0) + np.maximum(grid - boxes[None, :, 1], 0)
    return bool(np.linalg.norm(outside, axis=2).min(1).max() <= BAR_GAP)


def support_regions(obj) -> list[Region]:
    """Every support region of ``obj`` (an :class:`~infmob_usd.model.ArticulatedObject`) at rest,
    highest first, then by position (a stable order)."""
    hulls = _hulls(obj)
    boxes = hull_boxes(obj)
    out = []
    candidates = [(link, pts, (k,)) for k, (link, pts) in enumerate(hulls)] + _bars(hulls)
    for link, pts, own in candidates:
        top = _top(pts)
        if top is None:
            continue
        z, lo, hi = top
        clear, blocked = _clear_above(z, lo, hi, boxes, own)
        if blocked or (clear is not None and clear < MIN_CLEAR):
            continue
        out.append(Region(link, z, (float(lo[0]), float(lo[1])), (float(hi[0]), float(hi[1])), clear))
    return sorted(set(out), key=lambda r: (-r.z, r.lo, r.hi, r.link))
