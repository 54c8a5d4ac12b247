"""URDF beside the USD, with OBJ meshes: for SAPIEN, ManiSkill and MuJoCo.

* one visual OBJ (+ MTL with PBR texture maps) per link and material slot,
  named ``handle_*`` where the pieces are handles (ManiSkill looks for that);
  no ``<material>`` elements: colours live in the MTL, and SAPIEN's loader would
  need a render device to build URDF materials;
* one collision OBJ per convex piece (SAPIEN hulls each collision file), centred on its
  own origin and placed by ``<collision><origin>`` (PhysX's contacts misbehave otherwise);
* ``<inertial>`` with the full tensor about the centre of mass;
* ``<limit>`` with effort and velocity, ``<dynamics damping friction>``.

All mesh and texture paths are relative to the URDF file.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from .common import centred_hulls, merge_pieces, visual_groups

MESHES = "meshes"


def _f(x: float) -> str:
    s = f"{float(x):.9g}"
    return "0" if s == "-0" else s


def _v(a) -> str:
    return " ".join(_f(x) for x in a)


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray, normals=None, uvs=None,
              mtl: str | None = None, material: str | None = None) -> None:
    """Write an OBJ; ``normals``/``uvs`` are per face corner ``(m, 3, 3)`` / ``(m, 3, 2)``."""
    lines = ["# infmob-usd"]
    if mtl:
        lines += [f"mtllib {mtl}"]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices]
    if uvs is not None:
        lines += [f"vt {u:.6f} {v:.6f}" for u, v in uvs.reshape(-1, 2)]
    if normals is not None:
        lines += [f"vn {x:.5f} {y:.5f} {z:.5f}" for x, y, z in normals.reshape(-1, 3)]
    if material:
        lines.append(f"usemtl {material}")
    f1 = faces + 1
    if uvs is not None and normals is not None:
        c = np.arange(1, 3 * len(faces) + 1).reshape(-1, 3)
        lines += [f"f {a}/{ca}/{ca} {b}/{cb}/{cb} {d}/{cd}/{cd}" for (a, b, d), (ca, cb, cd) in zip(f1, c)]
    else:
        lines += [f"f {a} {b} {d}" for a, b, d in f1]
    path.write_text("\n".join(lines) + "\n")


def _mtl(slot: str, look) -> str:
    r, g, b = look.base_color
    tex = f"../textures/{slot}"
    return "\n".join([
        f"newmtl {slot}",
        f"Kd {r:.4f} {g:.4f} {b:.4f}",
        "Ka 0 0 0",
        "Ks 0.04 0.04 0.04",
        f"d {look.opacity:.3f}",
        f"Pr {look.roughness:.3f}",
        f"Pm {look.metallic:.3f}",
        f"map_Kd {tex}_basecolor.png",
        f"map_Pr {tex}_roughness.png",
        f"map_Pm {tex}_metallic.png",
        f"norm {tex}_normal.png",
        "",
    ])


def write_urdf(obj, folder: Path) -> Path:
    """Write ``<name>.urdf`` and ``meshes/`` into ``folder``; return the URDF path."""
    meshes = folder / MESHES
    meshes.mkdir()
    for slot, look in obj.materials.items():
        (meshes / f"{slot}.mtl").write_text(_mtl(slot, look))
    out = [f'<?xml version="1.0"?>\n<robot name={quoteattr(obj.name)}>']
    for link in obj.links:
        out.append(f'  <link name="{link.name}">')
        for vname, slot, pieces, _role in visual_groups(link):
            fname = f"{link.name}__{vname}.obj"
            v, f, n, uv = merge_pieces(pieces)
            write_obj(meshes / fname, v, f, n, uv, mtl=f"{slot}.mtl", material=slot)
            out.append(f'    <visual name="{link.name}_{vname}"><origin xyz="0 0 0" rpy="0 0 0"/>'
                       f'<geometry><mesh filename="{MESHES}/{fname}"/></geometry></visual>')
        for i, (centre, hv, hf) in enumerate(centred_hulls(link)):
            fname = f"{link.name}__collision_{i:03d}.obj"
            write_obj(meshes / fname, hv, hf)
            out.append(f'    <collision name="{link.name}_collision_{i:03d}"><origin xyz="{_v(centre)}" rpy="0 0 0"/>'
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
    path.write_text("\n".join(out))
    return path


__all__ = ["write_obj", "write_urdf"]
