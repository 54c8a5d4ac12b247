"""Many triangle soups clipped by their own planes at once, each to exactly what trimesh's
``slice_faces_plane`` gives it one plane at a time.

The grasp search (:mod:`infmob_usd.interaction`) crops a part's triangles to a finger's box for every candidate
pinch and every hand box: thousands of calls on meshes of a few dozen triangles, where the slicer's cost is its
per-call overhead. Here every problem's triangles travel in one array, tagged with the problem they belong to,
and each plane cuts all of them in one pass.

The result is the slicer's, bit for bit: a cut triangle's pieces depend on that triangle alone (its vertices
are read per face; nothing is merged), so which other triangles share the array changes nothing, and every
float is computed by the same operation the slicer uses. numpy's 2-D ``dot`` (BLAS gemv) and its 3-D ``dot``
(BLAS ddot) round a 3-term sum differently (fused multiply-adds in their own order); ``np.vecdot`` calls the
same ddot, and with the terms taken in gemv's order it rounds as gemv does. Which order that is depends on the
BLAS kernel this machine runs, so it is measured at import (:data:`EXACT`); where no order matches (another
BLAS, or a numpy without ``vecdot``) the caller keeps slicing with trimesh one problem at a time.
"""

from __future__ import annotations

import itertools

import numpy as np
from trimesh import triangles as _triangles
from trimesh.constants import tol

_MERGE = tol.merge  # the slicer's tolerance: a vertex within it of the plane is on the plane


def _calibrate() -> tuple[list[int] | None, bool]:
    """The term order in which ``np.vecdot`` rounds a row's dot as numpy's 2-D ``dot`` does, and whether
    ``np.vecdot`` rounds as the 3-D ``dot`` does; ``None`` / ``False`` where nothing matches."""
    if not hasattr(np, "vecdot"):
        return None, False
    rng = np.random.default_rng(7)
    x = rng.normal(size=(512, 3)) * rng.choice([1e-3, 1.0, 1e3], size=(512, 1))
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    rows = np.ascontiguousarray(np.broadcast_to(n, x.shape))
    ddot = bool((np.vecdot(x, rows) == x[:, None, :].dot(n)[:, 0]).all())
    gemv = np.dot(x, n)
    for order in itertools.permutations(range(3)):
        p = list(order)
        if (np.vecdot(x[:, p], rows[:, p]) == gemv).all():
            return p, ddot
    return None, ddot


_GEMV_ORDER, _DDOT = _calibrate()
EXACT = _GEMV_ORDER is not None and _DDOT
"""Whether :func:`clip` and :func:`gemv_rows` reproduce trimesh's and numpy's rounding on this machine."""


def gemv_rows(x: np.ndarray, n: np.ndarray) -> np.ndarray:
    """``x[..., :] . n[..., :]`` row by row (shapes broadcast), each rounded as numpy's 2-D ``x @ n`` rounds
    it (only where :data:`EXACT`)."""
    p = _GEMV_ORDER or [0, 1, 2]
    x, n = np.broadcast_arrays(x, n)
    return np.vecdot(x[..., p], n[..., p])


def _on_plane(tri: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Of triangles lying on their plane, those the slicer keeps: not degenerate, facing against its normal."""
    check, valid = _triangles.normals(tri)
    keep = np.zeros(len(tri), bool)
    keep[np.flatnonzero(valid)] = gemv_rows(check, n[valid]) < 0.0
    return keep


def _slice(tri: np.ndarray, pid: np.ndarray, normal: np.ndarray, origin: np.ndarray):
    """Each triangle ``tri[i]`` (``(m, 3, 3)``) cut by the plane ``(normal[i], origin[i])``, keeping the part on
    the normal's side: ``slice_faces_plane``'s cases and arithmetic, per row. Returns ``(tri, pid)``."""
    dots = gemv_rows(tri - origin[:, None, :], normal[:, None, :])  # the slicer's per-vertex np.dot (gemv)
    signs = np.zeros(dots.shape, np.int8)
    signs[dots < -_MERGE] = 1
    signs[dots > _MERGE] = -1
    ssum, asum = signs.sum(1, dtype=np.int8), np.abs(signs).sum(1, dtype=np.int8)
    onedge = (asum >= 2) & (np.abs(ssum) <= 1)
    inside = ssum == -asum
    flat = np.flatnonzero(asum == 0)
    if len(flat):
        inside[flat] = _on_plane(tri[flat], normal[flat])
    if not onedge.any():
        return tri[inside], pid[inside]
    cut, cpid, csign, csum = tri[onedge], pid[onedge], signs[onedge], ssum[onedge]
    n, o = normal[onedge][:, None, :], origin[onedge][:, None, :]
    d = np.roll(cut, -1, axis=1) - cut
    num = np.vecdot(o - cut, n)  # the slicer's 3-D np.dot (ddot)
    denom = np.vecdot(d, n)
    denom[denom == 0.0] = 1e-12
    hit = (num / denom)[:, :, None] * d + cut  # where each edge i -> i+1 meets the plane
    quad = csum < 0  # one vertex outside: the quad left is two triangles
    rq = np.flatnonzero(quad)
    iq = np.argmax(csign[rq] == 1, axis=1)
    a, b = cut[rq, (iq + 1) % 3], cut[rq, (iq + 2) % 3]
    c, e = hit[rq, (iq + 2) % 3], hit[rq, iq]
    rt = np.flatnonzero(~quad)  # one vertex inside: a triangle
    it = np.argmax(csign[rt] == -1, axis=1)
    one = np.stack([cut[rt, it], hit[rt, it], hit[rt, (it + 2) % 3]], 1)
    out = np.concatenate([tri[inside], np.stack([a, b, c], 1), np.stack([c, e, a], 1), one])
    return out, np.concatenate([pid[inside], cpid[rq], cpid[rq], cpid[rt]])


def clip(tri: np.ndarray, pid: np.ndarray, normals: np.ndarray, origins: np.ndarray):
    """The triangles ``tri`` (``(m, 3, 3)``), each of problem ``pid[i]``, cut by that problem's planes
    ``normals[p, j]``, ``origins[p, j]`` (``(P, J, 3)``) in turn, each keeping the side its normal points to.
    Returns ``(tri, pid)``: every piece left, with its problem (in no promised order)."""
    for j in range(normals.shape[1]):
        if not len(tri):
            break
        tri, pid = _slice(tri, pid, normals[pid, j], origins[pid, j])
    return tri, pid
