"""The JSON and text files of a PartNet-Mobility object folder, and one whole object written."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from infmob_usd._version import __version__

from .partnet import Plan, Written, joint_data, plan, pm_category, urdf_model, write_meshes
from .source import Source


def _json(path: Path, data) -> None:
    path.write_text(json.dumps(data, indent=1) + "\n")


def result_tree(src: Source, p: Plan, w: Written) -> tuple[list, dict[str, list[dict]]]:
    """result.json (PartNet's part hierarchy: object -> one node per part -> one leaf per mesh, leaves
    naming their ``textured_objs`` files) and, per part link, its leaves as mobility_v2.json lists them."""
    next_id = 1
    children, parts = [], {}
    for name in p.ids:
        label = src.semantics[name][1]
        node = {"id": next_id, "text": label, "name": label, "children": []}
        next_id += 1
        parts[name] = []
        for leaf, stem in w.leaves[name]:
            node["children"].append({"id": next_id, "text": leaf, "name": leaf, "objs": [stem]})
            parts[name].append({"id": next_id, "name": leaf, "children": []})
            next_id += 1
        children.append(node)
    cat = pm_category(src.category)
    return [{"id": 0, "text": cat, "name": src.category, "children": children}], parts


def mobility_v2(src: Source, p: Plan, parts: dict[str, list[dict]]) -> list[dict]:
    out = []
    for name, k in p.ids.items():
        joint, data = joint_data(src, p, name)
        parent = p.parent.get(name)
        out.append({"id": k, "parent": -1 if parent is None else p.ids[parent], "joint": joint,
                    "name": src.semantics[name][1], "parts": parts[name], "jointData": data})
    return out


def bounding_box(w: Written) -> dict:
    boxes = [b for b in w.bounds.values()]
    if not boxes:
        return {"min": [0.0, 0.0, 0.0], "max": [0.0, 0.0, 0.0]}
    allb = np.concatenate(boxes)
    return {"min": [round(float(x), 9) for x in allb.min(0)], "max": [round(float(x), 9) for x in allb.max(0)]}


def write_object(fmt: str, src: Source, obj_id: int, dst: Path, source_rel: str) -> dict:
    """Write one object in ``fmt`` into the new, empty folder ``dst``; return its row (id, category,
    seed, part labels, joints) for the dataset card. Every format holds the PartNet-Mobility files;
    ``gapartnet`` adds GAPartNet's annotation files, ``cage`` CAGE's ``train.json`` and ``plys/``."""
    row, ctx = write_partnet(src, obj_id, dst, source_rel)
    if fmt == "gapartnet":
        from .gapartnet import write_gapartnet

        row["gaparts"] = write_gapartnet(src, *ctx, dst)
    elif fmt == "cage":
        from .cage import write_cage

        write_cage(src, *ctx, dst)
    row["format"] = fmt
    return row


def write_partnet(src: Source, obj_id: int, dst: Path, source_rel: str) -> tuple[dict, tuple]:
    """Write one object's PartNet-Mobility folder into ``dst``; return its row and ``(plan, written,
    mobility_v2 list)`` for the formats built on it."""
    p = plan(src)
    w = write_meshes(src, p, dst)
    model = urdf_model(src, p, w, obj_id)
    from infmob_usd.validate.files import write_urdf

    text = write_urdf(model)
    (dst / "mobility.urdf").write_text(text)
    (dst / "mobility_cvx.urdf").write_text(text)  # the name ManiSkill's loader looks for (convex collisions)
    tree, parts = result_tree(src, p, w)
    _json(dst / "result.json", tree)
    mob = mobility_v2(src, p, parts)
    _json(dst / "mobility_v2.json", mob)
    (dst / "semantics.txt").write_text("".join(f"{p.names[n]} {src.semantics[n][0]} {src.semantics[n][1]}\n"
                                               for n in p.ids))
    _json(dst / "bounding_box.json", bounding_box(w))
    meta = {"model_cat": pm_category(src.category), "anno_id": str(obj_id), "model_id": str(obj_id),
            "version": "infmob-" + __version__,
            "infmob": {"category": src.category, "seed": src.seed, "name": src.meta.get("name"),
                       "generator_version": src.meta.get("version"), "overrides": src.meta.get("overrides", {}),
                       "source": source_rel, "links": p.names, "joints": p.joint_names}}
    _json(dst / "meta.json", meta)
    movable = [j for j in src.model.joints.values() if j.movable]
    licences = sorted({str(r.get("licence")) for r in src.meta.get("retrieved_parts", []) or []
                       if isinstance(r, dict) and r.get("licence")})
    row = {"id": obj_id, "category": src.category, "seed": src.seed, "source": source_rel,
           "version": str(src.meta.get("version")), "labels": sorted(src.semantics[n][1] for n in p.ids),
           "joints": [[j.type, j.lower, j.upper] for j in movable], "part_licences": licences}
    return row, (p, w, mob)
