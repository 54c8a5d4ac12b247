"""Test-only annotations (schema ``infmob-annotations/1``, /work/ANNOTATIONS.md) computed from a written object
folder, so that the robot check can be exercised before the build writes ``annotations.json`` itself.

Covers the simple case only: a movable link with a handle drawn as its own visual mesh,
``meshes/<link>__handle_handle.obj`` or ``meshes/<link>__pull.obj`` (vertices in the link frame: the writer
puts visuals at the link origin). The grasp is the middle of the handle's face towards where the handle first
moves when the joint opens (a sliding door or sash: its front, +X), approached against that motion along the
nearest world axis, the fingers closing across the handle's thinner other side; the path is the grasp point
moved by the joint in SAPIEN with every other joint at rest.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

FRACTIONS = [i / 10 for i in range(11)]
HANDLE_MESHES = ("{link}__handle_handle.obj", "{link}__pull.obj")


def _obj_vertices(path: Path) -> np.ndarray:
    return np.array([[float(x) for x in line.split()[1:4]] for line in path.read_text().splitlines()
                     if line.startswith("v ")])


def _handle(folder: Path, link: str) -> np.ndarray | None:
    for pattern in HANDLE_MESHES:
        mesh = folder / "meshes" / pattern.format(link=link)
        if mesh.is_file():
            return _obj_vertices(mesh)
    return None


def _matrix(pose) -> np.ndarray:
    return np.asarray(pose.to_transformation_matrix(), float)


def _path(art, qi: int, rest: np.ndarray, link, position: np.ndarray, opened: float) -> list[list[float]]:
    """The link-frame point ``position`` in the root frame at joint fractions 0, 0.1 ... 1."""
    out = []
    for f in FRACTIONS:
        q = rest.copy()
        q[qi] = rest[qi] + f * (opened - rest[qi])
        art.set_qpos(q.astype(np.float32))
        root = _matrix(art.root.entity_pose)
        p = np.linalg.inv(root) @ _matrix(link.entity_pose) @ np.array([*position, 1.0])
        out.append(p[:3].tolist())
    art.set_qpos(rest.astype(np.float32))
    return out


def _target(art, ctx, qi: int, joint: dict, vertices: np.ndarray, groups: dict[str, str]) -> dict:
    link = art.find_link_by_name(joint["child"])
    pose = _matrix(link.entity_pose)
    inv = np.linalg.inv(pose)
    opened = float(joint["upper"])
    centre = (vertices.min(0) + vertices.max(0)) / 2
    start = _path(art, qi, ctx.rest_qpos, link, centre, opened)[:2]
    pull = np.asarray(start[1]) - np.asarray(start[0])  # where the handle goes first (root frame = world here)
    if joint["type"] == "prismatic" and "drawer" not in link.name:
        pull = np.array([1.0, 0.0, 0.0])  # a sliding door or sash: its handle is taken from the front
    k = int(np.argmax(np.abs(pull)))  # handles are axis-aligned at rest: the world axis nearest the pull
    sign = float(np.sign(pull[k]))
    world = (pose[:3, :3] @ vertices.T).T + pose[:3, 3]
    lo, hi = world.min(0), world.max(0)
    grasp_world = (lo + hi) / 2
    grasp_world[k] = hi[k] if sign > 0 else lo[k]  # the handle's face towards the person pulling
    approach_world = np.zeros(3)
    approach_world[k] = -sign
    across = [a for a in range(3) if a != k]
    closing_world = np.zeros(3)
    thin = min(across, key=lambda a: hi[a] - lo[a])
    closing_world[thin] = 1.0
    position = (inv @ np.array([*grasp_world, 1.0]))[:3]
    vlo, vhi = vertices.min(0), vertices.max(0)
    revolute = joint["type"] == "revolute"
    needs = joint.get("requires_open")
    return {
        "joint": joint["name"], "joint_type": joint["type"], "link": joint["child"],
        "part_class": "hinge_door" if revolute else "slider_drawer", "handle_class": "line_fixed_handle",
        "box": {"center": ((vlo + vhi) / 2).tolist(), "size": (vhi - vlo).tolist(), "quat_wxyz": [1.0, 0, 0, 0]},
        "grasps": [{"position": position.tolist(), "approach": (inv[:3, :3] @ approach_world).tolist(),
                    "closing": (inv[:3, :3] @ closing_world).tolist(), "width": float(hi[thin] - lo[thin])}],
        "action": "pull", "rest": float(ctx.rest_qpos[qi]), "open": opened,
        "open_threshold": 0.9, "closed_threshold": 0.05,
        "path": _path(art, qi, ctx.rest_qpos, link, position, opened),
        "requires_open": [groups[g] for g in ([needs] if isinstance(needs, str) else needs or []) if g in groups],
    }


def _link_vertices(folder: Path, link: str) -> np.ndarray | None:
    """Every visual mesh vertex of ``link`` (link frame)."""
    meshes = [m for m in sorted((folder / "meshes").glob(f"{link}__*.obj")) if "__collision" not in m.name]
    return np.concatenate([_obj_vertices(m) for m in meshes]) if meshes else None


def _small_part(art, ctx, qi: int, joint: dict, vertices: np.ndarray) -> dict:
    """A button (pressed along its motion, with the closed fingers' tips on its outer face) or a knob (held on
    its axis by its sides, turned in place: its path is a point)."""
    link = art.find_link_by_name(joint["child"])
    pose = _matrix(link.entity_pose)
    inv = np.linalg.inv(pose)
    sim_joint = ctx.joints[qi]
    axis = _matrix(sim_joint.get_global_pose())[:3, 0]  # PhysX: the joint axis is its frame's x (world)
    pivot = _matrix(sim_joint.get_global_pose())[:3, 3]
    world = (pose[:3, :3] @ vertices.T).T + pose[:3, 3]
    lo, hi = world.min(0), world.max(0)
    button = joint["type"] == "prismatic"
    out = -axis if button else axis * np.sign(float(np.mean((world - pivot) @ axis)) or 1.0)  # away from the body
    face = (lo + hi) / 2 if button else pivot + axis * float(np.dot((lo + hi) / 2 - pivot, axis))
    face = face + out * (float(np.max((world - face) @ out)))  # on the outer face, on the centre line
    k = int(np.argmax(np.abs(out)))
    across = [a for a in range(3) if a != k]
    thin = min(across, key=lambda a: hi[a] - lo[a])
    closing = np.eye(3)[thin]
    position = (inv @ np.array([*face, 1.0]))[:3]
    opened = float(joint["upper"]) if joint["type"] != "continuous" else float(np.pi / 2)
    vlo, vhi = vertices.min(0), vertices.max(0)
    return {
        "joint": joint["name"], "joint_type": joint["type"], "link": joint["child"],
        "part_class": "slider_button" if button else "hinge_knob", "handle_class": None,
        "box": {"center": ((vlo + vhi) / 2).tolist(), "size": (vhi - vlo).tolist(), "quat_wxyz": [1.0, 0, 0, 0]},
        "grasps": [{"position": position.tolist(), "approach": (inv[:3, :3] @ -out).tolist(),
                    "closing": (inv[:3, :3] @ closing).tolist(), "width": float(hi[thin] - lo[thin])}],
        "action": "press" if button else "turn", "rest": float(ctx.rest_qpos[qi]), "open": opened,
        "open_threshold": 0.9, "closed_threshold": 0.05,
        "path": _path(art, qi, ctx.rest_qpos, link, position, opened), "requires_open": [],
    }


def write_annotations(folder: str | Path, small_parts: bool = False) -> list[dict]:
    """Write ``annotations.json`` into ``folder`` for every door or drawer (a revolute ``hinge`` or prismatic
    ``slide`` joint, not a lever or a folding handle) whose link has a handle mesh, and with ``small_parts``
    every ``button`` and ``knob`` joint hung off the root link; returns the targets."""
    from infmob_usd.validate.sim import _context, _find_urdf, _read_meta, load_sapien

    folder = Path(folder)
    meta = _read_meta(folder)
    urdf = _find_urdf(folder, meta)
    scene, art = load_sapien(urdf)
    ctx = _context(folder, meta, urdf, scene, art)
    names = [j.name for j in ctx.joints]
    groups = {j.get("group", j["child"]): j["name"] for j in meta["joints"]}
    art.set_qpos(ctx.rest_qpos.astype(np.float32))
    targets = []
    for joint in meta["joints"]:
        vertices = _handle(folder, joint["child"])
        operated = (joint.get("role") in ("hinge", "slide") and "lever" not in joint["name"]
                    and joint["child"] != "handle")
        if operated and joint["type"] in ("revolute", "prismatic") and vertices is not None and joint["name"] in names:
            targets.append(_target(art, ctx, names.index(joint["name"]), joint, vertices, groups))
        small = joint.get("role") in ("button", "knob") and joint["parent"] == meta["links"][0]["name"]
        if small_parts and small and joint["name"] in names and joint["type"] != "fixed":
            vertices = _link_vertices(folder, joint["child"])
            if vertices is not None:
                targets.append(_small_part(art, ctx, names.index(joint["name"]), joint, vertices))
    doc = {"format": "infmob-annotations/1",
           "units": "metres, radians for revolute/continuous joints, metres for prismatic; Z up, fronts face +X",
           "targets": targets}
    (folder / "annotations.json").write_text(json.dumps(doc, indent=1) + "\n")
    return targets
