"""Mass and inertia of links from material density and solid volume."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from .geometry import Piece, solids

DUMMY_MASS = 0.01
"""kg of a dummy link of a compound joint: light, never zero (zero means "compute it")."""

DUMMY_INERTIA = 1e-6
"""kg m^2 on each principal axis of a dummy link."""

MIN_MASS = 0.005
"""kg; no link is lighter (a thin decoration would otherwise make solvers stiff)."""


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
