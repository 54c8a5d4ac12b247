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
