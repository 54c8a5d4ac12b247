"""Facts every writer reads the same way."""

from __future__ import annotations

import os

import numpy as np

from infmob_usd.shading import corner_attributes, grain_frame

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


_CREATE = os.O_WRONLY | os.O_CREAT | os.O_TRUNC | getattr(os, "O_CLOEXEC", 0)


def write_file(path, data: str | bytes) -> None:
    """Write ``data`` (``str`` as UTF-8) to ``path``, replacing it: the same bytes as
    ``Path.write_text`` / ``write_bytes`` (mode 0o666 less the umask), with one ``open``, ``write``
    and ``close`` system call each and no Python file object. An object folder holds ~150 files
    (one OBJ per collision hull); measured 32 us of CPU per small file against 75 us for
    ``Path.write_text``."""
    if isinstance(data, str):
        data = data.encode("utf-8")
    fd = os.open(os.fspath(path), _CREATE, 0o666)
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
    finally:
        os.close(fd)


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


def visual_meshes(obj) -> dict[str, list]:
    """Every visual mesh of ``obj`` per link: ``[(vname, slot, role, verts, faces, normals, uvs)]``.

    ``normals`` ``(3m, 3)`` and ``uvs`` ``(3m, 2)`` are per face corner, computed in one pass
    over the whole object (:func:`~infmob_usd.shading.corner_attributes`), UVs in each
    piece's grain frame (:func:`~infmob_usd.shading.grain_frame`).  While
    :func:`~infmob_usd.layers.write_object` runs, the result is kept on the object
    (``obj._visual_meshes``) so the USD and URDF writers share it.
    """
    cached = getattr(obj, "_visual_meshes", None)
    if cached is not None:
        return cached
    groups, verts, faces, frames, counts, off, nf = [], [], [], [], [], 0, 0
    for link in obj.links:
        for vname, slot, pieces, role in visual_groups(link):
            v0, f0 = off, nf
            for p in pieces:
                verts.append(p.vertices)
                faces.append(p.faces + off)
                frames.append(grain_frame(p.vertices))
                counts.append(len(p.faces))
                off += len(p.vertices)
                nf += len(p.faces)
            groups.append((link.name, vname, slot, role, v0, off, f0, nf))
    out: dict[str, list] = {link.name: [] for link in obj.links}
    if not groups:
        return out
    v_all, f_all = np.vstack(verts), np.vstack(faces)
    normals, uvs = corner_attributes(v_all, f_all, np.repeat(np.array(frames), counts, axis=0))  # a frame per face
    for lname, vname, slot, role, v0, v1, f0, f1 in groups:
        out[lname].append((vname, slot, role, v_all[v0:v1], f_all[f0:f1] - v0,
                           normals[3 * f0:3 * f1], uvs[3 * f0:3 * f1]))
    return out


def collision_placements(link) -> list[tuple]:
    """Every collision hull of a link as ``(mesh index, position (3,), rotation (3, 3) or None,
    centred vertices or None, faces or None)``.

    A hull with its own mesh (rotation ``None``) is written centred on the middle of its bounds
    and placed there: PhysX's default contact generation (PCM) reports false deep contacts
    between convex meshes whose vertices lie far from their shape origin. A hull that is a
    rigidly moved copy of another hull of its piece (the wedges of a shell band,
    :meth:`~infmob_usd.piece.Piece.hull_instances`) reuses that hull's mesh (``mesh index``)
    placed by ``position`` and ``rotation``: one file per band instead of one per wedge.
    """
    hulls, instances, first = [], [], []  # every hull of the link, its instance hint, its piece's first hull
    for piece in link.pieces:
        first += [len(hulls)] * len(piece.hulls())
        hulls += piece.hulls()
        instances += piece.hull_instances()
    if not hulls:
        return []
    sizes = np.array([len(v) for v, _ in hulls])
    starts = np.cumsum(sizes) - sizes
    v_all = np.concatenate([v for v, _ in hulls])
    centre = (np.minimum.reduceat(v_all, starts) + np.maximum.reduceat(v_all, starts)) / 2  # of the bounds
    out = []
    for k, ((v, f), inst, base) in enumerate(zip(hulls, instances, first)):
        if inst is None or instances[base + inst[0]] is not None:
            out.append((k, centre[k], None, v - centre[k], f))
        else:
            j, rot, t = inst
            out.append((base + j, rot @ centre[base + j] + t, rot, None, None))
    return out
