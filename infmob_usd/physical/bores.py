"""Clear bores: a shaft that only turns about and slides along its own axis keeps no collision hull inside
the bore of a link it is not jointed to directly.

The joints between the two (a push-to-turn knob: a slide and a turn on one axis, through a dummy link)
carry the shaft about and along its axis only, so it can never touch the bore's sides. PhysX tests the
pair all the same (an articulation skips only a link and its parent; the USD and the MJCF filter a compound
joint's real parent and child, a URDF cannot), and its persistent contact manifold (PCM) misreads it: a
light switch's dimmer shaft, a 6 mm 16-gon in a square hole 2.5 mm clear of its sides, stalled at 2.33 of
5.24 rad on a contact of -8.3 mm (the gap plus the shaft: the shaft's far side taken for its near one); as
an 8-gon, a 32-gon or turned half a facet it stalled at other angles; with its hull ending outside the bore
(its push travel clear of the mouth) it turned its whole range, as it did with PCM off
(``PhysxSceneConfig.enable_pcm``).

The rule: for a link two or more joints below another, those joints all turning about or sliding along one
line, a hull of the lower link that straddles the line, with hulls of the upper one round it on every side (outside its
radius from the line by less than :data:`~.rims.NEAR`) over the same stretch of the line, is cut where that stretch
begins: what of it could lie in the bore's stretch, the slides' travel counted, is cut away and the longer
end kept. A hull that would keep nothing is left as it is.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from scipy.spatial import ConvexHull

from ..hulls import hull_arrays
from .rims import NEAR, PARALLEL_COS, _basis, _planes, solid

SIDES = 72
"""Directions round the line in which a bore must have a wall (every 5 degrees)."""

ON_LINE = 1e-6
"""m; pivots this close to one line turn about it."""


def _ancestry(joints) -> dict[str, list]:
    """``link -> the joints from it up to the root``, nearest first."""
    into = {j.child: j for j in joints}
    out: dict[str, list] = {}

    def up(name: str) -> list:
        if name not in out:
            out[name] = [into[name], *up(into[name].parent)] if name in into else []
        return out[name]
    for j in joints:
        up(j.child)
    return out


def _line(chain: list) -> tuple[np.ndarray, np.ndarray] | None:
    """``(point, unit axis)`` of the one line every joint of ``chain`` turns about or slides along, or None."""
    if not chain or any(j.type not in ("revolute", "continuous", "prismatic") for j in chain):
        return None
    axis = np.asarray(chain[0].axis, float) / np.linalg.norm(chain[0].axis)
    if any(abs(float(np.asarray(j.axis, float) @ axis)) / np.linalg.norm(j.axis) < PARALLEL_COS for j in chain):
        return None
    pivots = [np.asarray(j.origin, float) for j in chain if j.type != "prismatic"]
    if not pivots:
        return None
    off = [p - pivots[0] - ((p - pivots[0]) @ axis) * axis for p in pivots]
    return (pivots[0], axis) if max(np.linalg.norm(off, axis=1)) <= ON_LINE else None


def _travel(chain: list, axis: np.ndarray) -> tuple[float, float]:
    """The least and most the slides of ``chain`` move the shaft along ``axis`` from rest."""
    lo = hi = 0.0
    for j in chain:
        if j.type == "prismatic":
            ends = float(np.asarray(j.axis, float) @ axis) / np.linalg.norm(j.axis) * np.array([j.lower, j.upper])
            lo, hi = lo + min(0.0, ends.min()), hi + max(0.0, ends.max())
    return lo, hi


def _radial(world: np.ndarray, point: np.ndarray, axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points' positions along the line and their 2-D positions across it."""
    rel = world - point
    return rel @ axis, rel @ _basis(axis).T


def _distance(poly: np.ndarray) -> float:
    """How far the line (the 2-D origin) lies outside the convex outline of ``poly``; 0 inside it."""
    hull = ConvexHull(poly)
    if np.all(hull.equations[:, 2] < -1e-12):
        return 0.0
    ring = poly[hull.vertices]
    best = np.inf
    for p, q in zip(ring, np.roll(ring, -1, axis=0), strict=True):
        t = np.clip(-(p @ (q - p)) / max(float((q - p) @ (q - p)), 1e-30), 0.0, 1.0)
        best = min(best, float(np.linalg.norm(p + t * (q - p))))
    return best


def _surrounds(walls: list[np.ndarray], radius: float) -> bool:
    """Whether the 2-D outlines ``walls`` close the line in on every side within :data:`NEAR` of ``radius``: a
    bore, not a wall on one side (a knob's grip beside a panel's rim stays whole)."""
    turn = np.linspace(0.0, 2 * np.pi, SIDES, endpoint=False)
    r = np.linspace(radius, radius + NEAR, 11)
    pts = (r[None, :, None] * np.stack([np.cos(turn), np.sin(turn)], axis=1)[:, None, :]).reshape(-1, 2)
    inside = np.zeros(len(pts), bool)
    for c in walls:
        eq = ConvexHull(c).equations
        inside |= np.all(pts @ eq[:, :2].T + eq[:, 2] <= 1e-12, axis=1)
    return bool(inside.reshape(SIDES, -1).any(axis=1).all())


def _keep(shaft: np.ndarray, others: list[np.ndarray], line, travel) -> tuple[np.ndarray, float] | None:
    """The half-space ``(axis, offset)``: keep ``axis . x >= offset``) that clears ``shaft`` (world points) of
    the bore formed by ``others`` (world points of the other link's hulls), or None if none lies beside it."""
    point, axis = line
    along, across = _radial(shaft, point, axis)
    if _distance(across) > 0.0:
        return None  # the line misses it: no shaft
    radius = float(np.linalg.norm(across, axis=1).max())
    reach = (along.min() + travel[0], along.max() + travel[1])
    stretch, walls = [], []
    for pts in others:
        a, c = _radial(pts, point, axis)
        if radius < _distance(c) < radius + NEAR and a.min() < reach[1] and a.max() > reach[0]:
            stretch += [a.min(), a.max()]
            walls.append(c)
    if not walls or not _surrounds(walls, radius):
        return None
    start, end = min(stretch) - travel[1], max(stretch) - travel[0]  # where the shaft may not be
    ahead, behind = along.max() - end, start - along.min()
    if max(ahead, behind) <= 0:
        return None
    return (axis, end + point @ axis) if ahead >= behind else (-axis, -start - point @ axis)


def clear_bores(links, joints) -> list:
    """New links whose shafts keep no hull inside a bore they turn or slide in (see the module docstring);
    links with nothing cut are returned as they are. Only collision shapes change."""
    real = [link for link in links if not link.dummy]
    hulls = {link.name: [(p, k, h[0] + link.origin) for p, piece in enumerate(link.pieces)
                         for k, h in enumerate(piece.hulls())] for link in real}
    cuts: dict[str, dict[tuple[int, int], list]] = {}
    ancestry = _ancestry(joints)
    for a in real:
        chain = ancestry.get(a.name, [])
        for n in range(2, len(chain) + 1):  # a shaft two or more joints below the link it runs in
            b, mine = chain[n - 1].parent, chain[:n]
            if b not in hulls or not hulls[b]:
                continue
            line = _line(mine)
            if line is None:
                continue
            travel = _travel(mine, line[1])
            for p, k, world in hulls[a.name]:
                keep = _keep(world, [w for _, _, w in hulls[b]], line, travel)
                if keep is not None:
                    cuts.setdefault(a.name, {}).setdefault((p, k), []).append(keep)
    return [_cut_link(link, cuts[link.name]) if link.name in cuts else link for link in links]


def _cut_link(link, cuts: dict[tuple[int, int], list]):
    """``link`` with each hull ``(piece, k)`` of ``cuts`` cut to its half-spaces (left as it is if nothing stays)."""
    pieces = list(link.pieces)
    for p in sorted({p for p, _ in cuts}):
        replaced = {}
        for (q, k), keep in sorted(cuts.items()):
            if q != p:
                continue
            v, f = pieces[p].hulls()[k]
            world = v + link.origin
            halves = [np.r_[n, -d] for n, d, _ in _planes(world, f)]
            halves += [np.r_[-axis, offset] for axis, offset in keep]
            pts = solid(np.array(halves))
            if pts is not None:
                hv, hf = hull_arrays(pts - link.origin)
                replaced[k] = (hv, hv, hf)
        if replaced:
            pieces[p] = pieces[p].with_convex(replaced)
    return replace(link, pieces=pieces)
