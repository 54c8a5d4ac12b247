"""Per-triangle arithmetic on ``(n, 3)`` arrays: row-wise cross products, row lengths, triangle
area vectors, and whether a face array is a closed, consistently oriented mesh.

Small helpers written out in plain NumPy (bit for bit what ``np.cross`` / ``np.linalg.norm`` give,
without their per-call overhead, which dominates for the small arrays of hulls and pieces).
"""

from __future__ import annotations

import numpy as np


def cross_rows(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise cross product of ``(n, 3)`` arrays: ``np.cross`` without its per-call overhead
    (which dominates for the small arrays of hulls)."""
    out = np.empty(a.shape if a.shape == b.shape else np.broadcast_shapes(a.shape, b.shape))
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out


_YZX = np.array([1, 2, 0])
_ZXY = np.array([2, 0, 1])
"""Column orders that make a row-wise cross product two products: ``a.take(_YZX, 1) * b.take(_ZXY, 1)
- a.take(_ZXY, 1) * b.take(_YZX, 1)`` is :func:`cross_rows` of ``(n, 3)`` arrays, bit for bit, and
C-ordered like it (``a[:, _YZX]`` is not, and NumPy's reductions add a layout in another order)."""


def triangle_cross(tri: np.ndarray) -> np.ndarray:
    """``(m, 3)`` cross products of the edges of ``(m, 3, 3)`` triangles (twice their area vectors)."""
    return cross_rows(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])


_EYE3 = np.eye(3)
_EYE3.flags.writeable = False


def _norm(x: np.ndarray) -> np.ndarray:
    """Row lengths of ``(n, 3)`` ``x``, bit for bit ``np.linalg.norm(x, axis=1)``, faster."""
    return np.sqrt(x[:, 0] * x[:, 0] + x[:, 1] * x[:, 1] + x[:, 2] * x[:, 2])


def is_closed(faces: np.ndarray) -> bool:
    """Whether a triangle mesh is closed and consistently oriented: every directed edge
    appears exactly once and so does its reverse (what ``trimesh.is_watertight`` and
    ``is_winding_consistent`` check, without building a Trimesh)."""
    f = faces if type(faces) is np.ndarray and faces.dtype == np.int64 else np.asarray(faces, np.int64)
    if not len(f):
        return False
    n = int(f.max()) + 1
    a, b = f.ravel(), f[:, _NEXT_CORNER].ravel()
    fwd = a * n + b
    fwd.sort()
    if (fwd[1:] == fwd[:-1]).any():
        return False
    bwd = b * n + a
    bwd.sort()
    return bool((fwd == bwd).all())


_NEXT_CORNER = np.array([1, 2, 0])
