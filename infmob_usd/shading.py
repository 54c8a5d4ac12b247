"""How a piece is shaded: per face-corner normals (smooth below a crease angle, split above) and
UVs box-projected in the piece's grain frame at one texel density for every piece.

:func:`grain_frame` gives a mesh's ``(3, 3)`` frame (columns long, across, thin) so wood grain and
brushing run along a leg, a rail or a door leaf; :func:`corner_attributes` gives ``(3m, 3)`` normals
and ``(3m, 2)`` UVs of ``(m, 3)`` faces, :data:`UV_TILE` metres per texture repeat.
"""

from __future__ import annotations

import math

import numpy as np

from .triangles import _norm, triangle_cross

UV_TILE = 0.5
"""Metres of surface covered by one repeat of a texture (the materials room synthesises
its maps at this scale: ``infmob_usd.materials.synth.TILE_METRES``)."""


CREASE_DEG = 35.0
"""Edges sharper than this get split normals."""


_COS_CREASE = math.cos(math.radians(CREASE_DEG))
# faces all within half the crease angle of one direction are pairwise within it (a hair
# tighter, so rounding never lets a creased vertex through)
_COS_HALF = math.cos(math.radians(CREASE_DEG / 2 - 0.01))


_SNAP = math.cos(math.radians(10.0))


def _snap(axis: list[float]) -> list[float]:
    """A unit direction ``[x, y, z]``, replaced by the nearest world axis (same sense) within 10 degrees."""
    k = _argabsmax(axis)
    if abs(axis[k]) >= _SNAP:
        out = [0.0, 0.0, 0.0]
        out[k] = math.copysign(1.0, axis[k])
        return out
    return axis


def _argabsmax(a) -> int:
    """``int(np.abs(a).argmax())`` of 3 floats (the first of equals)."""
    x, y, z = abs(a[0]), abs(a[1]), abs(a[2])
    return 0 if x >= y and x >= z else (1 if y >= z else 2)


def _argabsmin(a) -> int:
    """``int(np.abs(a).argmin())`` of 3 floats (the first of equals)."""
    x, y, z = abs(a[0]), abs(a[1]), abs(a[2])
    return 0 if x <= y and x <= z else (1 if y <= z else 2)


def _across(a: list[float], b: list[float]) -> tuple[list[float], float]:
    """``a`` less its part along the unit ``b``, and the length of what is left (in floats, the same
    bits as NumPy's ``a - b * float(a @ b)`` and ``sqrt(float(r @ r))`` on ``(3,)`` arrays)."""
    d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    r = [a[0] - b[0] * d, a[1] - b[1] * d, a[2] - b[2] * d]
    return r, math.sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2])


_AXES = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def grain_frame(vertices: np.ndarray) -> np.ndarray:
    """``(3, 3)`` orthonormal frame of a piece, columns ``(long, across, thin)``.

    ``long`` is the piece's longest direction (the first principal axis of its vertices,
    or, where two are about as long, the world axis of its largest extent), ``thin`` its
    thinnest (for a round section, the world axis most across ``long``); axes within 10
    degrees of a world axis are snapped to it.  UVs are box-projected in this frame with U
    along ``long`` wherever a face allows it, so grain and brushing follow legs, rails,
    door leaves and handles instead of the world's X axis.  An axis-aligned box whose
    longest side is along X gets the identity (the plain world box projection).
    NumPy does the sums over the vertices; the 3-vectors are plain floats (this runs for
    every piece of every object, where NumPy's per-call overhead would dominate).
    """
    v = vertices if type(vertices) is np.ndarray and vertices.dtype == np.float64 else np.asarray(vertices, float)
    if len(v) > 4096:  # the principal axes of a large mesh are those of a spread-out sample
        v = v[:: len(v) // 2048]
    n = len(v)
    if n >= 256:  # column by column: a strided axis-0 reduction is many times slower
        ext = [float(v[:, k].max() - v[:, k].min()) for k in range(3)]
    else:
        ext = (np.maximum.reduce(v, 0) - np.minimum.reduce(v, 0)).tolist()
    c = v - np.add.reduce(v, 0) / n  # v - v.mean(0), bit for bit
    cov = c.T @ c / max(n, 1)
    (c00, c01, c02), (_, c11, c12), (_, _, c22) = cov.tolist()
    if abs(c01) + abs(c02) + abs(c12) <= 1e-9 * (c00 + c11 + c22):
        diag = (c00, c11, c22)
        order = sorted(range(3), key=diag.__getitem__)  # already axis-aligned: no eigensolver (stable)
        w = [diag[k] for k in order]
        cols = [_AXES[k] for k in order]  # the eigenvectors
    else:
        w, vec = np.linalg.eigh(cov)  # ascending
        w, cols = w.tolist(), vec.T.tolist()
    if w[2] <= 1.15 * w[1]:  # no single long direction: the widest world axis (ties: X, then Y)
        top = max(ext) * (1 - 1e-6)
        long = [0.0, 0.0, 0.0]
        long[0 if ext[0] >= top else (1 if ext[1] >= top else 2)] = 1.0
    else:
        col = cols[2]
        s = math.copysign(1.0, col[_argabsmax(col)])
        long = _snap([col[0] * s, col[1] * s, col[2] * s])
    if w[1] <= 1.15 * w[0]:  # a round section: the world axis most across the long one
        thin = [0.0, 0.0, 0.0]
        thin[_argabsmin(long)] = 1.0
    else:
        col = cols[0]
        s = math.copysign(1.0, col[_argabsmax(col)])
        thin = [col[0] * s, col[1] * s, col[2] * s]
    thin, norm = _across(thin, long)
    if norm < 1e-6:  # degenerate: any axis across
        thin = [0.0, 0.0, 0.0]
        thin[_argabsmin(long)] = 1.0
        thin, norm = _across(thin, long)
    thin, norm = _across(_snap([thin[0] / norm, thin[1] / norm, thin[2] / norm]), long)
    t0, t1, t2 = thin[0] / norm, thin[1] / norm, thin[2] / norm
    l0, l1, l2 = long
    return np.array([[l0, t1 * l2 - t2 * l1, t0],  # columns long, thin x long, thin
                     [l1, t2 * l0 - t0 * l2, t1],
                     [l2, t0 * l1 - t1 * l0, t2]])


def corner_attributes(vertices: np.ndarray, faces: np.ndarray,
                      frames: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Per face-corner normals ``(3m, 3)`` and UVs ``(3m, 2)`` of a mesh.

    Each corner averages (area-weighted) the normals of the faces around its vertex that
    lie within :data:`CREASE_DEG` of its own face; UVs are box-projected, :data:`UV_TILE`
    metres per repeat, in each face's frame (``frames``, ``(m, 3, 3)`` with columns
    ``(long, across, thin)`` from :func:`grain_frame` of the face's piece; default the world
    axes): U runs along ``long`` on every face but the end faces across it.  A mesh made of
    several pieces (which share no vertices) gives each
    piece's own values, so the writers call it once per object.  Fast on large meshes: a
    vertex whose faces all lie within ``CREASE_DEG / 2`` of their area-weighted mean keeps
    every neighbour, so its corners take that plain area-weighted sum
    (``np.bincount`` adds in corner order, as the pairwise ``np.add.at`` does), normalised
    once per vertex; only the corners of crease vertices are compared pairwise, batched
    by valence.
    """
    tri = vertices[faces]
    cross = triangle_cross(tri)
    length = _norm(cross)[:, None]
    fn = cross / np.where(length > 0, length, 1.0)  # unit face normals
    weighted = fn * (0.5 * length)  # area-weighted
    vert = faces.ravel()  # vertex of each corner; corner c belongs to face c // 3
    nv = len(vertices)
    total = np.stack([np.bincount(vert, np.repeat(weighted[:, d], 3), nv) for d in range(3)], 1)
    tlen = _norm(total)[:, None]
    vn = total / np.maximum(tlen, 1e-15)  # the normal of a corner keeping every face of its vertex
    # a vertex is a crease unless all its faces are within CREASE_DEG / 2 of vn (then they
    # are pairwise within CREASE_DEG); a vertex without area (vn ~ 0) is a crease too
    around = vn[faces]  # (m, 3, 3): per corner, the normal of its vertex
    dots = (fn[:, None, 0] * around[..., 0] + fn[:, None, 1] * around[..., 1]
            + fn[:, None, 2] * around[..., 2]).ravel()
    crease = np.zeros(nv, bool)
    crease[vert[dots < _COS_HALF]] = True
    crease[tlen[:, 0] <= 1e-15] = True  # no area around the vertex: face normals, pairwise
    normals = around.reshape(-1, 3)
    creased = np.flatnonzero(crease[vert])
    if len(creased):
        cv = vert[creased]
        order = creased[np.argsort(cv, kind="stable")]
        counts = np.bincount(cv, minlength=nv)
        start = np.cumsum(counts) - counts
        for k in np.unique(counts[counts > 0]):
            vs = np.flatnonzero(counts == k)
            c = order[start[vs][:, None] + np.arange(k)].ravel()  # corners of each vertex, ascending
            cf = c // 3
            n = fn[cf]
            x, y, z = (n[:, d].reshape(len(vs), k) for d in range(3))
            keep = (x[:, :, None] * x[:, None] + y[:, :, None] * y[:, None] + z[:, :, None] * z[:, None]
                    >= _COS_CREASE)
            acc = (keep.astype(float) @ weighted[cf].reshape(len(vs), k, 3)).reshape(-1, 3)
            alen = _norm(acc)[:, None]
            normals[c] = np.where(alen > 1e-15, acc / np.maximum(alen, 1e-15), n)
    # box-projected UVs in the frame (long, across, thin): (across, thin) on faces facing
    # along the long axis, (long, thin) on faces facing across, (long, across) on the broad
    # faces; with the world axes, (y, z) on X-facing faces, (x, z) on Y-facing, (x, y) on Z-facing
    if frames is not None:
        fn = np.einsum("mi,mij->mj", fn, frames)
        tri = np.einsum("mki,mij->mkj", tri, frames)
    axis = np.abs(fn).argmax(1)[:, None]
    uvs = np.stack([np.where(axis == 0, tri[..., 1], tri[..., 0]),
                    np.where(axis == 2, tri[..., 1], tri[..., 2])], -1) / UV_TILE
    return normals, uvs.reshape(-1, 2)


# ---------------------------------------------------------------------------
# helpers
