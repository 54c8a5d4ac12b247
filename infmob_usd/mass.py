"""Mass and inertia of links from material density and solid volume."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from .geometry import Piece, cross_rows, triangle_cross

DUMMY_MASS = 0.01
"""kg of a dummy link of a compound joint: light, never zero (zero means "compute it")."""

DUMMY_INERTIA = 1e-6
"""kg m^2 on each principal axis of a dummy link."""

MIN_MASS = 0.005
"""kg; no link is lighter (a thin decoration would otherwise make solvers stiff)."""


def is_closed(faces: np.ndarray) -> bool:
    """Whether a triangle mesh is closed and consistently oriented: every directed edge
    appears exactly once and so does its reverse (what ``trimesh.is_watertight`` and
    ``is_winding_consistent`` check, without building a Trimesh)."""
    f = np.asarray(faces, np.int64)
    if not len(f):
        return False
    n = int(f.max()) + 1
    a, b = f.ravel(), f[:, [1, 2, 0]].ravel()
    fwd = np.sort(a * n + b)
    if (fwd[1:] == fwd[:-1]).any():
        return False
    return bool(np.array_equal(fwd, np.sort(b * n + a)))


def mass_properties(vertices: np.ndarray, faces: np.ndarray) -> tuple[float, np.ndarray, np.ndarray, float]:
    """Volume, centroid ``(3,)``, inertia tensor about the centroid at unit density ``(3, 3)``
    and surface area of a closed, outward-oriented triangle mesh.

    Sum over the tetrahedra (reference point, triangle): the second moment of a tetrahedron
    with one vertex at the reference point and edge vectors a, b, c is
    ``det[a b c] / 120 * (a a^T + b b^T + c c^T + s s^T)`` with ``s = a + b + c``.
    """
    v = np.asarray(vertices, float)
    ref = v.mean(0)  # close to the solid: no cancellation for parts far from the origin
    tri = v[np.asarray(faces, np.int64)] - ref  # (m, 3, 3)
    cross = cross_rows(tri[:, 1], tri[:, 2])
    det = np.einsum("ij,ij->i", tri[:, 0], cross)  # 6 x signed tetra volume
    area = 0.5 * float(np.linalg.norm(triangle_cross(tri), axis=1).sum())
    volume = float(det.sum()) / 6.0
    if abs(volume) <= 1e-15:
        return 0.0, ref, np.zeros((3, 3)), area
    s = tri.sum(1)  # (m, 3)
    centroid = (det @ s) / (24.0 * volume)
    corners = tri.reshape(-1, 3)
    second = ((corners * np.repeat(det, 3)[:, None]).T @ corners + (s * det[:, None]).T @ s) / 120.0
    second -= volume * np.outer(centroid, centroid)  # about the centroid
    inertia = np.trace(second) * np.eye(3) - second
    return volume, centroid + ref, inertia, area


def solids(piece: Piece) -> list[tuple[float, np.ndarray, np.ndarray, float]]:
    """Mass properties of the solids of a piece: its mesh if closed, else its convex hulls."""
    if is_closed(piece.faces):
        props = mass_properties(piece.vertices, piece.faces)
        if props[0] > 1e-12:
            return [props]
    return [mass_properties(v, f) for v, f in piece.hulls()]


def inertial(pieces: Iterable[tuple[Piece, float]]) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass (kg), centre of mass ``(3,)`` and inertia tensor ``(3, 3)`` about it.

    ``pieces`` yields ``(piece, density kg/m^3)`` in one common frame. Solids are
    the closed piece meshes, or their convex collision hulls where a mesh is open.
    The tensor is made positive definite with a floor relative to its size.
    """
    masses, coms, tensors = [], [], []
    for piece, density in pieces:
        parts = solids(piece)
        if piece.sheet > 0:
            # a part made of sheet (a casing panel, a tube) modelled solid: its wall is about half
            # the solid's surface (one face of a panel, the outside of a tube) times the sheet
            area = 0.5 * float(sum(s[3] for s in parts))
            solid_vol = float(sum(abs(s[0]) for s in parts))
            density = density * min(1.0, area * piece.sheet / max(solid_vol, 1e-12))
        for vol, centroid, unit_inertia, _area in parts:
            if abs(vol) <= 1e-12:
                continue
            m = density * abs(vol)
            masses.append(m)
            coms.append(centroid)
            tensors.append(unit_inertia * (density * np.sign(vol)))
    if not masses:
        return DUMMY_MASS, np.zeros(3), np.eye(3) * DUMMY_INERTIA
    total = float(sum(masses))
    com = np.sum([m * c for m, c in zip(masses, coms)], axis=0) / total
    inertia = np.zeros((3, 3))
    for m, c, t in zip(masses, coms, tensors):
        d = c - com
        inertia += t + m * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
    if total < MIN_MASS:
        inertia *= MIN_MASS / total
        total = MIN_MASS
    inertia = 0.5 * (inertia + inertia.T)
    floor = max(1e-8, 1e-3 * float(np.trace(inertia)) / 3)
    w, v = np.linalg.eigh(inertia)
    inertia = (v * np.maximum(w, floor)) @ v.T
    return total, com, inertia


def principal(inertia: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Principal moments ``(3,)`` and a proper rotation ``(3, 3)`` whose columns are the axes."""
    w, v = np.linalg.eigh(inertia)
    if np.linalg.det(v) < 0:
        v[:, 2] *= -1
    return w, v
