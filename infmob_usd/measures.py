"""Volume, area, centroid and inertia of closed triangle meshes at unit density, as a solid and as
a thin shell, and of pieces (their mesh if closed, else their collision hulls), cached per piece.

The integrals are written with few NumPy calls (they run for every piece of every object) and
:func:`_measure_closed` measures many pieces in one batch, the same bits as one at a time. Masses
come from these in :mod:`infmob_usd.mass`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .triangles import _EYE3

if TYPE_CHECKING:
    from .piece import Piece


def _relative_triangles(vertices, faces) -> tuple[np.ndarray, np.ndarray]:
    """``(ref, tri)``: the vertex mean and the ``(m, 3, 3)`` triangles relative to it."""
    v = vertices if type(vertices) is np.ndarray and vertices.dtype == np.float64 else np.asarray(vertices, float)
    f = faces if type(faces) is np.ndarray and faces.dtype == np.int64 else np.asarray(faces, np.int64)
    ref = np.add.reduce(v, 0) / len(v)  # v.mean(0), bit for bit, without its wrapper
    return ref, v[f] - ref


def _twice_areas(tri: np.ndarray) -> np.ndarray:
    """``(m,)`` lengths of :func:`~infmob_usd.triangles.triangle_cross` of ``tri`` (bit for bit its
    ``np.linalg.norm``)."""
    e1 = tri[:, 1] - tri[:, 0]
    e2 = tri[:, 2] - tri[:, 0]
    ax, ay, az = e1[:, 0], e1[:, 1], e1[:, 2]
    bx, by, bz = e2[:, 0], e2[:, 1], e2[:, 2]
    x = ay * bz - az * by
    y = az * bx - ax * bz
    z = ax * by - ay * bx
    return np.sqrt(x * x + y * y + z * z)


def mass_properties(vertices: np.ndarray, faces: np.ndarray) -> tuple[float, np.ndarray, np.ndarray, float]:
    """Volume, centroid ``(3,)``, inertia tensor about the centroid at unit density ``(3, 3)``
    and surface area of a closed, outward-oriented triangle mesh.

    Sum over the tetrahedra (reference point, triangle): the second moment of a tetrahedron
    with one vertex at the reference point and edge vectors a, b, c is
    ``det[a b c] / 120 * (a a^T + b b^T + c c^T + s s^T)`` with ``s = a + b + c``.
    """
    ref, tri = _relative_triangles(vertices, faces)
    return _mass_of(ref, tri, _twice_areas(tri))


def _mass_of(ref: np.ndarray, tri: np.ndarray, twice: np.ndarray) -> tuple[float, np.ndarray, np.ndarray, float]:
    """:func:`mass_properties` from :func:`_relative_triangles` and :func:`_twice_areas` (few numpy
    calls: this runs for every piece of every object)."""
    det, s = _dets(tri)
    return _mass_from(ref, tri, twice, det, s, tri * det[:, None, None], s * det[:, None])


def _dets(tri: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per triangle of ``tri`` (relative to a reference point): 6 x the signed volume of its
    tetrahedron and the sum of its corners (row by row, so a batch of meshes gives each mesh's)."""
    t1, t2 = tri[:, 1], tri[:, 2]
    cross = np.empty((len(tri), 3))  # cross_rows(t1, t2)
    cross[:, 0] = t1[:, 1] * t2[:, 2] - t1[:, 2] * t2[:, 1]
    cross[:, 1] = t1[:, 2] * t2[:, 0] - t1[:, 0] * t2[:, 2]
    cross[:, 2] = t1[:, 0] * t2[:, 1] - t1[:, 1] * t2[:, 0]
    return np.einsum("ij,ij->i", tri[:, 0], cross), np.add.reduce(tri, 1)


def _mass_from(ref, tri, twice, det, s, td, sd) -> tuple[float, np.ndarray, np.ndarray, float]:
    """:func:`_mass_of` given :func:`_dets` ``(det, s)``, ``td = tri * det`` and ``sd = s * det``
    (per-triangle arrays: slices of a batch give the same bits)."""
    area = 0.5 * float(np.add.reduce(twice))
    volume = float(np.add.reduce(det)) / 6.0
    if abs(volume) <= 1e-15:
        return 0.0, ref, np.zeros((3, 3)), area
    centroid = (det @ s) / (24.0 * volume)
    second = (td.reshape(-1, 3).T @ tri.reshape(-1, 3) + sd.T @ s) / 120.0
    second -= volume * (centroid[:, None] * centroid[None, :])  # about the centroid
    inertia = (second[0, 0] + second[1, 1] + second[2, 2]) * _EYE3 - second
    return volume, centroid + ref, inertia, area


def shell_properties(vertices: np.ndarray, faces: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """Area, area centroid ``(3,)`` and inertia tensor about it per unit of surface mass ``(3, 3)``
    of a triangle mesh: the mass properties of a thin shell of uniform wall (mass = density x
    wall x area).

    Per triangle with corners ``p_i`` (from a reference point) and area ``a``, the second moment
    is ``a / 12 * (sum p_i p_i^T + s s^T)`` with ``s = sum p_i``.
    """
    ref, tri = _relative_triangles(vertices, faces)
    return _shell_of(ref, tri, _twice_areas(tri))


def _shell_of(ref: np.ndarray, tri: np.ndarray, twice: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """:func:`shell_properties` from :func:`_relative_triangles` and :func:`_twice_areas`."""
    a = 0.5 * twice  # (m,)
    s = np.add.reduce(tri, 1)
    return _shell_from(ref, tri, a, s, tri * a[:, None, None], s * a[:, None])


def _shell_from(ref, tri, a, s, ta, sa) -> tuple[float, np.ndarray, np.ndarray]:
    """:func:`_shell_of` given the areas ``a``, corner sums ``s``, ``ta = tri * a`` and ``sa = s * a``
    (per-triangle arrays: slices of a batch give the same bits)."""
    area = float(np.add.reduce(a))
    if area <= 1e-15:
        return 0.0, ref, np.zeros((3, 3))
    centroid = (a @ s) / (3.0 * area)
    second = (ta.reshape(-1, 3).T @ tri.reshape(-1, 3) + sa.T @ s) / 12.0
    second -= area * (centroid[:, None] * centroid[None, :])
    inertia = (second[0, 0] + second[1, 1] + second[2, 2]) * _EYE3 - second
    return area, centroid + ref, inertia


def _measured(vertices, faces) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    ref, tri = _relative_triangles(vertices, faces)
    return ref, tri, _twice_areas(tri)


def _solid_parts(piece: Piece, with_shells: bool = False) -> tuple:
    """``(meshes, properties)``: the closed meshes a piece's mass comes from (its mesh if closed, with
    volume, else its hulls) and their :func:`mass_properties`; with ``with_shells`` a third entry,
    their :func:`shell_properties`. Computed once per piece (the piece is immutable, so the cache
    never goes stale); solids and shells share their triangles when computed together."""
    memo = piece.__dict__.get("_solids")
    if memo is not None and (len(memo) == 3 or not with_shells):
        return memo
    if memo is None:
        meshes = None
        if piece.closed():
            whole = _measured(piece.vertices, piece.faces)
            props = _mass_of(*whole)
            if props[0] > 1e-12:
                meshes, measured, solid = ((piece.vertices, piece.faces),), [whole], (props,)
        if meshes is None:
            meshes = tuple(piece.hulls())
            measured = [_measured(v, f) for v, f in meshes]
            solid = tuple(_mass_of(*m) for m in measured)
    else:
        meshes, solid = memo
        measured = [_measured(v, f) for v, f in meshes]
    memo = (meshes, solid, tuple(_shell_of(*m) for m in measured)) if with_shells else (meshes, solid)
    object.__setattr__(piece, "_solids", memo)  # a cache of a pure function of the value
    return memo


def _measure_closed(entries: list[tuple[Piece, bool]]) -> None:
    """:func:`_solid_parts` of the closed pieces among ``(piece, with_shells)`` pairs, measured as one
    batch: the per-triangle arrays of all their meshes are made at once and each mesh's sums and
    products are taken over its slice (the same bits as one mesh at a time: NumPy's sums and BLAS give
    a slice what they give a fresh array). Pieces measured already, open ones and closed ones
    without volume are left to :func:`_solid_parts`."""
    todo = [(p, w) for p, w in entries if "_solids" not in p.__dict__ and p.closed()]
    if len(todo) < 2:
        return
    refs, tris, bounds = [], [], [0]
    for p, _ in todo:
        ref, tri = _relative_triangles(p.vertices, p.faces)
        refs.append(ref)
        tris.append(tri)
        bounds.append(bounds[-1] + len(tri))
    tri = np.concatenate(tris)
    twice = _twice_areas(tri)
    det, s = _dets(tri)
    td, sd = tri * det[:, None, None], s * det[:, None]
    if any(w for _, w in todo):
        a = 0.5 * twice
        ta, sa = tri * a[:, None, None], s * a[:, None]
    for k, (p, w) in enumerate(todo):
        lo, hi = bounds[k], bounds[k + 1]
        props = _mass_from(refs[k], tri[lo:hi], twice[lo:hi], det[lo:hi], s[lo:hi], td[lo:hi], sd[lo:hi])
        if props[0] > 1e-12:
            memo = (((p.vertices, p.faces),), (props,))
            if w:
                memo += ((_shell_from(refs[k], tri[lo:hi], a[lo:hi], s[lo:hi], ta[lo:hi], sa[lo:hi]),),)
            object.__setattr__(p, "_solids", memo)  # a cache of a pure function of the value


def solids(piece: Piece) -> list[tuple[float, np.ndarray, np.ndarray, float]]:
    """Mass properties of the solids of a piece: its mesh if closed, else its convex hulls."""
    return list(_solid_parts(piece)[1])


def shells(piece: Piece) -> list[tuple[float, np.ndarray, np.ndarray]]:
    """:func:`shell_properties` of the same closed meshes :func:`solids` measures."""
    return list(_solid_parts(piece, True)[2])
