"""Meeting gaps: a hinged part keeps :data:`MEETING_GAP` from the parts beside it that move on their own (the
twin leaf of a double door) all through its swing, not only at rest.

A leaf swinging shut brings the back corner of its free edge towards its twin by about ``T theta`` (``T`` its
thickness) before it lands: two 22 mm cabinet leaves 3 mm apart closed pass 2 mm apart at 0.09 rad, and PhysX's
persistent contact manifold reports -0.1 mm there, stalling the leaf 0.09 rad short of closed. Cabinet makers
leave 2-3 mm between fronts and bevel the meeting edges of a pair (Blum's planning guides: 2 mm minimum reveal
between fronts, more for thick ones; the bevel lets the back corner pass); here the collision hulls of the
meeting edge are eroded instead (visual meshes as designed).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..blueprint import descendants
from .gaps import _eroded
from .hulls import _face_normals, _inflate, _separated

MEETING_GAP = 0.003
"""m: the least gap a hinged part keeps from an independently moving neighbour over its swing (where they
are at least this far apart at rest)."""

SWING = 0.5
"""rad: how much of a hinge's range near rest is checked (the corner's approach peaks within a few degrees
of closed, where it is within a leaf's thickness of its twin)."""

STEP = 0.01  # rad between the sampled poses
ERODE = (0.0005, 0.001, 0.0015, 0.002, 0.003)  # m: the erosions tried on a piece, least first


def _world(c: np.ndarray, pose: np.ndarray) -> np.ndarray:
    return c @ pose[:3, :3].T + pose[:3, 3]


def _close(a: np.ndarray, na: np.ndarray, b: np.ndarray, nb: np.ndarray, gap: float) -> bool:
    """Whether hulls ``a`` and ``b`` (world points, face normals ``na``, ``nb``) come within ``gap``: the boxes
    first, then a face plane test, then an exact one on the grown hull."""
    if np.any(a.min(0) - gap > b.max(0)) or np.any(b.min(0) - gap > a.max(0)):
        return False
    if _separated(a, na, gap - 1e-6, b, nb):
        return False
    import manifold3d

    grown = manifold3d.Manifold.hull_points(_inflate(a, gap - 1e-6))
    return (grown ^ manifold3d.Manifold.hull_points(b)).volume() > 1e-12


def _neighbours(obj, j) -> list:
    """Links moved by some other movable joint that does not move ``j``'s part (and not by ``j``)."""
    mine = descendants(obj.joints, j.child)
    out: set[str] = set()
    for k in obj.joints:
        if k.movable and k is not j:
            theirs = descendants(obj.joints, k.child)
            if j.child not in theirs:
                out |= theirs - mine
    return sorted(n for n in out if obj.link(n).pieces)


def _angles(j) -> np.ndarray:
    top = min(j.upper, j.lower + SWING)
    return np.linspace(j.lower, top, max(2, int(np.ceil((top - j.lower) / STEP)) + 1))


def _swing_poses(obj, j, angles) -> list[np.ndarray]:
    """The child's world pose at each of ``angles`` of ``j``, every other joint at rest: a turn about the joint's
    axis through its origin (world, at rest) of the child's rest pose."""
    from ..rotation import axis_angle

    rest = obj.poses({})[j.child]
    origin = np.asarray(j.origin, float)
    out = []
    for a in angles:
        m = np.eye(4)
        m[:3, :3] = axis_angle(np.asarray(j.axis, float), float(a))
        m[:3, 3] = origin - m[:3, :3] @ origin
        out.append(m @ rest)
    return out


def _offenders(obj, child, others, angles) -> dict[tuple[int, int], list]:
    """``{(piece, convex index): [(other hull's world points at rest, its face normals)]}`` (``angles``: the
    child's sampled poses, rest first): the child's hulls that come within :data:`MEETING_GAP` of a
    neighbour's hull during the swing, though not at rest."""
    rest = obj.poses({})
    # links are world-aligned at rest: a neighbour's hull normals are its mesh's
    theirs = [(_world(oc, rest[o]), _face_normals(*h)) for o in others for op in obj.link(o).pieces
              for oc, h in zip(op.convex, op.hulls(), strict=True)]
    reach = np.vstack([_world(c, pose) for p in child.pieces for c in p.convex for pose in (angles[0], angles[-1])])
    lo_all, hi_all = reach.min(0) - child_span(child), reach.max(0) + child_span(child)
    theirs = [(b, nb) for b, nb in theirs if not (np.any(b.min(0) > hi_all) or np.any(b.max(0) < lo_all))]
    near: dict = {}
    if not theirs:
        return near
    bmin, bmax = np.array([b.min(0) for b, _ in theirs]), np.array([b.max(0) for b, _ in theirs])
    for n, piece in enumerate(child.pieces):
        for k, (c, h) in enumerate(zip(piece.convex, piece.hulls(), strict=True)):
            posed = _Posed(c, _face_normals(*h), angles)
            swept = np.vstack(posed.points)
            lo, hi = swept.min(0) - MEETING_GAP, swept.max(0) + MEETING_GAP
            for t in np.flatnonzero(~((bmin > hi).any(1) | (bmax < lo).any(1))).tolist():
                # _close's box test of every pose at once: a pose whose box is that far is not close
                b, nb = theirs[t]
                met = np.flatnonzero(~((posed.lo - MEETING_GAP > bmax[t]).any(1) |
                                       (bmin[t] - MEETING_GAP > posed.hi).any(1))).tolist()
                if not met or met[0] == 0 and _close(*posed[0], b, nb, MEETING_GAP):
                    continue  # far, or as close at rest by design: not the swing's doing
                if any(_close(*posed[i], b, nb, MEETING_GAP) for i in met if i > 0):
                    near.setdefault((n, k), []).append((b, nb))
    return near


class _Posed:
    """A hull's world points at each pose, their boxes, and its face normals at a pose when asked
    (:func:`_posed`'s, the same floats)."""

    def __init__(self, c: np.ndarray, normals: np.ndarray, poses):
        self.poses, self.normals = poses, normals
        self.points = [_world(c, pose) for pose in poses]
        self.lo = np.array([w.min(0) for w in self.points])
        self.hi = np.array([w.max(0) for w in self.points])

    def __getitem__(self, i: int) -> tuple[np.ndarray, np.ndarray]:
        return self.points[i], self.normals @ self.poses[i][:3, :3].T


def child_span(child) -> float:
    """A bound on how far a point of ``child`` moves past the box of its rest and last swing poses (an arc
    bulges out of its chord's box by at most its radius)."""
    pts = np.vstack([c for p in child.pieces for c in p.convex])
    return float(np.linalg.norm(np.ptp(pts, axis=0))) + MEETING_GAP


def _posed(c: np.ndarray, normals: np.ndarray, poses) -> list[tuple[np.ndarray, np.ndarray]]:
    return [(_world(c, pose), normals @ pose[:3, :3].T) for pose in poses]


def _clear_after(child, n: int, k: int, theirs: list, angles, d: float) -> tuple | None:
    piece = child.pieces[n]
    c, hv, hf = _eroded(piece.convex[k], piece.hulls()[k], d)
    for w, nw in _posed(c, _face_normals(hv, hf), angles):
        if any(_close(w, nw, b, nb, MEETING_GAP) for b, nb in theirs):
            return None
    return c, hv, hf


def keep_meeting_gaps(obj):
    """A copy of ``obj`` whose hinged parts' collision pieces that pass within :data:`MEETING_GAP` of an
    independently moving neighbour during the first :data:`SWING` of their range (and not at rest) are eroded,
    by the least of :data:`ERODE` that clears every sampled pose (left as they are if none does)."""
    links = {link.name: link for link in obj.links}
    for j in obj.joints:
        child = links[j.child]
        if j.type != "revolute" or child.dummy or not child.pieces or not j.upper > j.lower:
            continue
        others = _neighbours(obj, j)
        if not others:
            continue
        angles = _swing_poses(obj, j, _angles(j))  # the child's pose at each
        offenders = _offenders(obj, child, others, angles)
        if not offenders:
            continue
        pieces = list(child.pieces)
        by_piece: dict[int, dict] = {}
        for (n, k), bs in sorted(offenders.items(), key=lambda kv: kv[0]):
            for d in ERODE:
                got = _clear_after(child, n, k, bs, angles, d)
                if got is not None:
                    by_piece.setdefault(n, {})[k] = got
                    break
        for n, replaced in by_piece.items():
            pieces[n] = pieces[n].with_convex(replaced)
        links[child.name] = replace(child, pieces=pieces)
        obj = replace(obj, links=[links[link.name] for link in obj.links])
    return obj


__all__ = ["MEETING_GAP", "keep_meeting_gaps"]
