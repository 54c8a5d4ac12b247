"""Convex hulls of point sets: the collision shapes of pieces.

:func:`hull_indices` checks the point layouts the primitives make (a box's 8 corners, a shell
wedge's 16 points) against their known hull before calling Qhull (scipy's runner, without the
ConvexHull wrapper's bookkeeping); hulls come back as ``(vertices (k, 3), outward faces (f, 3))``.
Also the corner order and shared faces of an axis-aligned box (its own hull) and the PhysX limit
of :data:`MAX_HULL_VERTICES`.
"""

from __future__ import annotations

import math

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from .triangles import _YZX, _ZXY, _norm, triangle_cross


def _quads(*quads) -> list[tuple[int, int, int]]:
    return [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def _fan(*ring) -> list[tuple[int, int, int]]:
    return [(ring[0], ring[i], ring[i + 1]) for i in range(1, len(ring) - 1)]


_BOX_CORNERS = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
_BOX_CORNERS.flags.writeable = False
_BOX_FACES = np.array([[1, 3, 0], [4, 1, 0], [0, 3, 2], [2, 4, 0], [1, 7, 3], [5, 1, 4],
                       [5, 7, 1], [3, 7, 2], [6, 4, 2], [2, 7, 6], [6, 5, 4], [7, 5, 6]])
_BOX_FACES.flags.writeable = False  # shared by every box piece (read-only, like every piece's faces)


def _box_arrays(size: np.ndarray, center: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """An axis-aligned box: 8 corners (in trimesh.creation.box order) and 12 outward triangles
    (the shared read-only :data:`_BOX_FACES`)."""
    return _BOX_CORNERS * size + center, _BOX_FACES


# Hull faces of the point layouts the primitives produce, tried before Qhull and kept only
# when every point lies inside every face plane (so a wrong guess costs a check, never a
# wrong hull).  8: the corners of a box in _box_arrays order (index bits x, y, z).
# 16: a wedge of a shell band, 4 angles x (outer bottom, outer top, inner bottom, inner top):
# the inner points between the two end angles lie inside the hull.
_HULL_TEMPLATES = {
    8: np.array(_quads((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3))),
    16: np.array(_quads((0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (8, 12, 15, 11), (0, 4, 12, 8), (3, 11, 15, 7))
                 + _fan(0, 1, 2, 3, 11, 8) + _fan(4, 5, 6, 7, 15, 12)),
}


def _template_used(n: int, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    used = np.unique(faces)
    remap = np.full(n, -1)
    remap[used] = np.arange(len(used))
    return used, remap


_TEMPLATE_USED = {n: _template_used(n, f) for n, f in _HULL_TEMPLATES.items()}


def _box_hull(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """:func:`_template_hull` of 8 points that are exactly the corners of an axis-aligned box of
    positive size in :func:`_box_arrays` order, in plain float arithmetic (the answer is then the
    unit box's: every face normal is an axis, no point is outside a face plane, and the faces flip
    alike); None where that is not certain (then the general check decides)."""
    r = pts.tolist()
    (x0, y0, z0), (x1, y1, z1) = r[0], r[7]
    if not (x1 > x0 and y1 > y0 and z1 > z0):
        return None
    for i, (x, y, z) in enumerate(r):
        if x != (x1 if i & 4 else x0) or y != (y1 if i & 2 else y0) or z != (z1 if i & 1 else z0):
            return None
    dx, dy, dz = x1 - x0, y1 - y0, z1 - z0
    scale = max(dx, dy, dz)  # np.ptp(pts, axis=0).max()
    # the general check's face normal lengths are sqrt(0 + 0 + (da * db) ** 2)
    if min(math.sqrt((dx * dy) * (dx * dy)), math.sqrt((dy * dz) * (dy * dz)),
           math.sqrt((dx * dz) * (dx * dz))) <= 1e-12 * scale * scale:
        return None
    cx, cy, cz = (np.add.reduce(pts, 0) / len(pts)).tolist()  # pts.mean(0): faces flip by its side
    if not (x0 < cx < x1 and y0 < cy < y1 and z0 < cz < z1):
        return None
    return _UNIT_BOX_HULL[0].copy(), _UNIT_BOX_HULL[1].copy()


def _template_hull(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """``(used point indices, faces over them)`` from a known layout, or None."""
    if len(pts) == 8:
        known = _box_hull(pts)
        if known is not None:
            return known
    return _checked_template(pts)


def _checked_template(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    faces = _HULL_TEMPLATES.get(len(pts))
    if faces is None:
        return None
    tri = pts[faces]
    normal = triangle_cross(tri)
    length = _norm(normal)  # np.linalg.norm(normal, axis=1), bit for bit
    scale = float((np.maximum.reduce(pts, 0) - np.minimum.reduce(pts, 0)).max())  # np.ptp(pts, axis=0).max()
    if scale <= 0 or length.min() <= 1e-12 * scale * scale:
        return None
    normal /= length[:, None]
    centre = np.add.reduce(pts, 0) / len(pts)  # pts.mean(0), bit for bit
    flip = np.einsum("ij,ij->i", normal, tri[:, 0] - centre) < 0
    normal[flip] *= -1
    height = (pts @ normal.T) - np.einsum("ij,ij->i", normal, tri[:, 0])  # (points, faces)
    if height.max() > 1e-9 * scale:
        return None
    faces = faces.copy()
    faces[flip] = faces[flip][:, ::-1]
    used, remap = _TEMPLATE_USED[len(pts)]
    return used.copy(), remap[faces]  # _compact(len(pts), faces): the template's points are the used ones


def _outward(pts: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """``faces`` of a convex solid over ``pts``, each flipped to face away from the centroid."""
    tri = pts[faces]
    e1 = tri[:, 1] - tri[:, 0]
    e2 = tri[:, 2] - tri[:, 0]
    normal = e1.take(_YZX, 1) * e2.take(_ZXY, 1) - e1.take(_ZXY, 1) * e2.take(_YZX, 1)  # triangle_cross(tri)
    p = normal * (tri[:, 0] - np.add.reduce(pts, 0) / len(pts))  # pts.mean(0)
    # np.einsum("ij,ij->i", normal, offset) adds (x + z) + y
    inward = ((p[:, 0] + p[:, 2]) + p[:, 1]) < 0
    return np.where(inward[:, None], faces[:, ::-1], faces)


def _compact(n: int, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    used = np.unique(faces)
    remap = np.full(n, -1)
    remap[used] = np.arange(len(used))
    return used, remap[faces]



def hull_indices(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(indices of the points on the hull, outward faces indexing that subset)``.

    The layouts of boxes and shell wedges are checked against their known hull first;
    anything else goes to Qhull (scipy) directly, oriented against the centroid: ~20x
    faster than the general path through ``trimesh.convex``.
    """
    pts = np.asarray(points, float)
    known = _template_hull(pts)
    if known is not None:
        return known
    try:
        simplices = _simplices(pts)
    except QhullError:
        simplices = ConvexHull(pts, qhull_options="QJ").simplices  # degenerate (flat) input: joggle
    used, faces = _compact(len(pts), simplices)
    return used, _outward(pts[used], faces)


def _simplices(pts: np.ndarray) -> np.ndarray:
    """``ConvexHull(pts).simplices``, without the areas, volume and bookkeeping the wrapper adds (a
    third of the time of a small hull): scipy's own Qhull runner with ConvexHull's options, where it
    passed the self-check at import (:data:`_QHULL`), else ConvexHull. Raises ``QhullError`` alike."""
    if _QHULL is None:
        return ConvexHull(pts).simplices
    qhull = _QHULL(b"i", np.ascontiguousarray(pts, dtype=np.float64), b"", required_options=b"Qt")
    try:
        qhull.triangulate()
        return qhull.get_simplex_facet_array()[0]
    finally:
        qhull.close()


def _qhull_runner():
    """scipy's private ``_Qhull`` if it gives ConvexHull's simplices on a test set, else None."""
    try:
        from scipy.spatial._qhull import _Qhull
        pts = np.random.default_rng(0).normal(size=(40, 3))
        qhull = _Qhull(b"i", pts, b"", required_options=b"Qt")
        try:
            qhull.triangulate()
            ok = np.array_equal(qhull.get_simplex_facet_array()[0], ConvexHull(pts).simplices)
        finally:
            qhull.close()
    except Exception:  # another scipy: the public wrapper
        return None
    return _Qhull if ok else None


_QHULL = _qhull_runner()


def hull_arrays(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, faces)`` of the convex hull of a point set, faces outward (:func:`hull_indices`)."""
    pts = np.asarray(points, float)
    used, faces = hull_indices(pts)
    return pts[used], faces


def convex_hull(points: np.ndarray) -> trimesh.Trimesh:
    """The convex hull of a point set as a watertight trimesh with outward faces."""
    return trimesh.Trimesh(*hull_arrays(points), process=False)


MAX_HULL_VERTICES = 255
"""PhysX builds convex meshes of at most 255 vertices."""


def _farthest_points(points: np.ndarray, n: int) -> np.ndarray:
    """``n`` of ``points`` spread out by farthest-point sampling (deterministic: starts at index 0)."""
    chosen = [0]
    d = np.linalg.norm(points - points[0], axis=1)
    for _ in range(n - 1):
        k = int(np.argmax(d))
        chosen.append(k)
        d = np.minimum(d, np.linalg.norm(points - points[k], axis=1))
    return points[chosen]


_UNIT_BOX_HULL = _checked_template(_box_arrays(np.ones(3), np.zeros(3))[0])
"""The hull of every box in :func:`_box_arrays` order (:func:`_box_hull`)."""
