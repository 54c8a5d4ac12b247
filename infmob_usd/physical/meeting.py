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
from .hulls import _separated

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


def _close(a: np.ndarray, b: np.ndarray, gap: float) -> bool:
    """Whether hulls ``a`` and ``b`` (world points) come within ``gap`` (a face plane test on the boxes first,
    then an exact one on the grown hull)."""
    if np.any(a.min(0) - gap > b.max(0)) or np.any(b.min(0) - gap > a.max(0)):
        return False
    from scipy.spatial import ConvexHull, QhullError

    try:
        ha, hb = ConvexHull(a), ConvexHull(b)
    except (QhullError, ValueError):
        return False
    na, nb = ha.equations[:, :3], hb.equations[:, :3]
    if _separated(a, na, gap - 1e-6, b, nb):
        return False
    import manifold3d

    from .hulls import _inflate

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


def _offenders(obj, j, child, others, angles) -> dict[tuple[int, int], list]:
    """``{(piece, convex index): [other hull's world points at rest]}`` (``angles``: the child's sampled poses,
    rest first): the child's hulls that come
    within :data:`MEETING_GAP` of a neighbour's hull during the swing, though not at rest."""
    rest = obj.poses({})
    near = {}
    for n, piece in enumerate(child.pieces):
        for k, c in enumerate(piece.convex):
            at_rest = _world(c, rest[child.name])
            swept = np.vstack([_world(c, pose) for pose in angles])
            lo, hi = swept.min(0) - MEETING_GAP, swept.max(0) + MEETING_GAP
            for o in others:
                for op in obj.link(o).pieces:
                    for oc in op.convex:
                        b = _world(oc, rest[o])
                        if np.any(b.min(0) > hi) or np.any(b.max(0) < lo) or _close(at_rest, b, MEETING_GAP):
                            continue  # as close by design: not the swing's doing
                        if any(_close(_world(c, pose), b, MEETING_GAP) for pose in angles[1:]):
                            near.setdefault((n, k), []).append(b)
    return near


def _clear_after(obj, j, child, n: int, k: int, bs: list, angles, d: float) -> tuple | None:
    piece = child.pieces[n]
    c, hv, hf = _eroded(piece.convex[k], piece.hulls()[k], d)
    for pose in angles:
        w = _world(c, pose)
        if any(_close(w, b, MEETING_GAP) for b in bs):
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
        angles = [obj.poses({j.name: float(a)})[child.name] for a in _angles(j)]  # the child's pose at each
        offenders = _offenders(obj, j, child, others, angles)
        if not offenders:
            continue
        pieces = list(child.pieces)
        by_piece: dict[int, dict] = {}
        for (n, k), bs in sorted(offenders.items(), key=lambda kv: kv[0]):
            for d in ERODE:
                got = _clear_after(obj, j, child, n, k, bs, angles, d)
                if got is not None:
                    by_piece.setdefault(n, {})[k] = got
                    break
        for n, replaced in by_piece.items():
            pieces[n] = pieces[n].with_convex(replaced)
        links[child.name] = replace(child, pieces=pieces)
        obj = replace(obj, links=[links[link.name] for link in obj.links])
    return obj


__all__ = ["MEETING_GAP", "keep_meeting_gaps"]
