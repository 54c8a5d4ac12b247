"""The geometry kernel's authoring API: what a category builds its parts with.

A :class:`Piece` is one triangle mesh in world coordinates (metres, Z up) with the name of the
material slot it is painted with and, where construction tells them, its exact convex collision
pieces (a panel is a box, a knob a cylinder). Every builder takes plain numbers or ``(3,)`` arrays
and returns a ``Piece``. Categories write ``from infmob_usd import geometry as g`` and ``g.box_between``,
``g.cylinder``, ``g.shell``...: this module names that vocabulary in one place (:data:`__all__`).

The kernel itself is split by topic into flat sibling modules, which the core, the writers and
the tests import directly:

* :mod:`~infmob_usd.piece` -- the value type :class:`Piece` and its per-piece caches;
* :mod:`~infmob_usd.primitives` -- boxes, panels with holes, cylinders, discs, tubes, spheres,
  solids and thin walls of revolution, and their ``(vertices, faces)`` arrays;
* :mod:`~infmob_usd.profiles` -- section counts round a radius, profile thinning, collision bands
  and wedges of walls of revolution;
* :mod:`~infmob_usd.hulls` -- convex hulls (known layouts, then Qhull);
* :mod:`~infmob_usd.measures` -- volume, area, centroid and inertia of closed meshes (solid, shell);
* :mod:`~infmob_usd.shading` -- grain frames, per-corner normals and UVs;
* :mod:`~infmob_usd.booleans` -- CSG through manifold3d;
* :mod:`~infmob_usd.triangles` -- row-wise cross products and lengths, closed-mesh test.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .booleans import subtract
from .hulls import convex_hull, hull_arrays
from .piece import Piece, from_trimesh
from .primitives import (
    box,
    box_arrays,
    box_between,
    cylinder,
    cylinder_arrays,
    disc,
    instances,
    panel,
    revolve,
    revolve_arrays,
    shell,
    sphere,
    tube,
)
from .profiles import collision_bands, sections_for, simplify_profile, wedge_points
from .rotation import rotation_between

__all__ = [
    "Piece", "from_trimesh",
    "box", "box_between", "panel", "cylinder", "disc", "tube", "sphere", "revolve", "shell",
    "box_arrays", "cylinder_arrays", "revolve_arrays", "instances",
    "sections_for", "simplify_profile", "collision_bands", "wedge_points",
    "convex_hull", "hull_arrays", "subtract", "rotation_between",
    "bar_handle", "knob_handle", "pull_handle",
]


# ---------------------------------------------------------------------------
# handles: built on a face with outward normal ``normal`` (unit axis vector)


def bar_handle(anchor: Sequence[float], normal: Sequence[float], along: Sequence[float], length: float,
               material: str, standoff: float = 0.03, radius: float = 0.006) -> list[Piece]:
    """A bar pull: two posts out of the face and a bar between them.

    ``anchor`` is the centre of the handle on the face; ``along`` the bar direction.
    """
    anchor, n, d = (np.asarray(x, float) for x in (anchor, normal, along))
    half = d * length / 2
    inset = d * min(0.02, length * 0.15)
    pieces = []
    for end in (anchor - half + inset, anchor + half - inset):
        pieces.append(cylinder(end, end + n * standoff, radius * 0.8, material, 12, name="handle"))
    bar_c = anchor + n * (standoff + radius)
    pieces.append(cylinder(bar_c - half, bar_c + half, radius, material, 16, name="handle"))
    return pieces


def knob_handle(anchor: Sequence[float], normal: Sequence[float], material: str, radius: float = 0.015,
                depth: float = 0.025) -> list[Piece]:
    """A round knob: a stem and a wider cap."""
    anchor, n = np.asarray(anchor, float), np.asarray(normal, float)
    stem = cylinder(anchor, anchor + n * depth * 0.6, radius * 0.45, material, 16, name="handle")
    cap = cylinder(anchor + n * depth * 0.55, anchor + n * depth, radius, material, 24, name="handle")
    return [stem, cap]


def pull_handle(anchor: Sequence[float], normal: Sequence[float], along: Sequence[float], length: float,
                material: str, depth: float = 0.018, lip: float = 0.012) -> list[Piece]:
    """A low-profile edge pull (the "recessed" style): a flat lip standing off the face."""
    anchor, n, d = (np.asarray(x, float) for x in (anchor, normal, along))
    side = np.cross(n, d)
    corners = []
    for s in (-1, 1):
        for t in (0, 1):
            for w in (-1, 1):
                corners.append(anchor + d * s * length / 2 + n * depth * t + side * w * lip / 2)
    mesh = convex_hull(np.array(corners))
    return [from_trimesh(mesh, material, name="handle")]
