"""CAGE's per-object ``train.json`` (3dlg-hcvc/cage, ``preprocess.py``), written from our own data.

CAGE (and NAP, SINGAPO, which start from the same abstraction) preprocess a PartNet-Mobility folder
into one node per part: box (``aabb`` center/size), joint type (fixed, revolute, prismatic, screw,
continuous), axis (origin, direction), range and the parent graph. This module follows the steps of
that script on the PartNet-Mobility files we just wrote, so the result is what it would give:

1. one node per ``mobility_v2.json`` entry; ``free``/``heavy``/``static`` -> ``fixed`` (range 0 0, zero
   axis), ``hinge`` -> ``revolute`` (range in degrees) or ``continuous`` (range 0 0), ``slider`` ->
   ``prismatic`` or ``screw`` (``rotates``), range in metres;
2. every part moved to its lower limit and the range shifted to ``[0, upper - lower]``;
3. prismatic buttons folded into their parent (``attach_objs``) and a part's ``handle`` leaf split off
   as a fixed child node;
4. ``aabb`` of each node's meshes in that state; labels cleaned to CAGE's words (root ``base``,
   doors, drawers, trays, shelves, knobs, wheels); nodes renumbered to their list index;
   ``meta.tree_hash``: the Weisfeiler-Lehman hash of the graph (networkx, as CAGE's hash table).

``plys/original-N.ply`` holds each mesh in the reset state, as CAGE's retrieval reads them. CAGE's
loader knows 8 categories and 8 part labels (``utils/refs.py``); other categories or labels (lid,
rack, lever ...) are kept as they are, and training CAGE on them means adding them to those tables.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np

from .partnet import MESH_FROM_WORLD, Plan, Written, pm_category
from .source import Source


def _joint(entry: dict) -> dict:
    kind, data = entry["joint"], entry.get("jointData") or {}
    zero = {"origin": [0.0, 0.0, 0.0], "direction": [0.0, 0.0, 0.0]}
    if kind == "hinge" and data:
        lim = data["limit"]
        if lim["noLimit"]:
            return {"type": "continuous", "range": [0.0, 0.0], "axis": data["axis"]}
        return {"type": "revolute", "range": [lim["a"], lim["b"]], "axis": data["axis"]}
    if kind == "slider" and data:
        lim = data["limit"]
        return {"type": "screw" if lim.get("rotates") else "prismatic", "range": [lim["a"], lim["b"]],
                "axis": data["axis"]}
    return {"type": "fixed", "range": [0.0, 0.0], "axis": zero}


def reset_transforms(src: Source, p: Plan) -> dict[str, np.ndarray]:
    """Per part link, the ``(4, 4)`` motion in the object frame from q = 0 to every joint at its lower limit."""
    lower = src.model.poses(rest=lambda j: j.lower or 0.0)
    m = np.eye(4)
    m[:3, :3] = MESH_FROM_WORLD
    return {n: m @ lower[n] @ np.linalg.inv(p.poses[n]) @ m.T for n in p.ids}


def _faces(obj_text: str) -> np.ndarray:
    tris = []
    for line in obj_text.splitlines():
        if line.startswith("f "):
            idx = [int(t.split("/")[0]) - 1 for t in line.split()[1:]]
            tris += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    return np.asarray(tris, dtype=np.int32).reshape(-1, 3)


def write_ply(path: Path, verts: np.ndarray, faces: np.ndarray) -> None:
    """A binary little-endian PLY of a triangle mesh (what open3d reads)."""
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(verts)}\nproperty float x\n"
            f"property float y\nproperty float z\nelement face {len(faces)}\n"
            f"property list uchar int vertex_indices\nend_header\n").encode()
    rec = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
    rec["n"], rec["i"] = 3, faces
    path.write_bytes(head + verts.astype("<f4").tobytes() + rec.tobytes())


def _clean_label(node: dict) -> str:
    name, kind = node["name"], node["joint"]["type"]
    if node["parent"] == -1:
        return "base"
    rules = {"revolute": [(("door", "mirror", "glass", "board", "countertop", "control_panel", "display_panel",
                            "other_leaf"), "door"), (("shelf",), "shelf")],
             "prismatic": [(("drawer", "display_panel"), "drawer"), (("door", "mirror", "glass"), "door"),
                           (("tray",), "tray"), (("shelf",), "shelf")],
             "continuous": [(("button",), "knob"), (("tray",), "tray"), (("wheel",), "wheel")]}
    for words, label in rules.get(kind, []):
        if any(w in name for w in words):
            return label
    return name


def tree_hash(nodes: list[dict]) -> str | None:
    try:
        import networkx as nx
    except ImportError:
        return None
    g = nx.DiGraph()
    for n in nodes:
        g.add_node(n["id"])
        if n["parent"] != -1:
            g.add_edge(n["id"], n["parent"])
    with warnings.catch_warnings():  # networkx 3.5 notes that its hashes changed; ours are recomputed, not compared
        warnings.simplefilter("ignore", UserWarning)
        return nx.weisfeiler_lehman_graph_hash(g)


def arti_tree(src: Source, p: Plan, w: Written, mob: list[dict], dst: Path) -> list[dict]:
    """Steps 1 and 2: nodes from mobility_v2.json, meshes moved to the lower limits (``plys/``)."""
    reset = reset_transforms(src, p)
    link_of = {k: n for n, k in p.ids.items()}
    (dst / "plys").mkdir()
    nodes = []
    for entry in mob:
        joint = _joint(entry)
        lo, hi = joint["range"]
        joint["range"] = [0.0, hi - lo]
        objs = [f"textured_objs/{stem}.obj" for _, stem in w.leaves[link_of[entry["id"]]]]
        node = {"id": entry["id"], "parent": entry["parent"], "name": entry["name"], "children": [],
                "joint": joint, "objs": objs, "parts": [{"name": leaf, "objs": [f"textured_objs/{stem}.obj"]}
                                                        for leaf, stem in w.leaves[link_of[entry["id"]]]]}
        t = reset[link_of[entry["id"]]]
        for _, stem in w.leaves[link_of[entry["id"]]]:
            v = w.verts[stem] @ t[:3, :3].T + t[:3, 3]
            write_ply(dst / "plys" / f"{stem}.ply", v, _faces((dst / "textured_objs" / f"{stem}.obj").read_text()))
        nodes.append(node)
    for node in nodes:
        if node["parent"] != -1:
            nodes[node["parent"]]["children"].append(node["id"])
    return nodes


def _ply(obj: str) -> str:
    return "plys/" + obj.split("/")[-1][:-4] + ".ply"


def diffuse_tree(nodes: list[dict]) -> list[dict]:
    """Step 3: buttons folded into their parents, handles split off, then step 4's renumbering."""
    tree = json.loads(json.dumps(nodes))
    by_id = {n["id"]: n for n in tree}
    nxt = max(by_id) + 1
    for node in list(tree):
        if node["joint"]["type"] == "fixed":
            node["objs"] = [_ply(o) for o in node["objs"]]
            node.pop("parts", None)
            continue
        if node["joint"]["type"] == "prismatic" and "button" in node["name"]:
            parent = by_id[node["parent"]]
            parent["children"].remove(node["id"])
            parent.setdefault("attach_objs", []).extend(_ply(o) for o in node["objs"])
            node["id"] = -1
        elif len(node["parts"]) > 1:
            for part in node["parts"]:
                if part["name"] == "handle":
                    node["children"].append(nxt)
                    tree.append({"id": nxt, "parent": node["id"], "name": "handle", "children": [],
                                 "joint": {"type": "fixed", "range": [0.0, 0.0]},
                                 "objs": [_ply(o) for o in part["objs"]]})
                    node["objs"] = [o for o in node["objs"] if o not in part["objs"]]
                    nxt += 1
        node["objs"] = [_ply(o) for o in node["objs"]]
        node.pop("parts", None)
    tree = [n for n in tree if n["id"] != -1]
    index = {-1: -1, **{n["id"]: i for i, n in enumerate(tree)}}
    for n in tree:
        n["id"], n["parent"] = index[n["id"]], index[n["parent"]]
        n["children"] = [index[c] for c in n["children"]]
    return tree


def _aabb(node: dict, dst: Path, cache: dict[str, np.ndarray]) -> dict:
    pts = [cache[o] for o in node["objs"] if o in cache]
    if not pts:
        return {"center": [0.0, 0.0, 0.0], "size": [0.0, 0.0, 0.0]}
    allp = np.concatenate(pts)
    lo, hi = allp.min(0), allp.max(0)
    return {"center": [float(x) for x in (lo + hi) / 2], "size": [float(x) for x in hi - lo]}


def write_cage(src: Source, p: Plan, w: Written, mob: list[dict], dst: Path) -> dict:
    """``train.json`` and ``plys/`` of one object (see the module docstring); returns the JSON."""
    nodes = arti_tree(src, p, w, mob, dst)
    tree = diffuse_tree(nodes)
    reset = reset_transforms(src, p)
    link_of = {k: n for n, k in p.ids.items()}
    cache = {}
    for node in nodes:
        t = reset[link_of[node["id"]]]
        for o in node["objs"]:
            stem = o.split("/")[-1][:-4]
            cache[_ply(o)] = w.verts[stem] @ t[:3, :3].T + t[:3, 3]
    for node in tree:
        node["aabb"] = _aabb(node, dst, cache)
        node["name"] = _clean_label(node)
        if not math.isfinite(sum(node["aabb"]["size"])):
            raise ValueError("non-finite box")
    meta = {"obj_cat": pm_category(src.category), "infmob_category": src.category}
    h = tree_hash(tree)
    if h is not None:
        meta["tree_hash"] = h
    data = {"meta": meta, "diffuse_tree": tree}
    (dst / "train.json").write_text(json.dumps(data, indent=4) + "\n")
    return data
