"""Boolean operations on closed trimeshes through manifold3d (exact, robust CSG)."""

from __future__ import annotations

from collections.abc import Sequence

import manifold3d
import numpy as np
import trimesh

from .errors import GeometryError


def _to_manifold(mesh: trimesh.Trimesh) -> manifold3d.Manifold:
    m = manifold3d.Manifold(
        manifold3d.Mesh(
            vert_properties=np.asarray(mesh.vertices, np.float32),
            tri_verts=np.asarray(mesh.faces, np.uint32),
        )
    )
    if m.status() != manifold3d.Error.NoError:
        raise GeometryError(f"mesh is not a closed manifold ({m.status()}); cannot do booleans")
    return m


def _from_manifold(m: manifold3d.Manifold) -> trimesh.Trimesh:
    out = m.to_mesh()
    return trimesh.Trimesh(np.asarray(out.vert_properties[:, :3], float), np.asarray(out.tri_verts), process=False)


def subtract(a: trimesh.Trimesh, cutters: Sequence[trimesh.Trimesh]) -> trimesh.Trimesh:
    """Boolean difference ``a - union(cutters)`` through manifold3d."""
    m = _to_manifold(a)
    for c in cutters:
        m = m - _to_manifold(c)
    return _from_manifold(m)
