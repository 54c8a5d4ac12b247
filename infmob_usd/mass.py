"""Mass and inertia of links from material density and solid volume, or shell area x wall.

A piece is massed one of three ways (:func:`inertial`):

* **sheet** (``Piece.sheet`` > 0): a panel or tube of sheet modelled solid; its density is scaled
  so the mass is half its surface x the sheet (one face of a panel), the solid's inertia shape;
* **hollow** (``Piece.wall``, else its material family's ``wall``): the closed mesh is the outside
  of a thin shell (a ceramic bowl, a steel tube or casing, a hollow-core door's skins): mass =
  density x wall x area with the shell's own centre of mass and inertia
  (:func:`~infmob_usd.measures.shell_properties`), unless the shell would outweigh the solid (a
  part thinner than two walls, a wire, a thin plate) which is then massed solid;
* **solid**: density x volume.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from .measures import _measure_closed, _solid_parts
from .piece import Piece
from .triangles import _EYE3

DUMMY_MASS = 0.01
"""kg of a dummy link of a compound joint: light, never zero (zero means "compute it")."""

DUMMY_INERTIA = 1e-6
"""kg m^2 on each principal axis of a dummy link."""

DUMMY_CARRY_RATIO = 1e-2
"""A dummy link weighs at least this fraction of the mass it carries (:func:`dummy_masses`). Iterative joint
solvers converge slowly on a light body between heavy ones: Newton's XPBD let a television's 10 g dummy (the
height slide of its post's slide-and-swivel) under 16 kg of post and screen sink 5.4 mm through its stop in
0.5 s; at 0.1 kg 0.46 mm, at 0.5 kg 0.08 mm (measured). The slide's inner tube is what the dummy stands
for, and 1/100 of what a stand carries is what a real one weighs; the object grows by that much."""

MIN_MASS = 0.005
"""kg; no link is lighter (a thin decoration would otherwise make solvers stiff), except in a small
object (:func:`link_floor`)."""

SMALL_SHARE = 0.05
"""A link of an object lighter than ``MIN_MASS / SMALL_SHARE`` (100 g) is floored at this share of the
object's mass instead: a pen's 0.5 g push button or a USB drive's 1 g cap is a twentieth of its 10 g
object, where a 5 g floor would make it half the object and fail its real mass; a twentieth keeps the
ratio of the lightest link to the object that the 5 g floor keeps on a 100 g object."""


LEAST_MASS = 0.001
"""kg; no link of any object is lighter: Isaac Lab's robot doctor warns of a link under 1 g beside heavier
ones (PhysX articulations handle such mass ratios badly, its 'easily bullied bodies'), and a click pen's
button or a lighter's lever, 0.3-1 g in the product, moves the same at 1 g under its spring."""


def link_floor(object_mass: float) -> float:
    """kg: the least mass of a link of an object of ``object_mass`` kg (its links before any floor)."""
    return max(LEAST_MASS, min(MIN_MASS, SMALL_SHARE * object_mass))

MIN_INERTIA = DUMMY_INERTIA
"""kg m^2; no principal moment of a link is smaller."""

CHAIN_INERTIA_RATIO = 1e-2
"""No principal moment of a link is below this fraction of the largest moment of any link it carries.

A thin pole (22 g, 15 mm across: 6e-7 kg m^2 about its axis) between two coaxial joints under a lamp
head and shade of 9e-3 kg m^2 made PhysX's solver lose the drives: in the fuzz's lamp reach failures
the pole's swivel stalled at 73 % of its range and the held head swung 1.5 rad. With the pole at
1e-5 (1/860 of what it carries) every one of them passes; 1/100 leaves a margin. Mass and centre of
mass are unchanged; the added moment acts like a drive's armature, far below what the joint moves."""


def wall_of(piece: Piece, family_wall: float = 0.0) -> float:
    """The wall thickness (m) a piece is massed with as a hollow shell; 0 = not hollow."""
    if piece.sheet > 0:
        return 0.0
    return max(0.0, family_wall if piece.wall is None else piece.wall)


def inertial(pieces: Iterable[tuple], min_mass: float = MIN_MASS) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass (kg), centre of mass ``(3,)`` and inertia tensor ``(3, 3)`` about it.

    ``pieces`` yields ``(piece, density kg/m^3)`` or ``(piece, density, family wall m)`` in one
    common frame. Solids are the closed piece meshes, or their convex collision hulls where a
    mesh is open; hollow pieces (module docstring) are their shells.
    The tensor is made positive definite with a floor relative to its size and never below
    ``MIN_INERTIA`` on a principal axis; a link lighter than ``min_mass`` is scaled up to it.
    """
    masses, coms, tensors = [], [], []
    entries = [(e[0], e[1], wall_of(e[0], e[2] if len(e) > 2 else 0.0)) for e in pieces]
    _measure_closed([(piece, wall > 0) for piece, _, wall in entries])  # closed meshes in one batch
    for piece, density, wall in entries:
        measured = _solid_parts(piece, wall > 0)  # solids (and shells) measured once per piece
        parts = measured[1]
        if wall > 0:
            skins = measured[2]
            area = float(sum(s[0] for s in skins))
            if wall * area < float(sum(abs(s[0]) for s in parts)):
                for a, centroid, unit_inertia in skins:
                    if a <= 1e-12:
                        continue
                    masses.append(density * wall * a)
                    coms.append(centroid)
                    tensors.append(unit_inertia * (density * wall))
                continue
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
        inertia += t + m * (np.dot(d, d) * _EYE3 - d[:, None] * d[None, :])  # np.eye(3), np.outer
    if total < min_mass:
        inertia *= min_mass / total
        total = min_mass
    inertia = 0.5 * (inertia + inertia.T)
    floor = max(MIN_INERTIA, 1e-3 * float(np.trace(inertia)) / 3)
    w, v = np.linalg.eigh(inertia)
    inertia = (v * np.maximum(w, floor)) @ v.T
    return total, com, inertia


def floor_chain_inertia(inertias: dict[str, np.ndarray], children: dict[str, list[str]]) -> dict[str, np.ndarray]:
    """Inertia tensors with every principal moment raised to ``CHAIN_INERTIA_RATIO`` times the
    largest principal moment among the links below it (``children``: link -> child links)."""
    largest: dict[str, float] = {}

    def below(name: str) -> float:  # largest moment of any link under ``name``
        if name not in largest:
            largest[name] = max((max(float(np.linalg.eigvalsh(inertias[c])[-1]), below(c))
                                 for c in children.get(name, ())), default=0.0)
        return largest[name]

    out = {}
    for name, inertia in inertias.items():
        floor = CHAIN_INERTIA_RATIO * below(name)
        w, v = np.linalg.eigh(inertia)
        out[name] = inertia if w[0] >= floor else (v * np.maximum(w, floor)) @ v.T
    return out


def dummy_masses(masses: dict[str, float], children: dict[str, list[str]], dummies: set[str]) -> dict[str, float]:
    """Each dummy link's mass: :data:`DUMMY_MASS`, or :data:`DUMMY_CARRY_RATIO` of the mass of the links below
    it where that is more (``masses``: the links' masses, dummies' included; ``children``: link -> child links)."""
    carried: dict[str, float] = {}

    def below(name: str) -> float:  # mass of every link under ``name``, dummies at their own weight
        if name not in carried:
            carried[name] = sum(weight(c) + below(c) for c in children.get(name, ()))
        return carried[name]

    def weight(name: str) -> float:
        return max(DUMMY_MASS, DUMMY_CARRY_RATIO * below(name)) if name in dummies else masses[name]

    return {name: weight(name) for name in sorted(dummies)}


def principal(inertia: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Principal moments ``(3,)`` and a proper rotation ``(3, 3)`` whose columns are the axes."""
    w, v = np.linalg.eigh(inertia)
    if np.linalg.det(v) < 0:
        v[:, 2] *= -1
    return w, v
