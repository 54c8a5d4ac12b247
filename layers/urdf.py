"""URDF beside the USD, with OBJ meshes: for SAPIEN, ManiSkill and MuJoCo.

* one visual OBJ (+ MTL with PBR texture maps) per link and material slot,
  named ``handle_*`` where the pieces are handles (ManiSkill looks for that);
  no ``<material>`` elements: colours live in the MTL, and SAPIEN's loader would
  need a render device to build URDF materials;
* one ``<collision>`` per convex piece (SAPIEN and MuJoCo hull each collision file), its OBJ
  centred on its own origin and placed by ``<collision><origin>`` (PhysX's contacts misbehave
  otherwise); the wedges of a shell band are turned copies of one wedge, so they share its
  OBJ and differ by their origin's ``xyz rpy`` (a pot writes ~30 collision files, not ~180),
  and identical hulls of a link (a keypad's buttons) share one file;
* ``<inertial>`` with the full tensor about the centre of mass;
* ``<limit>`` with effort and velocity, ``<dynamics damping friction>``;
* a ``<mujoco><compiler strippath="false" discardvisual="false"/></mujoco>`` hint, so MuJoCo finds
  the meshes (3.x strips folders from mesh paths by default) and keeps the visual meshes.

All mesh and texture paths are relative to the URDF file.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from infmob_usd.rotation import matrix_rpy as rotation_rpy

from .common import collision_placements, visual_meshes, write_file

MESHES = "meshes"


def _f(x: float) -> str:
    s = f"{float(x):.9g}"
    return "0" if s == "-0" else s


def _v(a) -> str:
    return " ".join(_f(x) for x in a)


def _rows(prefix: str, fmt: str, a: np.ndarray) -> str:
    """One line ``prefix fmt...`` per row of ``a`` (one %-format over the whole array: ~3x an f-string loop)."""
    if not len(a):
        return ""
    return (f"{prefix} {fmt}\n" * len(a)) % tuple(a.ravel().tolist())


def _unique_rows(a: np.ndarray, decimals: int) -> tuple[np.ndarray, np.ndarray]:
    """Rows of ``a`` rounded to ``decimals`` and deduplicated, and each row's index among them."""
    q = np.rint(a * 10.0**decimals).astype(np.int64)
    lo, span = q.min(0), q.max(0) - q.min(0) + 1
    bits = [int(s).bit_length() for s in span]
    if sum(bits) <= 62:  # pack each row into one integer: a 1-D sort instead of a row sort
        key = np.zeros(len(q), np.int64)
        for col, b in zip((q - lo).T, bits):
            key = (key << b) | col
        _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
        uniq = q[first]
    else:
        uniq, inverse = np.unique(q, axis=0, return_inverse=True)
    return uniq / 10.0**decimals, inverse.reshape(-1)


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray, normals=None, uvs=None,
              mtl: str | None = None, material: str | None = None) -> None:
    """Write an OBJ; ``normals``/``uvs`` are per face corner ``(m, 3, 3)`` / ``(m, 3, 2)``.

    Corner normals and UVs are rounded to the precision written and shared between
    corners that agree, so a smooth surface lists each normal once.  Where nearly every
    vertex has one UV and one normal (smooth surfaces), the lists run in step and faces
    read ``f i/i/i ...``.
    """
    parts = ["# infmob-usd\n"]
    if mtl:
        parts.append(f"mtllib {mtl}\n")
    vertices = np.asarray(vertices, float)
    f1 = np.asarray(faces, np.int64) + 1
    if uvs is not None and normals is not None:
        vt, ti = _unique_rows(np.asarray(uvs, float).reshape(-1, 2), 6)
        vn, ni = _unique_rows(np.asarray(normals, float).reshape(-1, 3), 5)
        vi = f1.reshape(-1) - 1
        if max(len(vertices), len(vt), len(vn)) < 1 << 21:
            # a smooth surface: one (position, uv, normal) triple per vertex, almost; then list the
            # triples in step so a face reads "f i/i/i j/j/j k/k/k", one number per corner to format
            key = (vi << 42) | (ti << 21) | ni
            triples, first, inverse = np.unique(key, return_index=True, return_inverse=True)
            if len(triples) <= 1.25 * len(vertices):
                corner = np.arange(len(key))[first]
                parts.append(_rows("v", "%.6f %.6f %.6f", vertices[vi[corner]]))
                parts.append(_rows("vt", "%.6f %.6f", vt[ti[corner]]))
                parts.append(_rows("vn", "%.5f %.5f %.5f", vn[ni[corner]]))
                if material:
                    parts.append(f"usemtl {material}\n")
                token = [f"{i}/{i}/{i}" for i in range(1, len(triples) + 1)]
                parts.append(("f %s %s %s\n" * len(f1)) % tuple([token[i] for i in inverse.reshape(-1).tolist()]))
                write_file(path, "".join(parts))
                return
        parts.append(_rows("v", "%.6f %.6f %.6f", vertices))
        parts.append(_rows("vt", "%.6f %.6f", vt))
        parts.append(_rows("vn", "%.5f %.5f %.5f", vn))
        if material:
            parts.append(f"usemtl {material}\n")
        corners = np.stack([f1.reshape(-1), ti + 1, ni + 1], 1).reshape(-1, 9)
        parts.append(_rows("f", "%d/%d/%d %d/%d/%d %d/%d/%d", corners))
    else:
        parts.append(_rows("v", "%.6f %.6f %.6f", vertices))
        if material:
            parts.append(f"usemtl {material}\n")
        parts.append(_rows("f", "%d %d %d", f1))
    write_file(path, "".join(parts))


_MTL_MAPS = {"basecolor": "map_Kd", "roughness": "map_Pr", "metallic": "map_Pm", "normal": "norm"}


def _mtl(slot: str, look, maps) -> str:
    """MTL of one slot: constants from the look, a map line for each texture written.

    The object's wear of the look (:class:`~infmob_usd.materials.Wear`): ``Kd`` is the tint,
    which multiplies ``map_Kd`` (as the MTL format defines it; without a map it is the tinted
    colour), the roughness scale is ``map_Pr -mm 0 <scale>`` (base, gain), and the UV rotation
    and offset are baked into the OBJ ``vt`` (:func:`write_urdf`), which every reader honours.
    ``d`` and ``Tr`` (= 1 - d) give the opacity, ``Ni`` the index of refraction.
    """
    tint = np.asarray(look.wear.tint, float)
    r, g, b = tint if "basecolor" in maps else tint * np.asarray(look.base_color, float)
    rough = look.wear.roughness_scale
    lines = [
        f"newmtl {slot}",
        f"Kd {r:.4f} {g:.4f} {b:.4f}",
        "Ka 0 0 0",
        "Ks 0.04 0.04 0.04",
        f"d {look.opacity:.3f}",
        f"Pr {min(1.0, look.roughness * rough):.3f}",
        f"Pm {look.metallic:.3f}",
    ]
    if look.opacity < 1.0:
        from infmob_usd.materials import FAMILIES

        lines += [f"Tr {1.0 - look.opacity:.3f}", f"Ni {FAMILIES[look.family].ior:.3f}"]
    for name, key in _MTL_MAPS.items():
        if name in maps:
            option = f"-mm 0 {rough:.4f} " if name == "roughness" else ""
            lines.append(f"{key} {option}../textures/{slot}_{name}.png")
    return "\n".join(lines + [""])


def write_meshes(obj, folder: Path) -> dict[str, tuple[list, list]]:
    """Write ``meshes/`` (visual OBJ + MTL per link and slot, collision OBJ per distinct hull) once
    per object folder, for the URDF and the MJCF; return, per link, ``(visuals, collisions)``:
    ``visuals`` ``[(vname, slot, file)]``, ``collisions`` ``[(file, position (3,), rotation or None)]``
    (files relative to ``meshes/``). Kept on the object while :func:`~infmob_usd.layers.write_object`
    runs, so the second writer only reads it."""
    cached = getattr(obj, "_mesh_files", None)
    if cached is not None and cached[0] == folder:
        return cached[1]
    meshes = folder / MESHES
    meshes.mkdir()
    for slot, look in obj.materials.items():
        write_file(meshes / f"{slot}.mtl", _mtl(slot, look, obj.textures.get(slot, {})))
    visuals = visual_meshes(obj)
    table = {}
    for link in obj.links:
        vis = []
        for vname, slot, _role, v, f, n, uv in visuals[link.name]:
            fname = f"{link.name}__{vname}.obj"
            m = obj.materials[slot].wear.uv_matrix()  # this object's placement of the maps, baked in
            write_obj(meshes / fname, v, f, n, uv @ m[:, :2].T + m[:, 2], mtl=f"{slot}.mtl", material=slot)
            vis.append((vname, slot, fname))
        col = []
        same_shape: dict[bytes, str] = {}  # identical centred hulls (a keypad's buttons) share a file
        file_of: dict[int, str] = {}  # hull index -> the file holding its mesh
        for mesh, pos, rot, hv, hf in collision_placements(link):
            if rot is None:
                key = np.round(hv, 9).tobytes() + np.asarray(hf, np.int64).tobytes()
                if key not in same_shape:
                    same_shape[key] = f"{link.name}__collision_{mesh:03d}.obj"
                    write_obj(meshes / same_shape[key], hv, hf)
                file_of[mesh] = same_shape[key]
            col.append((file_of[mesh], pos, rot))  # an instance's prototype comes before it
        table[link.name] = (vis, col)
    obj._mesh_files = (folder, table)
    return table


def write_urdf(obj, folder: Path) -> Path:
    """Write ``<name>.urdf`` (and ``meshes/``, unless written already) into ``folder``; return the URDF path."""
    files = write_meshes(obj, folder)
    out = [f'<?xml version="1.0"?>\n<robot name={quoteattr(obj.name)}>']
    # MuJoCo reads this: keep the meshes/ folder in mesh paths (3.x strips it by default) and the visuals
    out.append('  <mujoco><compiler strippath="false" discardvisual="false"/></mujoco>')
    for link in obj.links:
        out.append(f'  <link name="{link.name}">')
        visuals, collisions = files[link.name]
        for vname, _slot, fname in visuals:
            out.append(f'    <visual name="{link.name}_{vname}"><origin xyz="0 0 0" rpy="0 0 0"/>'
                       f'<geometry><mesh filename="{MESHES}/{fname}"/></geometry></visual>')
        for i, (fname, pos, rot) in enumerate(collisions):
            rpy = "0 0 0" if rot is None else _v(rotation_rpy(rot))
            out.append(f'    <collision name="{link.name}_collision_{i:03d}"><origin xyz="{_v(pos)}" rpy="{rpy}"/>'
                       f'<geometry><mesh filename="{MESHES}/{fname}"/></geometry></collision>')
        I = link.inertia
        out.append(f'    <inertial><origin xyz="{_v(link.com)}" rpy="0 0 0"/><mass value="{_f(link.mass)}"/>'
                   f'<inertia ixx="{_f(I[0, 0])}" ixy="{_f(I[0, 1])}" ixz="{_f(I[0, 2])}" iyy="{_f(I[1, 1])}"'
                   f' iyz="{_f(I[1, 2])}" izz="{_f(I[2, 2])}"/></inertial>')
        out.append("  </link>")
    origins = {link.name: link.origin for link in obj.links}
    for j in obj.joints:
        xyz = np.asarray(origins[j.child]) - np.asarray(origins[j.parent])
        out.append(f'  <joint name="{j.name}" type="{j.type}">')
        out.append(f'    <parent link="{j.parent}"/><child link="{j.child}"/>')
        out.append(f'    <origin xyz="{_v(xyz)}" rpy="0 0 0"/>')
        if j.type != "fixed":
            out.append(f'    <axis xyz="{_v(j.axis)}"/>')
            lim = "" if j.type == "continuous" else f'lower="{_f(j.lower)}" upper="{_f(j.upper)}" '
            out.append(f'    <limit {lim}effort="{_f(j.effort)}" velocity="{_f(j.velocity)}"/>')
            out.append(f'    <dynamics damping="{_f(j.damping)}" friction="{_f(j.friction)}"/>')
        out.append("  </joint>")
    out.append("</robot>\n")
    path = folder / f"{obj.name}.urdf"
    write_file(path, "\n".join(out))
    return path


__all__ = ["write_meshes", "write_obj", "write_urdf"]
