"""One object in PartNet-Mobility's layout (the files SAPIEN, ManiSkill, GAPartNet and CAGE read).

``DIR/<id>/`` holds, as PartNet-Mobility has them:

* ``mobility.urdf``: a ``base`` link, then ``link_0`` ... ``link_{n-1}`` (one per part; the
  emulation links of compound joints are ``link_K_helper``), ``joint_K`` moving ``link_K``. The
  root part hangs from ``base`` by a fixed joint with ``rpy="pi/2 0 -pi/2"``: meshes and every
  link frame are in PartNet-Mobility's object frame (Y up), and the URDF turns them back to Z up,
  front +X, so the object stands in a simulator exactly as the source object. Each link frame
  sits at its joint with the object frame's orientation; visual meshes are in object coordinates
  (visual origin = minus the link origin), as in the original. Our convex collision hulls
  (``collision/hull-N.obj``) and inertials are kept (PartNet-Mobility has neither).
* ``textured_objs/original-N.obj`` (+ ``.mtl``, textures in ``images/``): one per visual mesh.
* ``mobility_v2.json``, ``result.json``, ``semantics.txt``, ``meta.json``, ``bounding_box.json``.

Metres throughout (our objects have real sizes, so ManiSkill's ``scale`` is 1).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

import numpy as np

from infmob_usd.rotation import rpy_matrix
from infmob_usd.validate.files import UrdfJoint, UrdfLink, UrdfMesh, UrdfModel

from .source import SAFE_NAME, ExportError, Source, read_bytes, read_text

ROOT_RPY = (math.pi / 2, 0.0, -math.pi / 2)  # PartNet-Mobility's base joint: its Y-up object frame into Z up
WORLD_FROM_MESH = rpy_matrix(ROOT_RPY)
MESH_FROM_WORLD = WORLD_FROM_MESH.T

# model_cat of meta.json: the PartNet-Mobility category of each of ours (FIELD.md 3.1); the rest are CamelCase
PM_CATEGORY = {
    "kitchen_cabinet": "StorageFurniture", "storage_rack": "StorageFurniture", "dishwasher": "Dishwasher",
    "microwave": "Microwave", "oven": "Oven", "refrigerator": "Refrigerator", "beverage_fridge": "Refrigerator",
    "safe": "Safe", "dining_table": "Table", "cocktail_table": "Table", "door": "Door", "tap": "Faucet",
    "lamp": "Lamp", "office_chair": "Chair", "bar_chair": "Chair", "bottle": "Bottle", "pot": "KitchenPot",
    "toilet": "Toilet", "window": "Window", "tv": "Display", "trash_can": "TrashCan", "toaster": "Toaster",
    "kettle": "Kettle",
}


def pm_category(category: str) -> str:
    return PM_CATEGORY.get(category) or "".join(w.capitalize() for w in category.split("_"))


@dataclass
class Plan:
    """How a source object maps onto PartNet-Mobility's names and frames."""

    ids: dict[str, int]  # part link -> number K of link_K
    names: dict[str, str]  # source link -> exported link
    joint_names: dict[str, str]  # source joint -> exported joint
    poses: dict[str, np.ndarray]  # source link -> world (4, 4) pose at q = 0
    offset: dict[str, np.ndarray]  # source link -> exported link origin in the object (mesh) frame
    parent: dict[str, str | None] = field(default_factory=dict)  # part link -> parent part link
    chain: dict[str, list[UrdfJoint]] = field(default_factory=dict)  # part link -> joints from its parent part
    root: str = ""


def plan(src: Source) -> Plan:
    model = src.model
    real = [n for n in model.links if n not in src.dummies]
    ids = {n: k for k, n in enumerate(real)}
    into = {j.child: j for j in model.joints.values()}
    below: dict[str, list[str]] = {}
    for j in model.joints.values():
        below.setdefault(j.parent, []).append(j.child)

    def part_of(link: str) -> str:  # the part a helper link leads to
        while link in src.dummies:
            if not below.get(link):
                raise ExportError(f"{src.folder}: emulation link {link} carries no part")
            link = below[link][0]
        return link

    names, joint_names, helpers = {}, {}, {}
    for name in model.links:
        k = ids[part_of(name)]
        if name in src.dummies:
            helpers[k] = helpers.get(k, 0) + 1
            suffix = "" if helpers[k] == 1 else str(helpers[k])
            names[name] = f"link_{k}_helper{suffix}"
        else:
            names[name] = f"link_{k}"
        if name in into:
            joint_names[into[name].name] = names[name].replace("link_", "joint_", 1)
    poses = model.poses()
    offset = {n: MESH_FROM_WORLD @ p[:3, 3] for n, p in poses.items()}
    p = Plan(ids, names, joint_names, poses, offset, root=model.root)
    for name in real:
        chain, link = [], name
        while link in into:
            chain.insert(0, into[link])
            link = into[link].parent
            if link not in src.dummies:
                break
        p.parent[name] = link if chain else None
        p.chain[name] = chain
    return p


def _coords(lines: list[str], rows: list[int], skip: int) -> np.ndarray:
    """``(n, 3)`` numbers after the keyword of ``lines[rows]``; :class:`ExportError` unless each line has 3."""
    words = " ".join(lines[i][skip:] for i in rows).split()
    try:
        xyz = np.array(words, dtype=float).reshape(len(rows), 3)
    except ValueError:
        raise ExportError(f"malformed OBJ: a vertex line without 3 numbers (near {lines[rows[0]][:60]!r})") from None
    if not np.all(np.isfinite(xyz)):
        raise ExportError("malformed OBJ: a vertex that is not a finite number")
    return xyz


def transform_obj(text: str, m: np.ndarray, keep_materials: bool = True) -> tuple[str, np.ndarray, list[str]]:
    """An OBJ's text with vertices moved by the ``(4, 4)`` transform ``m`` (normals turned with it);
    returns ``(text, (n, 3) vertices, mtllib names)``. Other lines are kept as they are."""
    lines = text.splitlines()
    vs = [i for i, line in enumerate(lines) if line.startswith("v ")]
    ns = [i for i, line in enumerate(lines) if line.startswith("vn ")]
    verts = _coords(lines, vs, 2) @ m[:3, :3].T + m[:3, 3] if vs else np.zeros((0, 3))
    for i, row in zip(vs, verts):
        lines[i] = f"v {row[0]:.6f} {row[1]:.6f} {row[2]:.6f}"
    if ns:
        normals = _coords(lines, ns, 3) @ np.linalg.inv(m[:3, :3])
        normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
        for i, row in zip(ns, normals):
            lines[i] = f"vn {row[0]:.6f} {row[1]:.6f} {row[2]:.6f}"
    libs = [w for line in lines if line.startswith("mtllib ") for w in line.split()[1:]]
    if not keep_materials:
        lines = [line for line in lines if not line.startswith(("mtllib ", "usemtl "))]
        libs = []
    return "\n".join(lines) + "\n", verts, libs


MAP_KEYS = ("map_", "norm", "bump", "disp", "refl")


def copy_mtl(src: Source, mtl_rel: str, dst, images: dict[str, str]) -> None:
    """Copy a material library, its texture paths rewritten to ``../images/NAME`` (textures copied
    there); a texture outside the object folder is refused."""
    text = read_text(src.folder, mtl_rel, "material")
    base = os.path.dirname(mtl_rel)
    out = []
    for line in text.splitlines():
        words = line.split()
        if words and words[0].startswith(MAP_KEYS) and len(words) > 1:
            rel = os.path.normpath(os.path.join(base, words[-1]))
            name = os.path.basename(rel)
            if not SAFE_NAME.match(name) or images.get(name, rel) != rel:
                raise ExportError(f"{src.folder}: texture {words[-1]!r} in {mtl_rel} has an unusable name")
            if name not in images:
                (dst / "images").mkdir(exist_ok=True)
                (dst / "images" / name).write_bytes(read_bytes(src.folder, rel, "texture"))
                images[name] = rel
            line = " ".join([*words[:-1], f"../images/{name}"])
        out.append(line)
    (dst / "textured_objs" / os.path.basename(mtl_rel)).write_text("\n".join(out) + "\n")


def _inertia(link: UrdfLink, rot: np.ndarray) -> tuple[float, ...] | None:
    if link.inertia is None:
        return None
    xx, xy, xz, yy, yz, zz = link.inertia
    t = rot @ np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]) @ rot.T
    return tuple(float(round(v, 12)) for v in (t[0, 0], t[0, 1], t[0, 2], t[1, 1], t[1, 2], t[2, 2]))


@dataclass
class Written:
    """What :func:`write_meshes` wrote: per part link its leaf parts ``(leaf name, obj stem)``,
    the visual vertices' bounds per link, and the new URDF links."""

    leaves: dict[str, list[tuple[str, str]]]
    bounds: dict[str, np.ndarray]
    links: dict[str, UrdfLink]
    verts: dict[str, np.ndarray] = field(default_factory=dict)  # stem -> (n, 3) vertices, object frame


def part_name(visual: str, link: str) -> str:
    """A visual's part name as PartNet names parts: without its link's name, repeated words once
    (``door_0_0_handle_handle`` -> ``handle``)."""
    words = (visual[len(link) + 1:] if visual.startswith(link + "_") else visual).split("_")
    kept = [w for i, w in enumerate(words) if w and (i == 0 or w != words[i - 1])]
    return "_".join(kept) or "part"


def write_meshes(src: Source, p: Plan, dst) -> Written:
    """``textured_objs/``, ``images/``, ``collision/`` and each exported link's meshes and inertial."""
    (dst / "textured_objs").mkdir()
    (dst / "collision").mkdir()
    images: dict[str, str] = {}
    mtls: set[str] = set()
    n_vis = n_col = 0
    w = Written({}, {}, {})
    for name, link in src.model.links.items():
        to_mesh = np.eye(4)
        to_mesh[:3, :3] = MESH_FROM_WORLD
        to_mesh = to_mesh @ p.poses[name]
        back = tuple(float(-x) for x in p.offset[name])
        out = UrdfLink(p.names[name])
        leaves, verts = [], []
        for kind, meshes in (("visual", link.visuals), ("collision", link.collisions)):
            for m in meshes:
                rel = os.path.normpath(os.path.join(src.urdf_dir, m.filename))
                scale = np.diag([*m.scale, 1.0])
                text, v, libs = transform_obj(read_text(src.folder, rel, "mesh"), to_mesh @ m.origin @ scale,
                                              keep_materials=kind == "visual")
                if kind == "visual":
                    stem = f"original-{n_vis}"
                    n_vis += 1
                    (dst / "textured_objs" / f"{stem}.obj").write_text(text)
                    for lib in libs:
                        if not SAFE_NAME.match(lib):
                            raise ExportError(f"{src.folder}: material library {lib!r} has an unusable name")
                        if lib not in mtls:
                            copy_mtl(src, os.path.join(os.path.dirname(rel), lib), dst, images)
                            mtls.add(lib)
                    leaf = part_name(m.name or stem, name)
                    leaves.append((leaf, stem))
                    verts.append(v)
                    w.verts[stem] = v
                    out.visuals.append(UrdfMesh(f"textured_objs/{stem}.obj", back, name=f"{leaf}-{n_vis - 1}"))
                else:
                    stem = f"hull-{n_col}"
                    n_col += 1
                    (dst / "collision" / f"{stem}.obj").write_text(text)
                    out.collisions.append(UrdfMesh(f"collision/{stem}.obj", back, name=m.name))
        if link.mass is not None:
            rot = MESH_FROM_WORLD @ p.poses[name][:3, :3]
            com = to_mesh[:3, :3] @ np.asarray(link.com) + to_mesh[:3, 3] - p.offset[name]
            out.mass, out.com, out.inertia = link.mass, tuple(float(round(x, 12)) for x in com), _inertia(link, rot)
        w.links[name] = out
        w.leaves[name] = leaves
        if verts and sum(len(v) for v in verts):
            allv = np.concatenate(verts)
            w.bounds[name] = np.array([allv.min(0), allv.max(0)])
    return w


def urdf_model(src: Source, p: Plan, w: Written, obj_id: int) -> UrdfModel:
    """The exported ``mobility.urdf`` as a model (base link, renamed links and joints, object frame)."""
    model = UrdfModel(str(obj_id))
    model.links["base"] = UrdfLink("base")
    for name in src.model.links:
        model.links[p.names[name]] = w.links[name]
    root = p.names[p.root]
    t = tuple(float(x) for x in p.poses[p.root][:3, 3])
    jr = root.replace("link_", "joint_", 1)
    joints = [UrdfJoint(jr, "fixed", "base", root, t, ROOT_RPY)]
    for j in src.model.ordered():
        axis = MESH_FROM_WORLD @ p.poses[j.child][:3, :3] @ j.unit_axis
        xyz = tuple(float(round(x, 12)) for x in p.offset[j.child] - p.offset[j.parent])
        joints.append(UrdfJoint(p.joint_names[j.name], j.type, p.names[j.parent], p.names[j.child], xyz,
                                (0.0, 0.0, 0.0), np.round(axis, 12) + 0.0, j.lower, j.upper, j.effort, j.velocity,
                                j.damping, j.friction))
    for j in sorted(joints, key=lambda j: _joint_key(j.name)):
        model.joints[j.name] = j
    return model


def _joint_key(name: str) -> tuple[int, str]:
    head = name.split("_")
    return int(head[1]), name


def joint_data(src: Source, p: Plan, part: str) -> tuple[str, dict]:
    """``(joint, jointData)`` of mobility_v2.json for one part (PartNet-Mobility's conventions:
    hinge limits in degrees, slider limits in metres, axes in the object frame)."""
    if part == p.root:
        return "heavy", {}
    pm = src.semantics[part][0]
    want = {"hinge": ("revolute", "continuous"), "slider": ("prismatic",)}.get(pm)
    movable = [j for j in p.chain[part] if j.movable]
    # the joint that moves the part itself (the last of an emulation chain) when it is of the right kind
    pick = next((j for j in reversed(movable) if want and j.type in want), None)
    if pick is None:
        return pm, {}
    origin = p.offset[pick.child]
    direction = MESH_FROM_WORLD @ p.poses[pick.child][:3, :3] @ pick.unit_axis
    axis = {"origin": [round(float(x), 9) for x in origin], "direction": [round(float(x), 9) for x in direction]}
    lo, hi = pick.lower or 0.0, pick.upper or 0.0
    if pm == "hinge":
        free = pick.type == "continuous"
        limit = {"a": 0.0 if free else math.degrees(lo), "b": 0.0 if free else math.degrees(hi), "noLimit": free}
    else:
        turn = next((j for j in movable if j.type in ("revolute", "continuous")), None)
        limit = {"a": lo, "b": hi, "noLimit": False, "rotates": turn is not None,
                 "noRotationLimit": turn is not None and turn.type == "continuous",
                 "rotationLimit": 0.0 if turn is None or turn.type == "continuous"
                 else math.degrees((turn.upper or 0.0) - (turn.lower or 0.0))}
    return pm, {"axis": axis, "limit": limit}
