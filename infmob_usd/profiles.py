"""Round shapes sampled as finely as they need: the section count round a radius, profile curves
thinned to a tolerance, and the collision bands and flat-faced wedges of walls of revolution.

Profiles are ``(p, 2)`` arrays of ``(radius, z)`` points about +Z (metres).
"""

from __future__ import annotations

import math

import numpy as np

CHORD_TOL = 0.0004
"""Metres a round surface's facets may fall inside the true circle (the sagitta of one section):
:func:`sections_for` picks the fewest sections round a radius that keep to it. Normals are smooth,
so a silhouette reads round at this tolerance (0.4 mm: under a pixel of a 512 px picture of a
30 cm object)."""


PROFILE_TOL = 0.0002
"""Metres a simplified profile curve may stray from the curve it thins (:func:`simplify_profile`)."""


BAND_TOL = 0.0005
"""Metres a shell's collision band may stray from its profile where :func:`~infmob_usd.primitives.shell` merges nearly
collinear bands into one."""


def sections_for(radius: float, tol: float = CHORD_TOL, lo: int = 12, hi: int = 64) -> int:
    """The fewest sections round ``radius`` whose facets stay within ``tol`` of the circle (sagitta
    ``r (1 - cos(pi / n)) <= tol``), rounded up to a multiple of 4 (so quarter turns fall on a
    section) and clamped to ``[lo, hi]``: 12 round a wire or a 1 cm knob (fewer would turn more than
    :data:`~infmob_usd.shading.CREASE_DEG` from face to face and be drawn flat-shaded), 24 round a
    3.5 cm bottle, 36 round a 10 cm vase, 64 from a 30 cm table top on."""
    radius = float(radius)
    if radius <= tol:
        return int(lo)
    n = math.pi / math.acos(1.0 - tol / radius)
    return int(min(hi, max(lo, 4 * math.ceil(n / 4 - 1e-9))))


def simplify_profile(points, tol: float = PROFILE_TOL, max_turn: float = 20.0) -> np.ndarray:
    """The fewest of ``(p, 2)`` polyline points that keep the curve within ``tol`` (Douglas-Peucker)
    and turn at most ``max_turn`` degrees over any one kept segment (so a curve that was smooth
    still gets smooth normals, :data:`~infmob_usd.shading.CREASE_DEG`). The first and last points are kept."""
    pts = np.asarray(points, float)
    if len(pts) < 3:
        return pts.copy()
    d = np.diff(pts, axis=0)
    heading = np.unwrap(np.arctan2(d[:, 1], d[:, 0]))
    turn = np.r_[0.0, np.cumsum(np.abs(np.diff(heading)))]  # turn[k]: total turning before segment k
    limit = math.radians(max_turn)
    keep = np.zeros(len(pts), bool)
    keep[[0, -1]] = True
    stack = [(0, len(pts) - 1)]
    while stack:
        i, j = stack.pop()
        if j - i < 2:
            continue
        a, b = pts[i], pts[j]
        ab = b - a
        L = float(np.hypot(*ab))
        mid = pts[i + 1:j]
        if L < 1e-12:
            dist = np.hypot(*(mid - a).T)
        else:
            dist = np.abs(ab[0] * (mid[:, 1] - a[1]) - ab[1] * (mid[:, 0] - a[0])) / L
        k = int(np.argmax(dist))
        if dist[k] > tol or turn[j - 1] - turn[i] > limit:
            m = i + 1 + k if dist[k] > tol else (i + j) // 2
            keep[m] = True
            stack += [(i, m), (m, j)]
    return pts[keep]


def collision_bands(profile, tol: float = BAND_TOL) -> np.ndarray:
    """The points of a ``(p, 2)`` ``(radius, z)`` wall profile that bound its collision bands: a point
    whose neighbours' chord passes within ``tol`` of it is dropped (the bands on either side collide
    as one), so a straight wall sampled at many points collides as one band, a curve keeps a band per
    turn. The ends are always kept."""
    pts = np.asarray(profile, float)
    if len(pts) < 3:
        return pts
    keep = [0]
    for i in range(1, len(pts) - 1):
        a, b = pts[keep[-1]], pts[i + 1]
        ab = b - a
        span = pts[keep[-1] + 1:i + 1]  # every point the merged band would skip
        L = float(np.hypot(*ab))
        dist = np.abs(ab[0] * (span[:, 1] - a[1]) - ab[1] * (span[:, 0] - a[0])) / max(L, 1e-12)
        if dist.max() > tol:
            keep.append(i)
    keep.append(len(pts) - 1)
    return pts[keep]


def wedge_points(outer, inner, sectors: int, phase: float = 0.0) -> np.ndarray:
    """``(bands, sectors, 8, 3)`` corners of flat-faced wedges of a wall of revolution about +Z.

    ``outer`` and ``inner`` are matching ``(p, 2)`` ``(radius, z)`` profiles; corner ``b * 2 + a``
    of a wedge is band corner ``b`` (outer low, outer high, inner low, inner high) at sector
    edge ``a``, the edges at ``phase + 2 pi s / sectors``.
    """
    outer, inner = np.asarray(outer, float), np.asarray(inner, float)
    ang = phase + 2 * np.pi * np.arange(sectors + 1) / sectors
    cs, sn = np.cos(ang), np.sin(ang)
    edges_c, edges_s = np.stack([cs[:-1], cs[1:]], 1)[:, None, :], np.stack([sn[:-1], sn[1:]], 1)[:, None, :]
    bands = []
    for i in range(len(outer) - 1):
        ring = np.array([outer[i], outer[i + 1], inner[i], inner[i + 1]])  # (4, 2)
        r, z = ring[None, :, 0, None], ring[None, :, 1, None]
        pts = np.stack([r * edges_c, r * edges_s, np.broadcast_to(z, (sectors, 4, 2))], -1)  # (sectors, 4, 2, 3)
        bands.append(pts.reshape(sectors, 8, 3))
    return np.array(bands).reshape(len(bands), sectors, 8, 3)
