"""Square rims: a thin collision hull has no chamfer or flare at a face that looks onto a parallel face
of another link's hull across a small gap.

PhysX's persistent contact manifold (PCM, on by default in SAPIEN, ManiSkill and Isaac) misreads such a
pair while one of them moves (a pepper grinder's head turning 1.5 mm above the body's window bars): now
and then, with no overlap at all, it reports a contact as deep as the gap plus the thin hull's thickness
with the normal flipped (the far face of the thin hull taken for the near one; a freshly posed scene reads
the true gap), and the part stalls. In a parameter sweep of the grinder's head band over the bars (the
band's lateral position and the gap varied over 99 poses), a 5.9 mm band whose side flares out 14
degrees over the bars stalled in 29; the same band with a square rim (upright sides, the bottom face's
outline) in none, nor did a band half as flared or one 8.8 mm thick;
the contact offset (3 mm to 2 cm) made no difference. A phone's slide stopped half way where its bar
passed 6.7 mm over a 2.1 mm key with a chamfered top (an 8.8 mm contact); with the keys' tops squared it
ran its whole travel, and with PCM off (``PhysxSceneConfig.enable_pcm``) it did either way.

The rule: where a hull face ``f`` and an anti-parallel face of another link's hull are less than
:data:`NEAR` apart and overlap seen along their normal, and the hull is thinner than
:data:`WITNESS_TOL` across ``f``, the hull is cut to the upright prism over ``f`` (what of it lies over
``f``'s outline): its sides rise square from that face. A hull that would keep less than :data:`KEEP` of
its volume is left as it is; of several faces, those squared together that keep that much, the cheapest
first. The faces are compared at rest and along each slide between the root and either link, one at a time:
a face a slide moves within its own plane counts over its whole path (a slide's bar over a row of keys that
it never overlaps at rest). Pairs of links joined by one joint are skipped (a PhysX articulation never
tests a link against its parent).
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cached_property

import numpy as np
from scipy.optimize import linprog
from scipy.spatial import ConvexHull, HalfspaceIntersection, QhullError

from ..hulls import hull_arrays
from ..partlib import hull_volume
from ..triangles import triangle_cross

NEAR = 0.01
"""m; faces closer than this are squared. PhysX makes contacts out to the sum of the two contact offsets
(2 cm at SAPIEN's default 0.01 m); the misreads seen came at gaps of 0.5 to 6.7 mm."""

WITNESS_TOL = 0.01
"""m; PCM picks the face that bears a contact among those within ``0.01 x`` its tolerance length
(``PxTolerancesScale.length``, 1 m in SAPIEN) of the closest point: a hull thinner than this across a face
has its far face among them. Thicker hulls are left as they are."""

PARALLEL_COS = math.cos(math.radians(1.0))
"""Two faces count as parallel within 1 degree."""

IN_PLANE = math.sin(math.radians(1.0))
"""A slide moves a face within its own plane when its travel leaves the plane by at most 1 degree."""

OVERHANG = 1e-4
"""m; a hull that reaches less than this beyond a face's outline already rises square from it."""

KEEP = 0.6
"""The least share of its volume a hull keeps when squared: a rim's chamfer or flare is cut (a phone key's
0.64 mm chamfer round a 6.8 mm top: 70 % kept), a hull that is mostly overhang (a cone's blunt tip towards
the neighbour; a band flared 15 mm over 5.9 mm: 57 %) is left as it is."""


def _planes(v: np.ndarray, f: np.ndarray) -> list[tuple[np.ndarray, float, np.ndarray]]:
    """The flat faces of a hull: ``(outward unit normal, offset, indices of the vertices on it)``."""
    n = triangle_cross(v[f])
    length = np.linalg.norm(n, axis=1)
    keep = length > 1e-15
    n, tri = n[keep] / length[keep, None], f[keep]
    scale = float(np.ptp(v, axis=0).max())
    out: list[tuple[np.ndarray, float, np.ndarray]] = []
    for k in range(len(n)):
        d = float(n[k] @ v[tri[k, 0]])
        if any(float(p[0] @ n[k]) > 1 - 1e-9 and abs(p[1] - d) <= 1e-9 * scale for p in out):
            continue
        on = np.flatnonzero(np.abs(v @ n[k] - d) <= 1e-7 * max(scale, 1e-3))
        out.append((n[k], d, on))
    return out


def _basis(n: np.ndarray) -> np.ndarray:
    """Two unit vectors spanning the plane normal to ``n`` (rows)."""
    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(n, a)
    u /= np.linalg.norm(u)
    return np.array([u, np.cross(n, u)])


def _ring(pts2: np.ndarray) -> np.ndarray:
    """The convex outline (counter-clockwise) of 2-D points: a face's vertices in its plane."""
    c = pts2.mean(0)
    ang = np.arctan2(pts2[:, 1] - c[1], pts2[:, 0] - c[0])
    ring = pts2[np.argsort(ang, kind="stable")]
    keep = np.r_[True, np.linalg.norm(np.diff(ring, axis=0), axis=1) > 1e-12]
    return ring[keep]


def _outline(pts2: np.ndarray) -> np.ndarray:
    """The convex hull (counter-clockwise) of 2-D points that need not lie on one convex polygon: a face's
    outline at both ends of a slide."""
    return pts2[ConvexHull(pts2).vertices]


def _edges(ring: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Outward unit normals and offsets of a counter-clockwise outline's edges (2-D half-planes)."""
    e = np.roll(ring, -1, axis=0) - ring
    out = np.c_[e[:, 1], -e[:, 0]]
    length = np.linalg.norm(out, axis=1)
    ok = length > 1e-12
    out = out[ok] / length[ok, None]
    return out, np.einsum("ij,ij->i", out, ring[ok])


def _clip_area(a: np.ndarray, b: np.ndarray) -> float:
    """Area of the overlap of two convex counter-clockwise outlines (Sutherland-Hodgman)."""
    poly = list(a)
    normals, offsets = _edges(b)
    for m, c in zip(normals, offsets, strict=True):
        if not poly:
            return 0.0
        nxt = []
        for i, p in enumerate(poly):
            q = poly[(i + 1) % len(poly)]
            dp, dq = float(m @ p) - c, float(m @ q) - c
            if dp <= 0:
                nxt.append(p)
            if (dp < 0 < dq) or (dq < 0 < dp):
                nxt.append(p + (q - p) * (dp / (dp - dq)))
        poly = nxt
    if len(poly) < 3:
        return 0.0
    x, y = np.array(poly).T
    return 0.5 * abs(float(x @ np.roll(y, -1) - y @ np.roll(x, -1)))


class _Hull:
    """One convex piece of a link posed in the world at rest, its box and (when asked) its flat faces."""

    def __init__(self, link: str, piece: int, k: int, hull: tuple, origin: np.ndarray):
        self.link, self.piece, self.k = link, piece, k
        self.hull = hull
        self.world = hull[0] + origin
        self.lo, self.hi = self.world.min(0), self.world.max(0)

    @cached_property
    def planes(self) -> list[tuple[np.ndarray, float, np.ndarray]]:
        return _planes(self.world, self.hull[1])


def _squares(a: _Hull, b: _Hull, travel: np.ndarray | None = None) -> list[int]:
    """Indices of the faces of ``a`` that look onto a face of ``b`` across less than :data:`NEAR`,
    overlapping it seen along their normal, where ``a`` is thinner than :data:`WITNESS_TOL` and
    reaches beyond that face's outline. ``travel`` (2 x 3): the two ends of a slide that carries ``b``
    relative to ``a``; a face of ``b`` it moves within its own plane counts over its whole path."""
    out = []
    for i, (n, d, on) in enumerate(a.planes):
        if len(on) < 3 or d - float((a.world @ n).min()) >= WITNESS_TOL:
            continue
        basis = _basis(n)
        mine = _ring(a.world[on] @ basis.T)
        normals, offsets = _edges(mine)
        if float(((a.world @ basis.T) @ normals.T - offsets).max()) < OVERHANG:
            continue
        for m, e, other in b.planes:
            gap = -e - d  # b's face lies at n . x = -e
            if float(m @ n) > -PARALLEL_COS or len(other) < 3 or not -1e-9 <= gap < NEAR:
                continue
            face = b.world[other]
            if travel is not None:
                if np.abs(travel @ m).max() > IN_PLANE * np.abs(travel).max():
                    continue
                face = np.concatenate([face + t for t in travel])
            if _clip_area(mine, _outline(face @ basis.T)) > 1e-10:
                out.append(i)
                break
    return out


def solid(halves: np.ndarray) -> np.ndarray | None:
    """The corners of the solid inside every half-space ``a . x + b <= 0`` (rows ``a, b``), or None if it
    has no inside."""
    # the centre of the largest ball inside every half-space (Qhull starts from a point inside)
    norms = np.linalg.norm(halves[:, :3], axis=1)
    ball = linprog([0, 0, 0, -1], A_ub=np.c_[halves[:, :3], norms], b_ub=-halves[:, 3],
                   bounds=[(None, None)] * 3 + [(0, None)], method="highs")
    if not ball.success or ball.x[3] <= 1e-7:
        return None
    try:
        pts = HalfspaceIntersection(halves, ball.x[:3]).intersections
    except QhullError:
        return None
    if not np.all(np.isfinite(pts)) or len(pts) < 4:
        return None
    return pts


def _cut(h: _Hull, faces: list[int], origin: np.ndarray) -> tuple | None:
    """Hull ``h`` cut to the upright prisms over its ``faces``: ``(points, hull vertices, hull
    faces)`` in the link frame, or None if the cut leaves no solid or less than :data:`KEEP` of it."""
    halves = [np.r_[n, -d] for n, d, _ in h.planes]
    for i in faces:
        n, _, on = h.planes[i]
        basis = _basis(n)
        normals, offsets = _edges(_ring(h.world[on] @ basis.T))
        halves += [np.r_[m @ basis, -c] for m, c in zip(normals, offsets, strict=True)]
    pts = solid(np.array(halves))
    if pts is None:
        return None
    v, f = hull_arrays(pts - origin)
    if hull_volume(v, f) < KEEP * hull_volume(*h.hull):
        return None
    return v, v, f


def _squared(h: _Hull, faces: list[int], origin: np.ndarray) -> tuple | None:
    """Hull ``h`` squared at as many of its ``faces`` as keep :data:`KEEP` of it together (:func:`_cut`), the
    faces whose cut alone keeps the most first: a key squared at its top, which a slide passes over, though
    cutting its sides too (neighbouring keys face them) would leave too little. None if no face can be."""
    alone = {i: _cut(h, [i], origin) for i in faces}
    order = sorted((i for i in faces if alone[i] is not None), key=lambda i: -hull_volume(alone[i][0], alone[i][2]))
    chosen, out = [], None
    for i in order:
        trial = alone[i] if not chosen else _cut(h, chosen + [i], origin)
        if trial is not None:
            chosen.append(i)
            out = trial
    return out


def _slides(links, joints) -> dict[str, dict[str, np.ndarray]]:
    """``link -> {joint: its two ends (2 x 3)}`` for every slide between the root and each link: how far it
    carries the link from rest, either way."""
    into = {j.child: j for j in joints}
    out: dict[str, dict[str, np.ndarray]] = {}
    for link in links:
        path, name = {}, link.name
        while name in into:
            j = into[name]
            if j.type == "prismatic":
                path[j.name] = np.outer([j.lower, j.upper], np.asarray(j.axis, float))
            name = j.parent
        out[link.name] = path
    return out


def _travels(sa: dict[str, np.ndarray], sb: dict[str, np.ndarray]) -> list[np.ndarray]:
    """The ends of each slide that moves ``b`` relative to ``a`` (one at a time, the others at rest): the
    slides between the root and ``b`` and not ``a``, and those between the root and ``a`` reversed."""
    return [sb[k] for k in sorted(sb) if k not in sa] + [-sa[k] for k in sorted(sa) if k not in sb]


def _facing(hulls: list[_Hull], slides: dict, adjacent: set) -> dict[int, list[int]]:
    """``hull index -> its faces to square`` (:func:`_squares`) over every pair of hulls of two links not
    joined by one joint, at rest and along each slide that moves one past the other."""
    reach = np.array([np.sum([np.minimum(e.min(0), 0) for e in slides[h.link].values()] + [np.zeros(3)], axis=0)
                      for h in hulls]), np.array([np.sum([np.maximum(e.max(0), 0) for e in slides[h.link].values()]
                                                         + [np.zeros(3)], axis=0) for h in hulls])
    lo = np.array([h.lo for h in hulls]) + reach[0]
    hi = np.array([h.hi for h in hulls]) + reach[1]
    names = np.array([h.link for h in hulls])
    near = np.all((lo[:, None] < hi[None] + NEAR) & (lo[None] < hi[:, None] + NEAR), axis=2)
    near &= names[:, None] != names[None]
    cut: dict[int, list[int]] = {}
    for i, j in zip(*np.nonzero(np.triu(near, 1)), strict=True):
        a, b = hulls[i], hulls[j]
        if frozenset((a.link, b.link)) in adjacent:
            continue
        travels = [None, *_travels(slides[a.link], slides[b.link])]
        for x, y, k, sign in ((a, b, i, 1.0), (b, a, j, -1.0)):
            faces = sorted({f for t in travels for f in _squares(x, y, None if t is None else sign * t)})
            if faces:
                cut.setdefault(int(k), [])
                cut[int(k)] += [f for f in faces if f not in cut[int(k)]]
    return cut


def square_rims(links, joints) -> list:
    """New links whose thin collision hulls rise square from any face that looks onto a nearby parallel
    face of another link's hull, at rest or as a slide carries one over the other (see the module
    docstring); links with nothing cut are returned as they are. Only collision shapes change."""
    adjacent = {frozenset((j.parent, j.child)) for j in joints}
    hulls = [_Hull(link.name, p, k, h, link.origin)
             for link in links if not link.dummy
             for p, piece in enumerate(link.pieces)
             for k, h in enumerate(piece.hulls())]
    if len(hulls) < 2:
        return list(links)
    cut = _facing(hulls, _slides(links, joints), adjacent)
    if not cut:
        return list(links)
    by_link: dict[str, dict[int, dict[int, tuple]]] = {}
    origins = {link.name: link.origin for link in links}
    for k in sorted(cut):
        h = hulls[k]
        new = _squared(h, sorted(cut[k]), origins[h.link])
        if new is not None:
            by_link.setdefault(h.link, {}).setdefault(h.piece, {})[h.k] = new
    out = []
    for link in links:
        if link.name not in by_link:
            out.append(link)
            continue
        pieces = list(link.pieces)
        for p, replaced in by_link[link.name].items():
            pieces[p] = pieces[p].with_convex(replaced)
        out.append(replace(link, pieces=pieces))
    return out
