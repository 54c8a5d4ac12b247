"""GAPartNet's annotation files on top of the PartNet-Mobility folder (PKU-EPIC/GAPartNet, dataset/README.md).

* ``mobility_annotation_gapartnet.urdf``: the kinematic chain with every GAPart its own link: a
  fixed handle's meshes move from the door/drawer link to a new ``link_K`` fixed to it;
* ``mobility_texture_gapartnet.urdf``: the chain with the original meshes (our ``mobility.urdf``);
* ``semantics_gapartnet.txt``: ``link_name joint_type class`` per link of the annotation URDF;
* ``link_annotation_gapartnet.json``: per link ``link_name``, ``is_gapart``, ``category`` and ``bbox``,
  the 8 corners of the part's box at rest in the object frame, in GAPartNet's order
  ``(-x,+y,+z) (+x,+y,+z) (+x,-y,+z) (-x,-y,+z) (-x,+y,-z) (+x,+y,-z) (+x,-y,-z) (-x,-y,-z)``.

Classes come from the object's ``annotations.json`` (interaction targets: ``part_class``,
``handle_class`` and the handle's oriented box in the link frame) when the source has one; otherwise
from the part's label and joint type (:data:`CLASS_BY_LABEL`) and, for handles, from meshes named
``handle``/``pull``, boxed by their vertices.
"""

from __future__ import annotations

import copy
import json
from pathlib import Path

import numpy as np

from infmob_usd.validate.files import UrdfJoint, UrdfLink, write_urdf

from .partnet import WORLD_FROM_MESH, Plan, Written, urdf_model
from .source import Source, read_text

# (PartNet-Mobility joint type, our part label) -> GAPartNet class, where annotations.json is absent
CLASS_BY_LABEL = {
    ("hinge", "door"): "hinge_door", ("hinge", "leaf"): "hinge_door", ("hinge", "sash"): "hinge_door",
    ("hinge", "shutter"): "hinge_door", ("hinge", "flap"): "hinge_lid", ("hinge", "lid"): "hinge_lid",
    ("hinge", "seat"): "hinge_lid", ("hinge", "knob"): "hinge_knob", ("hinge", "lever"): "hinge_handle",
    ("hinge", "handle"): "hinge_handle", ("hinge", "switch"): "hinge_handle",
    ("hinge", "toggle"): "hinge_knob", ("hinge", "rocker"): "hinge_knob",
    ("slider", "drawer"): "slider_drawer", ("slider", "tray"): "slider_drawer", ("slider", "basket"): "slider_drawer",
    ("slider", "rack"): "slider_drawer", ("slider", "lid"): "slider_lid", ("slider", "cap"): "slider_lid",
    ("slider", "button"): "slider_button",
}
HANDLE_LEAVES = ("handle", "pull")
CORNERS = np.array([[-1, 1, 1], [1, 1, 1], [1, -1, 1], [-1, -1, 1], [-1, 1, -1], [1, 1, -1], [1, -1, -1],
                    [-1, -1, -1]], float) / 2


def _annotations(src: Source) -> dict[str, dict]:
    """Link -> its interaction target of ``annotations.json`` (empty when the file is absent)."""
    if not (src.folder / "annotations.json").exists():
        return {}
    data = json.loads(read_text(src.folder, "annotations.json", "annotations"))
    targets = data.get("targets", []) if isinstance(data, dict) else []
    return {t["link"]: t for t in targets if isinstance(t, dict) and isinstance(t.get("link"), str)}


def _box_corners(center, size, rot: np.ndarray) -> list[list[float]]:
    pts = (CORNERS * np.asarray(size, float)) @ rot.T + np.asarray(center, float)
    return [[round(float(x), 9) for x in p] for p in pts]


def _aabb_corners(v: np.ndarray) -> list[list[float]]:
    """The axis-aligned box (base frame, Z up) of vertices given in the object frame."""
    v = v @ WORLD_FROM_MESH.T
    lo, hi = v.min(0), v.max(0)
    return _box_corners((lo + hi) / 2, hi - lo, np.eye(3))


def _quat_matrix(q) -> np.ndarray:
    w, x, y, z = (float(c) for c in q)
    n = (w * w + x * x + y * y + z * z) ** 0.5 or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _handle_box(p: Plan, link: str, target: dict) -> list[list[float]] | None:
    """The annotated handle box (link frame) as 8 corners in the base frame."""
    box = target.get("box")
    if not isinstance(box, dict):
        return None
    pose = p.poses[link]
    rot = pose[:3, :3] @ _quat_matrix(box.get("quat_wxyz", (1, 0, 0, 0)))
    center = pose[:3, :3] @ np.asarray(box["center"], float) + pose[:3, 3]
    return _box_corners(center, box["size"], rot)


def classify(src: Source, p: Plan, w: Written) -> list[dict]:
    """One entry per part link, and one per fixed handle: ``(link, class, bbox, handle stems)``."""
    notes = _annotations(src)
    out = []
    for link in p.ids:
        pm, label = src.semantics[link]
        target = notes.get(link)
        cls = target.get("part_class") if target else CLASS_BY_LABEL.get((pm, label))
        handles = [stem for leaf, stem in w.leaves[link] if leaf.startswith(HANDLE_LEAVES)] if cls else []
        body = [w.verts[s] for _, s in w.leaves[link] if s not in handles]
        bbox = _aabb_corners(np.concatenate(body)) if cls and body else None
        out.append({"link": link, "class": cls, "bbox": bbox, "handles": []})
        if not cls:
            continue
        hcls = (target or {}).get("handle_class") if target else ("line_fixed_handle" if handles else None)
        if hcls and handles:
            hbox = _handle_box(p, link, target) if target else None
            hbox = hbox or _aabb_corners(np.concatenate([w.verts[s] for s in handles]))
            out[-1]["handles"].append({"class": hcls, "bbox": hbox, "stems": handles})
    return out


def annotation_model(src: Source, p: Plan, w: Written, parts: list[dict], obj_id: int):
    """The annotation URDF: each handle's visuals moved to a new link fixed to its part."""
    model = urdf_model(src, p, w, obj_id)
    names, nxt = [], len(p.ids)
    for part in parts:
        for h in part["handles"]:
            host = model.links[p.names[part["link"]]]
            stems = {f"textured_objs/{s}.obj" for s in h["stems"]}
            new = UrdfLink(f"link_{nxt}", [m for m in host.visuals if m.filename in stems])
            host.visuals = [m for m in host.visuals if m.filename not in stems]
            new.mass, new.inertia = 1e-3, (1e-8, 0.0, 0.0, 1e-8, 0.0, 1e-8)  # a link needs a mass to load
            model.links[new.name] = new
            model.joints[f"joint_{nxt}"] = UrdfJoint(f"joint_{nxt}", "fixed", host.name, new.name)
            names.append((new.name, h))
            nxt += 1
    return model, names


def write_gapartnet(src: Source, p: Plan, w: Written, mob: list[dict], dst: Path) -> list[str]:
    """Write GAPartNet's four files into ``dst``; return the GAPart classes found (for the card)."""
    obj_id = int(dst.name) if dst.name.isdigit() else 0
    parts = classify(src, p, w)
    model, handle_links = annotation_model(src, p, w, parts, obj_id)
    (dst / "mobility_annotation_gapartnet.urdf").write_text(write_urdf(model))
    (dst / "mobility_texture_gapartnet.urdf").write_text(write_urdf(urdf_model(src, p, w, obj_id)))
    entries, lines, classes = [], [], []
    for part in parts:
        name = p.names[part["link"]]
        entries.append({"link_name": name, "is_gapart": part["class"] is not None, "category": part["class"],
                        "bbox": part["bbox"]})
        lines.append(f"{name} {src.semantics[part['link']][0]} {part['class'] or 'other'}")
        classes += [part["class"]] if part["class"] else []
    for name, h in handle_links:
        entries.append({"link_name": name, "is_gapart": True, "category": h["class"], "bbox": h["bbox"]})
        lines.append(f"{name} static {h['class']}")
        classes.append(h["class"])
    (dst / "link_annotation_gapartnet.json").write_text(json.dumps(copy.deepcopy(entries), indent=1) + "\n")
    (dst / "semantics_gapartnet.txt").write_text("\n".join(lines) + "\n")
    return classes
