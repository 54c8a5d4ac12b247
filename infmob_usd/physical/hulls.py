"""Convex collision hulls posed in the world and the tests between them: face-plane separation,
box overlap, exact intersection volume (manifold3d), shared by the gap, sweep and clearance passes."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..triangles import triangle_cross

CLEARANCE = 1e-3
"""m; a moving subtree stops this far from what it may not touch (where it starts farther)."""

CONTACT_VOLUME = 1e-8
"""m^3; an exact hull intersection above this is a contact (validators fail at 1e-7 per pair)."""


def _inflate(points: np.ndarray, d: float) -> np.ndarray:
    """Points of the Minkowski sum with a cube of half-size ``d`` (an L-inf offset)."""
    offs = np.array([[x, y, z] for x in (-d, d) for y in (-d, d) for z in (-d, d)])
    return (points[:, None, :] + offs[None]).reshape(-1, 3)


def _face_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    tri = v[f]
    n = triangle_cross(tri)
    length = np.sqrt(np.add.reduce(n * n, axis=1, keepdims=True))  # np.linalg.norm(n, axis=1, keepdims=True)
    keep = length[:, 0] > 1e-15
    return n[keep] / length[keep]


def _separated(a: np.ndarray, a_normals: np.ndarray, d: float, b: np.ndarray, b_normals: np.ndarray) -> bool:
    """Whether a face plane of either hull separates the hull of points ``a`` grown by a cube of
    half-size ``d`` (:func:`_inflate`) from the hull of points ``b``: a sufficient test for
    "no overlap" (edge-edge separations are left to the exact test)."""
    n = np.concatenate((a_normals, b_normals))
    nt = n.T
    pa, pb = a @ nt, b @ nt
    amax, amin = np.maximum.reduce(pa, 0), np.minimum.reduce(pa, 0)
    if d != 0:  # adding a zero grow changes no comparison
        grow = d * np.add.reduce(np.abs(n), 1)
        amax, amin = amax + grow, amin - grow
    return bool(np.logical_or.reduce((amax < np.minimum.reduce(pb, 0)) | (amin > np.maximum.reduce(pb, 0))))


def _boxes_meet(lo_a: np.ndarray, hi_b: np.ndarray, lo_b: np.ndarray, hi_a: np.ndarray) -> np.ndarray:
    """``lo_a < hi_b`` and ``lo_b < hi_a`` on each of the three axes (the last one; the others
    broadcast): whether boxes ``a`` and ``b`` overlap. The same comparisons as
    ``np.all((lo_a < hi_b) & (lo_b < hi_a), axis=-1)``, axis by axis (faster on wide arrays)."""
    out = (lo_a[..., 0] < hi_b[..., 0]) & (lo_b[..., 0] < hi_a[..., 0])
    out &= lo_a[..., 1] < hi_b[..., 1]
    out &= lo_b[..., 1] < hi_a[..., 1]
    out &= lo_a[..., 2] < hi_b[..., 2]
    out &= lo_b[..., 2] < hi_a[..., 2]
    return out


@dataclass(frozen=True)
class _Hull:
    link: str
    points: np.ndarray  # (k, 3) hull vertices, link frame
    faces: np.ndarray  # (m, 3)

    @cached_property
    def normals(self) -> np.ndarray:
        """``(m, 3)`` distinct face normals, link frame (the triangles of one flat face share one)."""
        n = _face_normals(self.points, self.faces)
        # the first row of each distinct rounded normal (its 24 bytes), in row order: a dict built
        # from the last row to the first keeps the first row's index
        b = np.round(n, 9).tobytes()
        first = dict(zip([b[i:i + 24] for i in range(len(b) - 24, -24, -24)], range(len(n) - 1, -1, -1)))
        return n[sorted(first.values())]


def _solid_hulls(obj) -> dict[str, list[_Hull]]:
    out = {}
    for link in obj.links:
        if link.dummy or not link.pieces:
            continue
        hulls = [_Hull(link.name, v, f) for p in link.pieces for v, f in p.hulls()]
        if hulls:
            out[link.name] = hulls
    return out

_ROUNDED = object()  # key in an _Obstacles cache of the rounded key of each exact pose


class _Obstacles:
    """Posed hulls of the links a sweep may not enter, with lazily built exact solids.

    ``cache`` is shared between sweeps: per link and pose (rounded to 1e-9), the posed points and
    hull boxes; per hull and pose, the posed normals and the exact solid; per link, its hull points
    stacked in its frame; per exact pose, its rounded key."""

    def __init__(self, links: list[str], hulls: dict[str, list[_Hull]], poses: dict[str, np.ndarray],
                 cache: dict):
        self.hulls: list[_Hull] = []
        self.world: list[np.ndarray] = []
        self.keys: list[tuple] = []
        self.poses = poses
        lo, hi = [], []
        for name in links:
            pose = poses[name]
            exact = pose.tobytes()
            rounded = cache.setdefault(_ROUNDED, {}).get(exact)  # the key of each exact pose, once
            if rounded is None:
                rounded = cache[_ROUNDED][exact] = pose.round(9).tobytes()
            key = (name, rounded)
            if key not in cache:
                hs = hulls[name]
                if ("local", name) not in cache:  # the link's hull points stacked, in its frame
                    cache["local", name] = (np.vstack([h.points for h in hs]),
                                            np.cumsum([0] + [len(h.points) for h in hs]))
                local, starts = cache["local", name]
                stacked = local @ pose[:3, :3].T + pose[:3, 3]
                cache[key] = ([stacked[a:b] for a, b in zip(starts[:-1], starts[1:])],
                              np.minimum.reduceat(stacked, starts[:-1], axis=0),
                              np.maximum.reduceat(stacked, starts[:-1], axis=0),
                              [key + (k,) for k in range(len(hs))])
            world, l, h, keys = cache[key]
            self.hulls += hulls[name]
            self.world += world
            self.keys += keys
            lo.append(l)
            hi.append(h)
        if len(lo) == 1:
            self.lo, self.hi = lo[0], hi[0]
        else:
            self.lo = np.vstack(lo) if lo else np.zeros((0, 3))
            self.hi = np.vstack(hi) if hi else np.zeros((0, 3))
        self._cache = cache

    def normals(self, i: int) -> np.ndarray:
        key = ("normals",) + self.keys[i]
        if key not in self._cache:
            self._cache[key] = self.hulls[i].normals @ self.poses[self.hulls[i].link][:3, :3].T
        return self._cache[key]

    def solid(self, i: int, grown: float = 0.0):
        """The exact solid of hull ``i``, grown by a cube of half-size ``grown`` (:func:`_inflate`)."""
        import manifold3d

        key = ("solid", grown) + self.keys[i]
        if key not in self._cache:
            pts = _inflate(self.world[i], grown) if grown > 0 else self.world[i]
            self._cache[key] = manifold3d.Manifold.hull_points(pts)
        return self._cache[key]


def _hits(points: np.ndarray, normals: np.ndarray, margin: float, obstacles: _Obstacles, i: int,
          solids: dict | None = None, key=None) -> bool:
    """Whether the hull of ``points`` grown by ``margin`` overlaps obstacle hull ``i`` by more than
    :data:`CONTACT_VOLUME`: a face-plane separation test first, the exact intersection if it fails.
    ``solids`` (with ``key`` naming ``points``) keeps the exact hull of ``points`` for the next
    obstacle tested against the same points."""
    if _separated(points, normals, margin, obstacles.world[i], obstacles.normals(i)):
        return False
    import manifold3d

    if solids is None:
        solid = manifold3d.Manifold.hull_points(points)
    else:
        solid = solids.get(key)
        if solid is None:
            solid = solids[key] = manifold3d.Manifold.hull_points(points)
    # the obstacle grown by the margin (built once per obstacle) rather than every moving hull
    return (solid ^ obstacles.solid(i, margin)).volume() > CONTACT_VOLUME

