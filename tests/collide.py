"""Test helper: intersection volume of two links' convex collision pieces at given poses."""

from __future__ import annotations

import manifold3d
import numpy as np


def _hulls(link, pose):
    out = []
    for piece in link.pieces:
        for v, _f in piece.hulls():
            w = v @ pose[:3, :3].T + pose[:3, 3]
            out.append(w)
    return out


def overlap(link_a, pose_a, link_b, pose_b, pad: float = 0.0) -> float:
    """Total volume (m^3) shared by the convex pieces of two links."""
    total = 0.0
    hb = [(w, w.min(0), w.max(0)) for w in _hulls(link_b, pose_b)]
    for wa in _hulls(link_a, pose_a):
        lo_a, hi_a = wa.min(0) - pad, wa.max(0) + pad
        ma = None
        for wb, lo_b, hi_b in hb:
            if np.any(hi_a < lo_b) or np.any(hi_b < lo_a):
                continue
            ma = ma or manifold3d.Manifold.hull_points(wa)
            total += (ma ^ manifold3d.Manifold.hull_points(wb)).volume()
    return total


def contacts(bp, q=None, tol: float = 1e-7, skip=None) -> list[tuple[str, str, float]]:
    """``(a, b, volume)`` of the blueprint's part pairs sharing ``tol`` m^3 or more with its joints at
    ``q`` (:meth:`~infmob_usd.blueprint.Blueprint.poses` keys). Parent and child are skipped, and any
    pair for which ``skip(a, b)`` is true."""
    pose = bp.poses(q)
    parent = {j.child: j.parent for j in bp.joints}
    names = list(bp.parts)
    bad = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if parent.get(a) == b or parent.get(b) == a or (skip is not None and skip(a, b)):
                continue
            v = overlap(bp.parts[a], pose[a], bp.parts[b], pose[b])
            if v >= tol:
                bad.append((a, b, v))
    return bad
