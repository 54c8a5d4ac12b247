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
]

