"""Facts every writer reads the same way."""

from __future__ import annotations

import numpy as np

# PartNet-Mobility joint type of each declared joint kind (semantics.txt)
PM_JOINT_TYPE = {
    "fixed": "static",
    "revolute": "hinge",
    "continuous": "hinge",
    "flip_revolute": "hinge",
    "prismatic": "slider",
    "revolute_prismatic": "hinge",
    "continuous_prismatic": "hinge",
    "limited_planar": "free",
    "limited_floating": "free",
}


def visual_groups(link):
    """Pieces of a link grouped into visual meshes: ``(name, slot, pieces, role)``.

    One mesh per (role, material slot); ``role`` is a piece name such as
    ``"handle"`` (kept in the visual name, as ManiSkill looks for it) or ``""``.
    """
    groups: dict[tuple[str, str], list] = {}
    for p in link.pieces:
        groups.setdefault((p.name, p.material), []).append(p)
    return [
        (f"{role}_{slot}" if role else slot, slot, pieces, role)
        for (role, slot), pieces in groups.items()
    ]


def merge_pieces(pieces):
    """Concatenate pieces into one face-varying mesh: verts, faces, corner normals, corner uvs."""
    verts, faces, normals, uvs, off = [], [], [], [], 0
    for p in pieces:
        verts.append(p.vertices)
        faces.append(p.faces + off)
        normals.append(p.corner_normals())
        uvs.append(p.corner_uvs())
        off += len(p.vertices)
    return np.vstack(verts), np.vstack(faces), np.concatenate(normals), np.concatenate(uvs)


def centred_hulls(link):
    """Every collision hull of a link as ``(centre (3,), vertices - centre, faces)``.

    Writers place each hull at its centre (URDF ``<collision><origin>``, a translate op in
    USD) with vertices around it: PhysX's default contact generation (PCM) reports false deep
    contacts between convex meshes whose vertices lie far from their shape origin.
    """
    out = []
    for piece in link.pieces:
        for v, f in piece.hulls():
            c = (v.min(0) + v.max(0)) / 2
            out.append((c, v - c, f))
    return out
